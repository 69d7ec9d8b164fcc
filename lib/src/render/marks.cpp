// The Drawing calls as marks: batching, text markup and the shapes' outlines; no Cairo, so the
// browser's module draws its frames with the same code as the PNG frames.
#include "impulse2d/render/marks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace impulse2d::render {

namespace {

/// DejaVu Sans's descent per em, as Cairo reports it.
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

/// The directions of a dot's corners after the first, (cos, sin) of 2πk/kSmallCircleSides:
/// computed once, as a pyramid's frame draws a thousand dots.
const std::array<Vec2, kSmallCircleSides - 1>& dotDirections() {
  static const std::array<Vec2, kSmallCircleSides - 1> directions = [] {
    std::array<Vec2, kSmallCircleSides - 1> result;
    for (int k = 1; k < kSmallCircleSides; ++k) {
      const double angle = 2.0 * kPi * k / kSmallCircleSides;
      result[std::size_t(k - 1)] = Vec2(std::cos(angle), std::sin(angle));
    }
    return result;
  }();
  return directions;
}

/// A circle's outline: a dot as a polygon (at this size it looks the same, with a third of the
/// edges), a larger circle as itself.
Outline circleOutline(const Vec2& centre, double radius) {
  if (radius > kSmallCircle) return {{centre}, radius};
  Outline dot;
  dot.points.reserve(kSmallCircleSides);
  dot.points.push_back(Vec2(centre.x() + radius, centre.y()));
  for (const Vec2& direction : dotDirections()) {
    dot.points.push_back(
        Vec2(centre.x() + radius * direction.x(), centre.y() + radius * direction.y()));
  }
  return dot;
}

/// A mark that carries no shapes: Save, Translate, Clip, Restore.
Mark placing(Mark::Kind kind, const Vec2& at = Vec2::Zero()) {
  Mark mark;
  mark.kind = kind;
  mark.at = at;
  return mark;
}

}  // namespace

Color withOpacity(Color colour, double opacity) {
  colour.a = std::uint8_t(std::lround(colour.a * std::clamp(opacity, 0.0, 1.0)));
  return colour;
}

double lineHeight(double size) {
  return (kFontAscent + kDescent) * size;
}

void Canvas::placePart(const Picture&, const Vec2&, const Vec2&, const Vec2&, double) {
  throw std::logic_error("only a Cairo canvas can draw a recorded picture");
}

Drawing::Drawing(Canvas& canvas, DrawingLog* log) : canvas_(&canvas), log_(log) {}

Drawing::~Drawing() {
  flush();
}

void Drawing::log(DrawnShape::Kind kind, const std::vector<Vec2>& points, Color colour, double size,
                  const std::string& text) {
  if (log_ != nullptr) log_->push_back({kind, role_, points, colour, size, text});
}

void Drawing::log(DrawnShape::Kind kind, std::initializer_list<Vec2> points, Color colour,
                  double size, const std::string& text) {
  if (log_ != nullptr) log(kind, std::vector<Vec2>(points), colour, size, text);
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
  for (Batch& batch : batches_) {
    Mark mark;
    mark.kind = batch.stroke ? Mark::Kind::Stroke : Mark::Kind::Fill;
    mark.colour = batch.colour;
    mark.size = batch.width;
    mark.outlines = std::move(batch.outlines);
    canvas_->paint(std::move(mark));
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
  Outline shape = circleOutline(centre, radius);
  add(false, fill, 0.0, shape);
  if (outlineWidth > 0.0) add(true, outline, outlineWidth, std::move(shape));
  log(DrawnShape::Kind::Circle, {centre}, fill, radius);
}

void Drawing::ring(const Vec2& centre, double radius, Color colour, double width) {
  add(true, colour, width, circleOutline(centre, radius));
  log(DrawnShape::Kind::Circle, {centre}, colour, radius);
}

void Drawing::rectangle(const Vec2& corner, const Vec2& size, Color colour) {
  Outline shape{
      {corner, corner + Vec2(size.x(), 0.0), corner + size, corner + Vec2(0.0, size.y())}};
  log(DrawnShape::Kind::Polygon, shape.points, colour, 0.0);
  add(false, colour, 0.0, std::move(shape));
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
  double x = corner.x();
  const double baseline = corner.y() + kFontAscent * size;
  for (const Run& run : parseMarkup(text)) {
    if (run.text.empty()) continue;
    Mark mark;
    mark.kind = Mark::Kind::Text;
    mark.colour = colour;
    mark.size = run.subscript ? kSubscriptSize * size : size;
    mark.at = Vec2(x, baseline + (run.subscript ? kSubscriptDrop * size : 0.0));
    mark.text = run.text;
    x += canvas_->advance(run.text, mark.size);
    canvas_->paint(std::move(mark));
  }
  log(DrawnShape::Kind::Text, {corner, Vec2(x, corner.y() + lineHeight(size))}, colour, size, text);
}

double Drawing::textWidth(const std::string& text, double size) {
  double width = 0.0;
  for (const Run& run : parseMarkup(text)) {
    if (run.text.empty()) continue;
    width += canvas_->advance(run.text, run.subscript ? kSubscriptSize * size : size);
  }
  return width;
}

void Drawing::placePart(const Picture& picture, const Vec2& from, const Vec2& size,
                        const Vec2& corner, double scale) {
  flush();
  canvas_->placePart(picture, from, size, corner, scale);
}

void Drawing::inside(const Vec2& corner, const Vec2& size,
                     const std::function<void(Drawing&)>& draw) {
  flush();
  canvas_->paint(placing(Mark::Kind::Save));
  canvas_->paint(placing(Mark::Kind::Translate, corner));
  canvas_->paint(placing(Mark::Kind::Clip, size));
  draw(*this);
  flush();
  canvas_->paint(placing(Mark::Kind::Restore));
}

void Drawing::translate(const Vec2& offset) {
  flush();
  canvas_->paint(placing(Mark::Kind::Translate, offset));
}

}  // namespace impulse2d::render
