// Drawing with Cairo: the marks of the drawing calls (marks.h) painted anti-aliased, text in
// DejaVu Sans, on any surface. A frame is drawn once into a Picture (a Cairo recording: the
// drawing calls, not pixels), which is then rasterised for PNG or replayed into an SVG or PDF
// file, so every format shows the same drawing. Coordinates are pixels (points in SVG and PDF).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "impulse2d/math.h"
#include "impulse2d/render/image.h"
#include "impulse2d/render/marks.h"

using cairo_t = struct _cairo;
using cairo_surface_t = struct _cairo_surface;

namespace impulse2d::render {

class PngEncoder;

/// A recorded drawing of a fixed size, shared cheaply (the recording is reference counted).
class Picture {
 public:
  Picture() = default;
  /// An empty recording of width × height pixels.
  Picture(int width, int height);
  /// pixels
  int width() const { return width_; }
  /// pixels
  int height() const { return height_; }
  /// The Cairo recording surface.
  cairo_surface_t* surface() const { return surface_.get(); }
  /// Whether it holds a recording (a default-made Picture holds none).
  explicit operator bool() const { return bool(surface_); }

 private:
  int width_ = 0;
  int height_ = 0;
  std::shared_ptr<cairo_surface_t> surface_;
};

enum class ImageFormat { Png, Svg, Pdf };
/// "png", "svg", "pdf".
const char* extensionOf(ImageFormat format);

/// The picture's pixels, at `scale` times its size.
Image rasterise(const Picture& picture, double scale = 1.0);

/// Writes pictures as PNG, SVG or PDF: first to `path` + ".tmp", then renamed to `path`, so a
/// reader never sees a half-written file. Throws RenderError (png.h) naming the path. It keeps
/// its image surface and buffers from one PNG to the next, so a run's frames reuse memory.
class PictureWriter {
 public:
  PictureWriter();
  /// Writes `picture` to `path` in `format`.
  void write(const std::filesystem::path& path, const Picture& picture, ImageFormat format);

 private:
  void writePng(const std::filesystem::path& path, const Picture& picture);

  std::shared_ptr<cairo_surface_t> surface_;  ///< an image surface of the last size written
  std::vector<std::uint8_t> scanlines_;
  std::shared_ptr<PngEncoder> encoder_;
};

/// One picture written by a PictureWriter of its own.
void writePicture(const std::filesystem::path& path, const Picture& picture, ImageFormat format);

}  // namespace impulse2d::render
