// A raster image: 8-bit RGBA pixels, row-major, top row first, the layout PNG files use. It holds
// what a drawing becomes when it is rasterised (drawing.h), or a PNG read back; it draws nothing.
#pragma once

#include <cstdint>
#include <vector>

namespace impulse2d::render {

/// 8-bit RGBA, not premultiplied; a = 255 is opaque.
struct Color {
  std::uint8_t r = 0;    ///< red
  std::uint8_t g = 0;    ///< green
  std::uint8_t b = 0;    ///< blue
  std::uint8_t a = 255;  ///< opacity: 0 transparent, 255 opaque

  /// All four channels equal.
  bool operator==(const Color& other) const {
    return r == other.r && g == other.g && b == other.b && a == other.a;
  }
  /// Some channel differs.
  bool operator!=(const Color& other) const { return !(*this == other); }
};

static_assert(sizeof(Color) == 4, "an image's pixels are packed RGBA bytes, as PNG stores them");

/// The same colour with alpha multiplied by `opacity` in [0, 1].
Color withOpacity(Color colour, double opacity);

/// Pixels of one colour each, width × height of them.
class Image {
 public:
  Image() = default;
  /// width × height pixels of `fill`.
  Image(int width, int height, Color fill = Color{255, 255, 255, 255})
      : width_(width), height_(height), pixels_(std::size_t(width) * std::size_t(height), fill) {}

  /// pixels
  int width() const { return width_; }
  /// pixels
  int height() const { return height_; }
  /// Pixel (x, y), x to the right and y down from the top left.
  Color& at(int x, int y) { return pixels_[std::size_t(y) * width_ + x]; }
  /// Pixel (x, y), x to the right and y down from the top left.
  const Color& at(int x, int y) const { return pixels_[std::size_t(y) * width_ + x]; }
  /// Every pixel, row by row from the top.
  const std::vector<Color>& pixels() const { return pixels_; }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<Color> pixels_;
};

}  // namespace impulse2d::render
