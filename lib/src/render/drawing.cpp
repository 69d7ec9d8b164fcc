// Cairo behind the drawing calls; Picture recordings; rasterising and writing PNG, SVG and PDF.
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
/// DejaVu Sans's ascent and descent per em, as Cairo reports them (0.928 and 0.236).
constexpr double kAscent = 0.928;
constexpr double kDescent = 0.236;
/// A subscript is this size of its text and sits this many of its em below the baseline.
constexpr double kSubscriptSize = 0.7;
constexpr double kSubscriptDrop = 0.22;

/// Circles up to this radius (pixels) are drawn as polygons of kSmallCircleSides sides.
constexpr double kSmallCircle = 6.0;
constexpr int kSmallCircleSides = 8;

/// A piece of text at one level: the baseline's or a subscript.
struct Run {
  std::string text;
  bool subscript = false;
};

/// The length of the valid UTF-8 character at text[i] (RFC 3629: no overlong forms, no
/// surrogates, nothing past U+10FFFF), or 0 when none starts there.
std::size_t utf8Length(const std::string& text, std::size_t i) {
  const auto byte = [&text](std::size_t k) {
    return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u;
  };
  const unsigned lead = byte(i);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned low = 0x80;
  unsigned high = 0xBF;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    low = lead == 0xE0 ? 0xA0 : low;
    high = lead == 0xED ? 0x9F : high;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    low = lead == 0xF0 ? 0x90 : low;
    high = lead == 0xF4 ? 0x8F : high;
  } else {
    return 0;
  }
  if (byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  }
  return length;
}

/// The text with each byte that starts no valid UTF-8 character replaced by U+FFFD. Cairo refuses
/// invalid UTF-8 (a file name in another encoding), and a refusal stops all later drawing on the
/// frame: its heads-up, legend and arrows would vanish.
std::string validUtf8(const std::string& text) {
  std::string valid;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = utf8Length(text, i);
    valid.append(length ? text.substr(i, length) : std::string("\xEF\xBF\xBD"));
    i += length ? length : 1;
  }
  return valid;
}

/// "λ_n" -> {"λ", "n" (subscript)}; "λ_{ab}c" -> {"λ", "ab" (subscript), "c"}. Only a '_'
/// after a symbol (a character beyond ASCII) starts a subscript, so names such as "pushed_box"
/// are drawn as they are.
std::vector<Run> parseMarkup(const std::string& markup) {
  const std::string text = validUtf8(markup);
  std::vector<Run> runs{{"", false}};
  for (std::size_t i = 0; i < text.size(); ++i) {
    const bool afterSymbol = i > 0 && (static_cast<unsigned char>(text[i - 1]) & 0x80) != 0;
    if (text[i] != '_' || !afterSymbol || i + 1 >= text.size()) {
      runs.back().text += text[i];
      continue;
    }
    std::string lowered;
    if (text[i + 1] == '{') {
      const std::size_t close = text.find('}', i + 2);
      const std::size_t end = close == std::string::npos ? text.size() : close;
      lowered = text.substr(i + 2, end - i - 2);
      i = end;
    } else {
      // One character, which in UTF-8 may be several bytes.
      std::size_t length = 1;
      while (i + 1 + length < text.size() && (text[i + 1 + length] & 0xC0) == 0x80) ++length;
      lowered = text.substr(i + 1, length);
      i += length;
    }
    runs.push_back({lowered, true});
    runs.push_back({"", false});
  }
  return runs;
}

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

Color withOpacity(Color colour, double opacity) {
  colour.a = std::uint8_t(std::lround(colour.a * std::clamp(opacity, 0.0, 1.0)));
  return colour;
}

double lineHeight(double size) {
  return (kAscent + kDescent) * size;
}

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

Drawing::Drawing(const Picture& picture, DrawingLog* log)
    : cairo_(cairo_create(picture.surface())), log_(log) {
  cairo_select_font_face(cairo_, kFontFamily, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_line_join(cairo_, CAIRO_LINE_JOIN_MITER);
  cairo_set_line_cap(cairo_, CAIRO_LINE_CAP_BUTT);
  // Cairo's fast anti-aliasing still smooths every edge, in two thirds of the time of its
  // default; a pyramid's frame has thousands of small shapes.
  cairo_set_antialias(cairo_, CAIRO_ANTIALIAS_FAST);
}

Drawing::~Drawing() {
  flush();
  cairo_destroy(cairo_);
}

void Drawing::log(DrawnShape::Kind kind, std::vector<Vec2> points, Color colour, double size,
                  std::string text) {
  if (log_ != nullptr) {
    log_->push_back({kind, role_, std::move(points), colour, size, std::move(text)});
  }
}

void Drawing::setColour(Color colour) {
  cairoColour(cairo_, colour);
}

void Drawing::add(bool stroke, Color colour, double width, Outline outline) {
  for (Batch& batch : batches_) {
    if (batch.stroke == stroke && batch.colour == colour && batch.width == width) {
      batch.outlines.push_back(std::move(outline));
      return;
    }
  }
  batches_.push_back({stroke, colour, width, {std::move(outline)}});
}

void Drawing::flush() {
  for (const Batch& batch : batches_) {
    cairo_new_path(cairo_);
    for (const Outline& outline : batch.outlines) {
      if (outline.radius > kSmallCircle) {
        cairo_new_sub_path(cairo_);
        cairo_arc(cairo_, outline.points[0].x(), outline.points[0].y(), outline.radius, 0.0,
                  2.0 * kPi);
        continue;
      }
      if (outline.radius > 0.0) {
        // A dot as a polygon: at this size it looks the same, with a third of the edges.
        const Vec2& centre = outline.points[0];
        cairo_move_to(cairo_, centre.x() + outline.radius, centre.y());
        for (int k = 1; k < kSmallCircleSides; ++k) {
          const double angle = 2.0 * kPi * k / kSmallCircleSides;
          cairo_line_to(cairo_, centre.x() + outline.radius * std::cos(angle),
                        centre.y() + outline.radius * std::sin(angle));
        }
        cairo_close_path(cairo_);
        continue;
      }
      cairo_move_to(cairo_, outline.points[0].x(), outline.points[0].y());
      for (std::size_t i = 1; i < outline.points.size(); ++i) {
        cairo_line_to(cairo_, outline.points[i].x(), outline.points[i].y());
      }
      if (outline.closed) cairo_close_path(cairo_);
    }
    setColour(batch.colour);
    if (batch.stroke) {
      cairo_set_line_width(cairo_, batch.width);
      cairo_stroke(cairo_);
    } else {
      cairo_fill(cairo_);
    }
  }
  batches_.clear();
}

void Drawing::polygon(const std::vector<Vec2>& corners, Color fill, Color outline,
                      double outlineWidth) {
  if (corners.empty()) return;
  add(false, fill, 0.0, {corners});
  if (outlineWidth > 0.0) add(true, outline, outlineWidth, {corners});
  log(DrawnShape::Kind::Polygon, corners, fill, outlineWidth);
}

void Drawing::outline(const std::vector<Vec2>& corners, Color colour, double width) {
  if (corners.empty() || !(width > 0.0)) return;
  add(true, colour, width, {corners});
  log(DrawnShape::Kind::Polygon, corners, colour, width);
}

void Drawing::circle(const Vec2& centre, double radius, Color fill, Color outline,
                     double outlineWidth) {
  // Fill, then the outline as a stroke, as a polygon is drawn: an outline disc under the fill
  // would share a batch with every later outline disc and cover a fill whose colour an earlier
  // body had already batched (a ball listed after a box of its colour came out in the outline's).
  add(false, fill, 0.0, {{centre}, radius});
  if (outlineWidth > 0.0) add(true, outline, outlineWidth, {{centre}, radius});
  log(DrawnShape::Kind::Circle, {centre}, fill, radius);
}

void Drawing::ring(const Vec2& centre, double radius, Color colour, double width) {
  add(true, colour, width, {{centre}, radius});
  log(DrawnShape::Kind::Circle, {centre}, colour, radius);
}

void Drawing::rectangle(const Vec2& corner, const Vec2& size, Color colour) {
  std::vector<Vec2> corners{corner, corner + Vec2(size.x(), 0.0), corner + size,
                            corner + Vec2(0.0, size.y())};
  add(false, colour, 0.0, {corners});
  log(DrawnShape::Kind::Polygon, std::move(corners), colour, 0.0);
}

void Drawing::line(const Vec2& from, const Vec2& to, double width, Color colour) {
  // A square-ended line is a thin rectangle, and filling one costs less than stroking.
  const double length = (to - from).norm();
  if (length > 0.0) {
    const Vec2 along = (to - from) / length;
    const Vec2 side = 0.5 * width * Vec2(-along.y(), along.x());
    add(false, colour, 0.0, {{from + side, to + side, to - side, from - side}});
  }
  log(DrawnShape::Kind::Line, {from, to}, colour, width);
}

namespace {

/// The outline of an arrow: shaft and head as one polygon, `grow` pixels larger all round.
std::vector<Vec2> arrowOutline(const Vec2& from, const Vec2& to, double width, double headLength,
                               double headWidth, double grow) {
  const double length = (to - from).norm();
  const Vec2 direction = (to - from) / length;
  const Vec2 side(-direction.y(), direction.x());
  const double shrink = std::min(1.0, 0.6 * length / headLength);
  const Vec2 tip = to + grow * direction;
  const Vec2 tail = from - grow * direction;
  const Vec2 base = to - shrink * headLength * direction - grow * direction;
  const double shaft = 0.5 * width + grow;
  const double head = 0.5 * shrink * headWidth + 1.5 * grow;
  return {tail + shaft * side, base + shaft * side, base + head * side, tip,
          base - head * side,  base - shaft * side, tail - shaft * side};
}

}  // namespace

void Drawing::arrow(const Vec2& from, const Vec2& to, double width, double headLength,
                    double headWidth, Color colour, Color halo) {
  if (!((to - from).norm() > 0.0)) return;
  // The halo is a larger arrow in its own batch, painted under all arrows.
  if (halo.a > 0) {
    add(false, halo, 0.0, {arrowOutline(from, to, width, headLength, headWidth, 0.5 * width)});
  }
  add(false, colour, 0.0, {arrowOutline(from, to, width, headLength, headWidth, 0.0)});
  log(DrawnShape::Kind::Arrow, {from, to}, colour, width);
}

void Drawing::text(const std::string& text, const Vec2& corner, double size, Color colour) {
  flush();
  setColour(colour);
  double x = corner.x();
  const double baseline = corner.y() + kAscent * size;
  for (const Run& run : parseMarkup(text)) {
    if (run.text.empty()) continue;
    const double runSize = run.subscript ? kSubscriptSize * size : size;
    cairo_set_font_size(cairo_, runSize);
    cairo_move_to(cairo_, x, baseline + (run.subscript ? kSubscriptDrop * size : 0.0));
    cairo_show_text(cairo_, run.text.c_str());
    cairo_text_extents_t extents;
    cairo_text_extents(cairo_, run.text.c_str(), &extents);
    x += extents.x_advance;
  }
  log(DrawnShape::Kind::Text, {corner, Vec2(x, corner.y() + lineHeight(size))}, colour, size, text);
}

double Drawing::textWidth(const std::string& text, double size) {
  double width = 0.0;
  for (const Run& run : parseMarkup(text)) {
    if (run.text.empty()) continue;
    cairo_set_font_size(cairo_, run.subscript ? kSubscriptSize * size : size);
    cairo_text_extents_t extents;
    cairo_text_extents(cairo_, run.text.c_str(), &extents);
    width += extents.x_advance;
  }
  return width;
}

void Drawing::place(const Picture& picture, const Vec2& corner, double scale) {
  placePart(picture, Vec2::Zero(), Vec2(picture.width(), picture.height()), corner, scale);
}

void Drawing::placePart(const Picture& picture, const Vec2& from, const Vec2& size,
                        const Vec2& corner, double scale) {
  flush();
  cairo_save(cairo_);
  cairo_translate(cairo_, corner.x(), corner.y());
  cairo_scale(cairo_, scale, scale);
  cairo_rectangle(cairo_, 0.0, 0.0, size.x(), size.y());
  cairo_clip(cairo_);
  cairo_set_source_surface(cairo_, picture.surface(), -from.x(), -from.y());
  cairo_paint(cairo_);
  cairo_restore(cairo_);
}

void Drawing::inside(const Vec2& corner, const Vec2& size,
                     const std::function<void(Drawing&)>& draw) {
  flush();
  cairo_save(cairo_);
  cairo_translate(cairo_, corner.x(), corner.y());
  cairo_rectangle(cairo_, 0.0, 0.0, size.x(), size.y());
  cairo_clip(cairo_);
  draw(*this);
  flush();
  cairo_restore(cairo_);
}

void Drawing::translate(const Vec2& offset) {
  flush();
  cairo_translate(cairo_, offset.x(), offset.y());
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
