// Cairo painting the drawing calls' marks; Picture recordings; rasterising and writing PNG, SVG
// and PDF.
#include "impulse2d/render/drawing.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>

#include "impulse2d/render/png.h"

namespace impulse2d::render {

namespace {

constexpr const char* kFontFamily = "DejaVu Sans";

void cairoColour(cairo_t* cairo, Color colour) {
  cairo_set_source_rgba(cairo, colour.r / 255.0, colour.g / 255.0, colour.b / 255.0,
                        colour.a / 255.0);
}

/// Paints the picture onto a fresh file surface and finishes the file.
void writeVector(const std::filesystem::path& path, const Picture& picture, ImageFormat format) {
  cairo_surface_t* surface =
      format == ImageFormat::Svg
          ? cairo_svg_surface_create(path.c_str(), picture.width(), picture.height())
          : cairo_pdf_surface_create(path.c_str(), picture.width(), picture.height());
  if (format == ImageFormat::Svg) cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PX);
  cairo_t* cairo = cairo_create(surface);
  cairo_set_source_surface(cairo, picture.surface(), 0.0, 0.0);
  cairo_paint(cairo);
  cairo_destroy(cairo);
  cairo_surface_finish(surface);
  const cairo_status_t status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
    throw RenderError("cannot write image '" + path.string() +
                      "': " + cairo_status_to_string(status));
  }
}

}  // namespace

namespace {

cairo_surface_t* boundedRecording(int width, int height) {
  const cairo_rectangle_t extents{0.0, 0.0, double(width), double(height)};
  return cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, &extents);
}

}  // namespace

Picture::Picture(int width, int height)
    : width_(width),
      height_(height),
      surface_(boundedRecording(width, height), cairo_surface_destroy) {}

namespace {

/// Paints marks into a Cairo context as they come.
class CairoCanvas : public Canvas {
 public:
  explicit CairoCanvas(const Picture& picture) : cairo_(cairo_create(picture.surface())) {
    cairo_select_font_face(cairo_, kFontFamily, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_line_join(cairo_, CAIRO_LINE_JOIN_MITER);
    cairo_set_line_cap(cairo_, CAIRO_LINE_CAP_BUTT);
    // Cairo's fast anti-aliasing still smooths every edge, in two thirds of the time of its
    // default; a pyramid's frame has thousands of small shapes.
    cairo_set_antialias(cairo_, CAIRO_ANTIALIAS_FAST);
  }
  ~CairoCanvas() override { cairo_destroy(cairo_); }
  CairoCanvas(const CairoCanvas&) = delete;
  CairoCanvas& operator=(const CairoCanvas&) = delete;

  void paint(Mark mark) override {
    switch (mark.kind) {
      case Mark::Kind::Fill:
      case Mark::Kind::Stroke:
        paintOutlines(mark);
        break;
      case Mark::Kind::Text:
        cairoColour(cairo_, mark.colour);
        cairo_set_font_size(cairo_, mark.size);
        cairo_move_to(cairo_, mark.at.x(), mark.at.y());
        cairo_show_text(cairo_, mark.text.c_str());
        break;
      case Mark::Kind::Save:
        cairo_save(cairo_);
        break;
      case Mark::Kind::Translate:
        cairo_translate(cairo_, mark.at.x(), mark.at.y());
        break;
      case Mark::Kind::Clip:
        cairo_rectangle(cairo_, 0.0, 0.0, mark.at.x(), mark.at.y());
        cairo_clip(cairo_);
        break;
      case Mark::Kind::Restore:
        cairo_restore(cairo_);
        break;
    }
  }

  double advance(const std::string& text, double size) override {
    cairo_set_font_size(cairo_, size);
    cairo_text_extents_t extents;
    cairo_text_extents(cairo_, text.c_str(), &extents);
    return extents.x_advance;
  }

  void placePart(const Picture& picture, const Vec2& from, const Vec2& size, const Vec2& corner,
                 double scale) override {
    cairo_save(cairo_);
    cairo_translate(cairo_, corner.x(), corner.y());
    cairo_scale(cairo_, scale, scale);
    cairo_rectangle(cairo_, 0.0, 0.0, size.x(), size.y());
    cairo_clip(cairo_);
    cairo_set_source_surface(cairo_, picture.surface(), -from.x(), -from.y());
    cairo_paint(cairo_);
    cairo_restore(cairo_);
  }

 private:
  void paintOutlines(const Mark& mark) {
    cairo_new_path(cairo_);
    for (const Outline& outline : mark.outlines) {
      if (outline.radius > 0.0) {
        cairo_new_sub_path(cairo_);
        cairo_arc(cairo_, outline.points[0].x(), outline.points[0].y(), outline.radius, 0.0,
                  2.0 * kPi);
        continue;
      }
      cairo_move_to(cairo_, outline.points[0].x(), outline.points[0].y());
      for (std::size_t i = 1; i < outline.points.size(); ++i) {
        cairo_line_to(cairo_, outline.points[i].x(), outline.points[i].y());
      }
      if (outline.closed) cairo_close_path(cairo_);
    }
    cairoColour(cairo_, mark.colour);
    if (mark.kind == Mark::Kind::Stroke) {
      cairo_set_line_width(cairo_, mark.size);
      cairo_stroke(cairo_);
    } else {
      cairo_fill(cairo_);
    }
  }

  cairo_t* cairo_;
};

}  // namespace

Drawing::Drawing(const Picture& picture, DrawingLog* log)
    : owned_(std::make_unique<CairoCanvas>(picture)), canvas_(owned_.get()), log_(log) {}

void Drawing::place(const Picture& picture, const Vec2& corner, double scale) {
  placePart(picture, Vec2::Zero(), Vec2(picture.width(), picture.height()), corner, scale);
}

const char* extensionOf(ImageFormat format) {
  switch (format) {
    case ImageFormat::Png:
      return "png";
    case ImageFormat::Svg:
      return "svg";
    case ImageFormat::Pdf:
      return "pdf";
  }
  return "png";
}

namespace {

/// The picture painted onto a new image surface of `scale` times its size.
std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> paintedImage(const Picture& picture,
                                                                          double scale) {
  const int width = std::max(1, int(std::lround(picture.width() * scale)));
  const int height = std::max(1, int(std::lround(picture.height() * scale)));
  std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> surface(
      cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height), cairo_surface_destroy);
  cairo_t* cairo = cairo_create(surface.get());
  cairo_scale(cairo, scale, scale);
  cairo_set_source_surface(cairo, picture.surface(), 0.0, 0.0);
  cairo_paint(cairo);
  cairo_destroy(cairo);
  cairo_surface_flush(surface.get());
  return surface;
}

/// Row y of an image surface: Cairo's ARGB32, premultiplied, one native-endian word per pixel.
const std::uint32_t* surfaceRow(cairo_surface_t* surface, int y) {
  return reinterpret_cast<const std::uint32_t*>(cairo_image_surface_get_data(surface) +
                                                std::size_t(y) *
                                                    cairo_image_surface_get_stride(surface));
}

Color unpremultiplied(std::uint32_t pixel) {
  const std::uint32_t alpha = pixel >> 24;
  const auto channel = [&](int shift) {
    const std::uint32_t value = (pixel >> shift) & 0xFF;
    if (alpha == 255) return std::uint8_t(value);
    if (alpha == 0) return std::uint8_t(0);
    return std::uint8_t(std::min<std::uint32_t>(255, (value * 255 + alpha / 2) / alpha));
  };
  return Color{channel(16), channel(8), channel(0), std::uint8_t(alpha)};
}

/// The surface's rows as RGB scanlines (each row a filter byte 0, then R, G, B per pixel), taken
/// straight from Cairo's words; false, leaving `raw` unfinished, at the first pixel that is not
/// opaque.
bool opaqueScanlines(cairo_surface_t* surface, std::vector<std::uint8_t>& raw) {
  const int width = cairo_image_surface_get_width(surface);
  const int height = cairo_image_surface_get_height(surface);
  raw.resize((std::size_t(width) * 3 + 1) * std::size_t(height));
  std::uint8_t* out = raw.data();
  for (int y = 0; y < height; ++y) {
    *out++ = 0;
    const std::uint32_t* row = surfaceRow(surface, y);
    for (int x = 0; x < width; ++x) {
      const std::uint32_t pixel = row[x];
      if ((pixel >> 24) != 255) return false;
      *out++ = std::uint8_t(pixel >> 16);
      *out++ = std::uint8_t(pixel >> 8);
      *out++ = std::uint8_t(pixel);
    }
  }
  return true;
}

}  // namespace

Image rasterise(const Picture& picture, double scale) {
  const auto surface = paintedImage(picture, scale);
  Image image(cairo_image_surface_get_width(surface.get()),
              cairo_image_surface_get_height(surface.get()));
  for (int y = 0; y < image.height(); ++y) {
    const std::uint32_t* row = surfaceRow(surface.get(), y);
    for (int x = 0; x < image.width(); ++x) image.at(x, y) = unpremultiplied(row[x]);
  }
  return image;
}

PictureWriter::PictureWriter() : encoder_(std::make_shared<PngEncoder>()) {}

void PictureWriter::writePng(const std::filesystem::path& path, const Picture& picture) {
  const int width = picture.width();
  const int height = picture.height();
  if (!surface_ || cairo_image_surface_get_width(surface_.get()) != width ||
      cairo_image_surface_get_height(surface_.get()) != height) {
    surface_.reset(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height),
                   cairo_surface_destroy);
  }
  cairo_t* cairo = cairo_create(surface_.get());
  cairo_set_operator(cairo, CAIRO_OPERATOR_CLEAR);  // the last picture goes
  cairo_paint(cairo);
  cairo_set_operator(cairo, CAIRO_OPERATOR_OVER);
  cairo_set_source_surface(cairo, picture.surface(), 0.0, 0.0);
  cairo_paint(cairo);
  cairo_destroy(cairo);
  cairo_surface_flush(surface_.get());
  if (opaqueScanlines(surface_.get(), scanlines_)) {
    writeFileAtomically(path, encoder_->encode(width, height, 3, scanlines_));
  } else {
    render::writePng(path, rasterise(picture));
  }
}

void PictureWriter::write(const std::filesystem::path& path, const Picture& picture,
                          ImageFormat format) {
  if (format == ImageFormat::Png) {
    writePng(path, picture);
    return;
  }
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  writeVector(temporary, picture, format);
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    throw RenderError("cannot rename '" + temporary.string() + "' to '" + path.string() +
                      "': " + error.message());
  }
}

void writePicture(const std::filesystem::path& path, const Picture& picture, ImageFormat format) {
  PictureWriter().write(path, picture, format);
}

}  // namespace impulse2d::render
