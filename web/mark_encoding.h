// The frame's marks (render/marks.h) as the page paints them: a few numbers per mark and, for each
// fill and stroke, its outlines as SVG path data, which the page turns into one Path2D. One
// string the canvas parses in one call costs far less than a canvas call per point.
#pragma once

#include <string>
#include <vector>

#include "impulse2d/render/marks.h"

namespace sandbox {

/// The marks, encoded for web/page.js paintMarks.
struct EncodedMarks {
  /// Per mark, in order: its kind (render::Mark::Kind), then for Fill and Stroke the colour
  /// (r, g, b, a) and line width; for Text the colour, font size and baseline start (x, y); for
  /// Translate and Clip the offset or size (x, y); nothing more for Save and Restore.
  std::vector<double> numbers;
  /// The path data of each Fill and Stroke, in order, each followed by '|'; "=" where it is the
  /// last one's again (a contact point's dots, filled and then outlined), parsed once. Within a
  /// mark, ';' ends each piece of 16 outlines: a piece that comes again in the next frame (most
  /// of a pyramid's bodies and contact points, settled to the hundredth of a pixel) is not parsed
  /// again.
  std::string paths;
  /// The text of each Text mark, in order.
  std::vector<std::string> texts;
};

/// Encodes `marks`; path coordinates are rounded to a hundredth of a pixel.
EncodedMarks encodeMarks(const std::vector<impulse2d::render::Mark>& marks);

}  // namespace sandbox
