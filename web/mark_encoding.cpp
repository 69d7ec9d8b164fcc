// The marks as numbers and SVG path data for the page (mark_encoding.h). Compiled without
// exceptions: in a function that can unwind, emscripten routes every call through JavaScript,
// and a frame's encoding makes tens of thousands of calls.
#include "mark_encoding.h"

#include <cmath>
#include <cstdlib>

namespace sandbox {

namespace render = impulse2d::render;

namespace {

/// Path coordinates are written in hundredths of a pixel, as integers.
constexpr double kSteps = 100.0;

long hundredths(double value) {
  return std::lround(value * kSteps);
}

/// Appends " 12.34" for 1234 hundredths (" -0.05" for -5, " 3.1" for 310, " 3" for 300).
void appendFixed(std::string& out, long value) {
  char text[24];
  char* end = text + sizeof text;
  char* start = end;
  unsigned long magnitude = static_cast<unsigned long>(std::labs(value));
  const unsigned long fraction = magnitude % 100;
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
  out.append(start, end);
}

void appendNumber(std::string& out, double value) {
  appendFixed(out, hundredths(value));
}

/// A circle as two half arcs, as canvas arc(0, 2π) draws it, from its rightmost point.
void appendCircle(std::string& out, const impulse2d::Vec2& centre, double radius) {
  out += 'M';
  appendNumber(out, centre.x() + radius);
  appendNumber(out, centre.y());
  for (const double x : {centre.x() - radius, centre.x() + radius}) {
    out += 'A';
    appendNumber(out, radius);
    appendNumber(out, radius);
    out += " 0 1 0";
    appendNumber(out, x);
    appendNumber(out, centre.y());
  }
  out += 'Z';
}

/// A polygon or line: the first point absolute, each next one relative to the last (shorter to
/// write and to parse). The steps are taken between rounded points, so no rounding adds up.
void appendPolyline(std::string& out, const render::Outline& outline) {
  long x = hundredths(outline.points.front().x());
  long y = hundredths(outline.points.front().y());
  out += 'M';
  appendFixed(out, x);
  appendFixed(out, y);
  if (outline.points.size() > 1) out += 'l';
  for (std::size_t k = 1; k < outline.points.size(); ++k) {
    const long nextX = hundredths(outline.points[k].x());
    const long nextY = hundredths(outline.points[k].y());
    appendFixed(out, nextX - x);
    appendFixed(out, nextY - y);
    x = nextX;
    y = nextY;
  }
  if (outline.closed) out += 'Z';
}

void appendOutlines(EncodedMarks& encoded, const render::Mark& mark) {
  const render::Color& c = mark.colour;
  encoded.numbers.insert(encoded.numbers.end(),
                         {double(c.r), double(c.g), double(c.b), double(c.a), mark.size});
  for (const render::Outline& outline : mark.outlines) {
    if (outline.points.empty()) continue;
    if (outline.radius > 0.0) {
      appendCircle(encoded.paths, outline.points.front(), outline.radius);
    } else {
      appendPolyline(encoded.paths, outline);
    }
  }
  encoded.paths += '|';
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
