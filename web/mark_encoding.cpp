// The marks as numbers and SVG path data for the page (mark_encoding.h). Compiled without
// exceptions: in a function that can unwind, emscripten routes every call through JavaScript,
// and a frame's encoding makes tens of thousands of calls.
#include "mark_encoding.h"

#include <charconv>
#include <cmath>

namespace sandbox {

namespace render = impulse2d::render;

namespace {

/// Path coordinates are written in hundredths of a pixel, as integers.
constexpr double kSteps = 100.0;
/// A mark's outlines are written in pieces of this many, each parsed once for as long as it
/// comes again from frame to frame (mark_encoding.h).
constexpr std::size_t kOutlinesPerPiece = 16;
/// The most characters a coordinate and a command letter take: " -9223372036854775808" (the
/// most hundredths there are) with a point, and a letter.
constexpr std::size_t kMostPerNumber = 24;

long long hundredths(double value) {
  return static_cast<long long>(std::nearbyint(value * kSteps));
}

/// Writes path data at the end of a string through a buffer of its own, which it appends when
/// nearly full: a frame's hundred thousand numbers cost no call to the string each.
class PathWriter {
 public:
  explicit PathWriter(std::string& text) : text_(text) {}
  /// Appends what is left in the buffer.
  ~PathWriter() { text_.append(buffer_, std::size_t(cursor_ - buffer_)); }
  PathWriter(const PathWriter&) = delete;
  PathWriter& operator=(const PathWriter&) = delete;

  void letter(char command) {
    makeRoom();
    *cursor_++ = command;
  }
  void words(const char* text) {
    makeRoom();
    while (*text != '\0') *cursor_++ = *text++;
  }
  void number(double value) { fixed(hundredths(value)); }
  /// Writes " 12.34" for 1234 hundredths (" -0.05" for -5, " 3.1" for 310, " 3" for 300).
  void fixed(long long value) {
    makeRoom();
    char* const room = cursor_ + kMostPerNumber;  // within the buffer: makeRoom saw to it
    *cursor_++ = ' ';
    if (value < 0) *cursor_++ = '-';
    const unsigned long long magnitude = value < 0 ? 0ull - static_cast<unsigned long long>(value)
                                                   : static_cast<unsigned long long>(value);
    cursor_ = std::to_chars(cursor_, room, magnitude / 100).ptr;
    const unsigned fraction = unsigned(magnitude % 100);
    if (fraction != 0) {
      *cursor_++ = '.';
      *cursor_++ = char('0' + fraction / 10);
      if (fraction % 10 != 0) *cursor_++ = char('0' + fraction % 10);
    }
  }

 private:
  /// Room for one more number or word (at most kMostPerNumber characters).
  void makeRoom() {
    if (std::size_t(buffer_ + sizeof buffer_ - cursor_) >= kMostPerNumber) return;
    text_.append(buffer_, std::size_t(cursor_ - buffer_));
    cursor_ = buffer_;
  }

  std::string& text_;
  char buffer_[4096];
  char* cursor_ = buffer_;
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

/// Appends the mark's colour, width and path data, "=" where it is that of the mark before (`last`
/// is where that one's starts in encoded.paths, npos if the mark before has none), and sets
/// `last` to where this one's starts.
void appendOutlines(EncodedMarks& encoded, const render::Mark& mark, std::size_t& last) {
  const render::Color& c = mark.colour;
  encoded.numbers.insert(encoded.numbers.end(),
                         {double(c.r), double(c.g), double(c.b), double(c.a), mark.size});
  const std::size_t start = encoded.paths.size();
  {
    PathWriter out(encoded.paths);
    std::size_t written = 0;
    for (const render::Outline& outline : mark.outlines) {
      if (outline.points.empty()) continue;
      if (written > 0 && written % kOutlinesPerPiece == 0) out.letter(';');
      ++written;
      if (outline.radius > 0.0) {
        writeCircle(out, outline.points.front(), outline.radius);
      } else {
        writePolyline(out, outline);
      }
    }
    out.letter('|');
  }
  const std::size_t length = encoded.paths.size() - start;
  if (last != std::string::npos && length > 1 && start - last == length &&
      encoded.paths.compare(last, length, encoded.paths, start, length) == 0) {
    encoded.paths.replace(start, length, "=|");
  }
  last = start;
}

}  // namespace

EncodedMarks encodeMarks(const std::vector<render::Mark>& marks) {
  EncodedMarks encoded;
  encoded.paths.reserve(1 << 19);
  std::size_t last = std::string::npos;
  for (const render::Mark& mark : marks) {
    encoded.numbers.push_back(double(mark.kind));
    const render::Color& c = mark.colour;
    switch (mark.kind) {
      case render::Mark::Kind::Fill:
      case render::Mark::Kind::Stroke:
        appendOutlines(encoded, mark, last);
        continue;
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
    last = std::string::npos;
  }
  return encoded;
}

}  // namespace sandbox
