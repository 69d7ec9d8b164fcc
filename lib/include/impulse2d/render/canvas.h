// A canvas of RGBA pixels and the anti-aliased primitives frames are drawn with: filled circles
// and convex polygons with outlines, lines, arrows and text. Coordinates are pixels, x to the
// right and y down; pixel (i, j) covers [i, i+1) × [j, j+1), so its centre is (i + ½, j + ½).
//
// Anti-aliasing is coverage by signed distance: a pixel whose centre lies d pixels inside an edge
// is covered by clamp(d + ½, 0, 1), a one-pixel ramp across the edge. A shape whose edges lie on
// pixel boundaries therefore covers exactly its pixels, and a circle's summed coverage is its area.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "impulse2d/math.h"

namespace impulse2d::render {

/// 8-bit RGBA, not premultiplied; a = 255 is opaque.
struct Color {
  /// red
  std::uint8_t r = 0;
  /// green
  std::uint8_t g = 0;
  /// blue
  std::uint8_t b = 0;
  /// alpha: 0 transparent, 255 opaque
  std::uint8_t a = 255;

  /// Same four channels.
  bool operator==(const Color& other) const {
    return r == other.r && g == other.g && b == other.b && a == other.a;
  }
  /// Any channel differs.
  bool operator!=(const Color& other) const { return !(*this == other); }
};

static_assert(sizeof(Color) == 4, "a canvas's pixels are packed RGBA bytes, as PNG stores them");

/// The same colour with alpha multiplied by `opacity` in [0, 1].
Color withOpacity(Color color, double opacity);

/// An image in memory that frames are drawn into, pixel (0, 0) at the top left.
class Canvas {
 public:
  Canvas() = default;
  /// A width × height image filled with `background`.
  Canvas(int width, int height, Color background = Color{255, 255, 255, 255});

  /// in pixels
  int width() const { return width_; }
  /// in pixels
  int height() const { return height_; }
  /// Pixel (x, y), which must lie inside the canvas.
  Color& at(int x, int y) { return pixels_[std::size_t(y) * width_ + x]; }
  /// Pixel (x, y), which must lie inside the canvas.
  const Color& at(int x, int y) const { return pixels_[std::size_t(y) * width_ + x]; }
  /// Row-major pixels, top row first: the layout PNG files use.
  const std::vector<Color>& pixels() const { return pixels_; }

  /// Resizes if needed and sets every pixel to `color`.
  void reset(int width, int height, Color color);
  /// Sets every pixel to `color`.
  void fill(Color color);
  /// Mixes `color` into pixel (x, y) by coverage in [0, 1] ("over" compositing); ignores pixels
  /// outside the canvas.
  void blend(int x, int y, Color color, double coverage);

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<Color> pixels_;
};

/// A filled convex polygon (either winding) with an outline `outlineWidth` pixels wide drawn just
/// inside its edges; outlineWidth 0 draws no outline.
void fillConvexPolygon(Canvas& canvas, const std::vector<Vec2>& vertices, Color fill, Color outline,
                       double outlineWidth);
/// A filled circle with an outline `outlineWidth` pixels wide just inside its edge.
void fillCircle(Canvas& canvas, const Vec2& centre, double radius, Color fill, Color outline,
                double outlineWidth);
/// An axis-aligned rectangle from `corner` (top left) of the given size, no outline.
void fillRectangle(Canvas& canvas, const Vec2& corner, const Vec2& size, Color color);
/// A straight line `width` pixels wide with square-cut ends.
void drawLine(Canvas& canvas, const Vec2& from, const Vec2& to, double width, Color color);
/// A line from `from` to `to` ending in a filled triangular head of the given length and width;
/// a shaft shorter than the head shrinks the head with it.
void drawArrow(Canvas& canvas, const Vec2& from, const Vec2& to, double width, double headLength,
               double headWidth, Color color);

/// Text in stb_easy_font's bitmap font, each font pixel drawn `scale` pixels wide, its top left
/// corner at `corner`. Characters outside printable ASCII are drawn as '?'.
void drawText(Canvas& canvas, const std::string& text, const Vec2& corner, double scale,
              Color color);
/// Width in pixels of `text` drawn at `scale`.
double textWidth(const std::string& text, double scale);
/// Height in pixels of one line of text drawn at `scale` (caps and descenders).
double textHeight(double scale);

/// Copies `source` onto `target` with its top left corner at (x, y), clipped to the target.
void blit(Canvas& target, const Canvas& source, int x, int y);
/// `source` scaled to width × height by averaging the source pixels under each new pixel.
Canvas resized(const Canvas& source, int width, int height);

}  // namespace impulse2d::render
