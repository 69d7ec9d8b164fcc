// Drawing with Cairo: anti-aliased shapes, arrows and text in DejaVu Sans, on any surface. A frame
// is drawn once into a Picture (a Cairo recording: the drawing calls, not pixels), which is then
// rasterised for PNG or replayed into an SVG or PDF file, so every format shows the same drawing.
//
// Coordinates are pixels (points in SVG and PDF), x to the right and y down. Text takes a small
// markup for the lecture's symbols: after a symbol, "λ_n" sets n as a subscript and "λ_{max}" a
// longer one ("pushed_box" stays as it is); the symbols themselves (μ, λ, Δ, →) are Unicode and
// drawn from the font as they are.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "impulse2d/math.h"
#include "impulse2d/render/image.h"

using cairo_t = struct _cairo;
using cairo_surface_t = struct _cairo_surface;

namespace impulse2d::render {

class PngEncoder;

/// One drawing call as a test reads it back: what was drawn, where (pixels), in which colour, and
/// the role it was drawn for (Drawing::setRole: "body", "normal force", "load", ...).
struct DrawnShape {
  /// What kind of call it was.
  enum class Kind { Polygon, Circle, Line, Arrow, Text };
  Kind kind = Kind::Polygon;  ///< the call
  std::string role;           ///< what it was drawn for (Drawing::setRole)
  std::vector<Vec2>
      points;         ///< polygon corners; circle centre; line and arrow from, to; text corner
  Color colour;       ///< fill (shapes), stroke (lines, arrows), ink (text)
  double size = 0.0;  ///< circle radius, line width, text height
  std::string text;   ///< a text call's words
};
using DrawingLog = std::vector<DrawnShape>;

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

/// The calls frames are drawn with, on a Cairo context; optionally logged for tests.
///
/// Shapes are batched: each call adds its outline to the batch of its paint (fill or stroke,
/// colour, line width), and every batch is filled or stroked once, in the order the batches were
/// first used, when text or a picture is drawn or the drawing ends. A pyramid's thousand arrows
/// of one kind are then one fill, not a thousand: what makes a frame fast. A shape drawn later
/// in an earlier batch's paint goes under the later batches, so draw in layers (bodies, then
/// arrows, then points), as frames do.
class Drawing {
 public:
  /// Draws into `picture` (its recording); `log`, when given, receives every call.
  explicit Drawing(const Picture& picture, DrawingLog* log = nullptr);
  ~Drawing();
  Drawing(const Drawing&) = delete;
  Drawing& operator=(const Drawing&) = delete;

  /// The role recorded with the calls that follow, for tests reading the log.
  void setRole(std::string role) { role_ = std::move(role); }

  /// Filled polygon, outlined inside-and-out `outlineWidth` wide (0: none).
  void polygon(const std::vector<Vec2>& corners, Color fill, Color outline, double outlineWidth);
  /// Filled circle, outlined `outlineWidth` wide (0: none).
  void circle(const Vec2& centre, double radius, Color fill, Color outline, double outlineWidth);
  /// A closed polygon's outline only, `width` wide, centred on its edges.
  void outline(const std::vector<Vec2>& corners, Color colour, double width);
  /// A circle's outline only.
  void ring(const Vec2& centre, double radius, Color colour, double width);
  /// Filled axis-aligned rectangle from its top left `corner`, no outline.
  void rectangle(const Vec2& corner, const Vec2& size, Color colour);
  /// Straight line `width` wide with square-cut ends.
  void line(const Vec2& from, const Vec2& to, double width, Color colour);
  /// A shaft from `from` to `to` and a filled head at `to`; a shaft shorter than the head shrinks
  /// the head with it. A `halo` of nonzero alpha is drawn under it, `width` wider on each side,
  /// so the arrow stays visible over bodies of any colour.
  void arrow(const Vec2& from, const Vec2& to, double width, double headLength, double headWidth,
             Color colour, Color halo = Color{0, 0, 0, 0});
  /// Paints every batch so far.
  void flush();
  /// Text in DejaVu Sans of font size `size` (the em, pixels), its line's top left corner at
  /// `corner`: the line is lineHeight(size) tall.
  void text(const std::string& text, const Vec2& corner, double size, Color colour);
  /// Width in pixels of text drawn at `size`.
  double textWidth(const std::string& text, double size);

  /// Draws `picture` with its top left corner at `corner`, scaled by `scale`, clipped to
  /// its own size.
  void place(const Picture& picture, const Vec2& corner, double scale = 1.0);
  /// Draws the part of `picture` from `from` of size `size` (pixels of the picture) with its top
  /// left corner at `corner`, scaled by `scale`.
  void placePart(const Picture& picture, const Vec2& from, const Vec2& size, const Vec2& corner,
                 double scale);
  /// Calls `draw` with the origin moved to `corner` and the drawing clipped to `size` there: a
  /// sheet's cell, whose scene's arrows may reach past it.
  void inside(const Vec2& corner, const Vec2& size, const std::function<void(Drawing&)>& draw);
  /// Moves the origin of what follows by `offset` pixels.
  void translate(const Vec2& offset);

 private:
  /// One outline of a batch: a closed polygon, a circle, or an open line.
  struct Outline {
    std::vector<Vec2> points;
    double radius = 0.0;  ///< > 0: a circle round points[0]
    bool closed = true;
  };
  /// Outlines painted together: filled, or stroked `width` wide.
  struct Batch {
    bool stroke = false;
    Color colour;
    double width = 0.0;
    std::vector<Outline> outlines;
  };
  void add(bool stroke, Color colour, double width, Outline outline);
  void log(DrawnShape::Kind kind, std::vector<Vec2> points, Color colour, double size,
           std::string text = "");
  void setColour(Color colour);

  cairo_t* cairo_ = nullptr;
  DrawingLog* log_ = nullptr;
  std::string role_;
  std::vector<Batch> batches_;
};

enum class ImageFormat { Png, Svg, Pdf };
/// Height of a line of text of font size `size`: DejaVu Sans's ascent plus descent.
double lineHeight(double size);

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
