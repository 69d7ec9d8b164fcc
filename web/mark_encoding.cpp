// The marks as numbers and SVG path data for the page (mark_encoding.h). Compiled without
// exceptions: in a function that can unwind, emscripten routes every call through JavaScript,
// and a frame's encoding makes tens of thousands of calls.
#include "mark_encoding.h"

#include <cmath>

namespace sandbox {

namespace render = impulse2d::render;

namespace {

/// Path coordinates are written in hundredths of a pixel, as integers.
constexpr double kSteps = 100.0;
/// The most characters a coordinate and a command letter take: " -9223372036854775808" (the
/// most hundredths there are) with a point, and a letter.
constexpr std::size_t kMostPerNumber = 24;

long long hundredths(double value) {
  return std::llround(value * kSteps);
}

/// Writes path data at the end of a string, into room made for it beforehand: a frame's
/// hundred thousand numbers, each written without a call to the string.
class PathWriter {
 public:
  /// Room for `numbers` numbers and their commands at the end of `text`.
  PathWriter(std::string& text, std::size_t numbers) : text_(text), used_(text.size()) {
    text_.resize(used_ + kMostPerNumber * numbers + 2);
    cursor_ = &text_[used_];
  }
  /// Cuts the string to what was written.
  ~PathWriter() { text_.resize(std::size_t(cursor_ - text_.data())); }
  PathWriter(const PathWriter&) = delete;
  PathWriter& operator=(const PathWriter&) = delete;

  void letter(char command) { *cursor_++ = command; }
  void words(const char* text) {
    while (*text != '\0') *cursor_++ = *text++;
  }
  void number(double value) { fixed(hundredths(value)); }
  /// Writes " 12.34" for 1234 hundredths (" -0.05" for -5, " 3.1" for 310, " 3" for 300).
  void fixed(long long value) {
    char digits[32];
    char* end = digits + sizeof digits;
    char* start = end;
    unsigned long long magnitude = value < 0 ? 0ull - static_cast<unsigned long long>(value)
                                             : static_cast<unsigned long long>(value);
    const unsigned long long fraction = magnitude % 100;
    if (fraction % 10 != 0) *--start = char('0' + fraction % 10);
    if (fraction != 0) {
      *--start = char('0' + fraction / 10);
      *--start = '.';
    }
    magnitude /= 100;
    do {
      *--start = char('0' + magnitude % 10);
      magnitude /= 10;
    } while (magnitude != 0);
    if (value < 0) *--start = '-';
    *--start = ' ';
    while (start != end) *cursor_++ = *start++;
  }

 private:
  std::string& text_;
  std::size_t used_;
  char* cursor_;
};

/// A circle as two half arcs, as canvas arc(0, 2π) draws it, from its rightmost point.
void writeCircle(PathWriter& out, const impulse2d::Vec2& centre, double radius) {
  out.letter('M');
  out.number(centre.x() + radius);
  out.number(centre.y());
  for (const double x : {centre.x() - radius, centre.x() + radius}) {
    out.letter('A');
    out.number(radius);
    out.number(radius);
    out.words(" 0 1 0");
    out.number(x);
    out.number(centre.y());
  }
  out.letter('Z');
}

/// A polygon or line: the first point absolute, each next one relative to the last (shorter to
/// write and to parse). The steps are taken between rounded points, so no rounding adds up.
void writePolyline(PathWriter& out, const render::Outline& outline) {
  long long x = hundredths(outline.points.front().x());
  long long y = hundredths(outline.points.front().y());
  out.letter('M');
  out.fixed(x);
  out.fixed(y);
  if (outline.points.size() > 1) out.letter('l');
  for (std::size_t k = 1; k < outline.points.size(); ++k) {
    const long long nextX = hundredths(outline.points[k].x());
    const long long nextY = hundredths(outline.points[k].y());
    out.fixed(nextX - x);
    out.fixed(nextY - y);
    x = nextX;
    y = nextY;
  }
  if (outline.closed) out.letter('Z');
}

void appendOutlines(EncodedMarks& encoded, const render::Mark& mark) {
  const render::Color& c = mark.colour;
  encoded.numbers.insert(encoded.numbers.end(),
                         {double(c.r), double(c.g), double(c.b), double(c.a), mark.size});
  std::size_t numbers = 0;
  for (const render::Outline& outline : mark.outlines) numbers += 2 * outline.points.size() + 10;
  PathWriter out(encoded.paths, numbers);
  for (const render::Outline& outline : mark.outlines) {
    if (outline.points.empty()) continue;
    if (outline.radius > 0.0) {
      writeCircle(out, outline.points.front(), outline.radius);
    } else {
      writePolyline(out, outline);
    }
  }
  out.letter('|');
}

}  // namespace

EncodedMarks encodeMarks(const std::vector<render::Mark>& marks) {
  EncodedMarks encoded;
  encoded.paths.reserve(1 << 16);
  for (const render::Mark& mark : marks) {
    encoded.numbers.push_back(double(mark.kind));
    const render::Color& c = mark.colour;
    switch (mark.kind) {
      case render::Mark::Kind::Fill:
      case render::Mark::Kind::Stroke:
        appendOutlines(encoded, mark);
        break;
      case render::Mark::Kind::Text:
        encoded.numbers.insert(encoded.numbers.end(),
                               {double(c.r), double(c.g), double(c.b), double(c.a), mark.size,
                                mark.at.x(), mark.at.y()});
        encoded.texts.push_back(mark.text);
        break;
      case render::Mark::Kind::Translate:
      case render::Mark::Kind::Clip:
        encoded.numbers.insert(encoded.numbers.end(), {mark.at.x(), mark.at.y()});
        break;
      case render::Mark::Kind::Save:
      case render::Mark::Kind::Restore:
        break;
    }
  }
  return encoded;
}

}  // namespace sandbox
