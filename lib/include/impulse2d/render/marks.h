// A frame as drawing commands ("marks"): filled and stroked outlines, text runs, and the clips
// and moves between them. The Drawing calls frames are drawn with (shapes, arrows, text in DejaVu
// Sans) become marks, which go to a Canvas: Cairo paints them into a picture as they come
// (drawing.h: PNG, SVG and PDF frames), a MarkList keeps them for the browser's canvas to paint
// (web/). Both draw from the same marks, so the page shows what the frames show.
//
// Coordinates are pixels, x to the right and y down. Text takes a small markup for the lecture's
// symbols: after a symbol, "λ_n" sets n as a subscript and "λ_{max}" a longer one ("pushed_box"
// stays as it is); the symbols themselves (μ, λ, Δ, →) are Unicode and drawn from the font.
#pragma once

#include <functional>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "impulse2d/math.h"
#include "impulse2d/render/image.h"

namespace impulse2d::render {

class Picture;

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

/// One outline of a fill or stroke: a polygon (closed) or an open line through its points, or a
/// circle of `radius` round points[0].
struct Outline {
  std::vector<Vec2> points;  ///< pixels: the corners, or the circle's centre
  double radius = 0.0;       ///< > 0: a circle
  bool closed = true;        ///< a polygon (true) or an open line
};

/// One drawing command.
struct Mark {
  /// What the mark does.
  enum class Kind {
    Fill,       ///< fills the outlines (non-zero winding) in colour
    Stroke,     ///< strokes the outlines `size` wide, mitred joins, square-cut ends
    Text,       ///< one run of plain text of font size `size`, its baseline starting at `at`
    Save,       ///< keeps the origin and the clip
    Translate,  ///< moves the origin by `at`
    Clip,       ///< clips to the rectangle from the origin of size `at`
    Restore,    ///< goes back to the last Save
  };
  Kind kind = Kind::Fill;         ///< what it does
  Color colour;                   ///< Fill, Stroke, Text
  double size = 0.0;              ///< Stroke: line width; Text: font size (pixels)
  std::vector<Outline> outlines;  ///< Fill, Stroke
  Vec2 at = Vec2::Zero();         ///< Text, Translate, Clip
  std::string text;               ///< Text: valid UTF-8, no markup
};

/// Where marks go.
class Canvas {
 public:
  virtual ~Canvas() = default;
  /// Paints or keeps one mark.
  virtual void paint(Mark mark) = 0;
  /// Advance width (pixels) of plain `text` in DejaVu Sans at font size `size` (pixels).
  virtual double advance(const std::string& text, double size) = 0;
  /// Draws the part of a recorded picture from `from` of size `size` with its top left corner at
  /// `corner`, scaled by `scale`. Only Cairo's canvas holds pictures; others throw logic_error.
  virtual void placePart(const Picture& picture, const Vec2& from, const Vec2& size,
                         const Vec2& corner, double scale);
};

/// A canvas that keeps its marks, measuring text with the function it is given.
class MarkList : public Canvas {
 public:
  /// The advance width (pixels) of plain text at a font size (pixels).
  using Measure = std::function<double(const std::string& text, double size)>;
  /// An empty list whose text is measured by `measure`.
  explicit MarkList(Measure measure) : measure_(std::move(measure)) {}
  void paint(Mark mark) override { marks_.push_back(std::move(mark)); }
  double advance(const std::string& text, double size) override { return measure_(text, size); }
  /// The marks so far, in order.
  const std::vector<Mark>& marks() const { return marks_; }

 private:
  Measure measure_;
  std::vector<Mark> marks_;
};

/// The calls frames are drawn with; optionally logged for tests.
///
/// Shapes are batched: each call adds its outline to the batch of its paint (fill or stroke,
/// colour, line width), and every batch becomes one mark, in the order the batches were first
/// used, when text or a picture is drawn or the drawing ends. A pyramid's thousand arrows of one
/// kind are then one fill, not a thousand: what makes a frame fast. A shape drawn later in an
/// earlier batch's paint goes under the later batches, so draw in layers (bodies, then arrows,
/// then points), as frames do.
class Drawing {
 public:
  /// Draws onto `canvas`; `log`, when given, receives every call.
  explicit Drawing(Canvas& canvas, DrawingLog* log = nullptr);
  /// Draws into `picture` (its recording, through Cairo: drawing.h).
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
  /// Turns every batch so far into marks.
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
  /// Outlines painted together: filled, or stroked `width` wide.
  struct Batch {
    bool stroke = false;
    Color colour;
    double width = 0.0;
    std::vector<Outline> outlines;
  };
  void add(bool stroke, Color colour, double width, Outline outline);
  /// Records one call in the log, when there is one (a frame drawn for the screen builds none
  /// of what it would record).
  void log(DrawnShape::Kind kind, const std::vector<Vec2>& points, Color colour, double size,
           const std::string& text = "");
  void log(DrawnShape::Kind kind, std::initializer_list<Vec2> points, Color colour, double size,
           const std::string& text = "");

  std::unique_ptr<Canvas> owned_;  ///< the canvas of a picture drawn into
  Canvas* canvas_ = nullptr;
  DrawingLog* log_ = nullptr;
  std::string role_;
  std::vector<Batch> batches_;
};

/// Height of a line of text of font size `size`: DejaVu Sans's ascent plus descent.
double lineHeight(double size);
/// DejaVu Sans's ascent per em, as Cairo reports it: a line's baseline lies this far below its top.
inline constexpr double kFontAscent = 0.928;

}  // namespace impulse2d::render
