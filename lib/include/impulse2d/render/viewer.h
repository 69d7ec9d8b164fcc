// A run's frames as one page to open from disk: DIR/<scene>/index.html (PREFIX.html for traces
// and comparisons), with no network and no server. It shows one frame at a time, moved with a
// slider, the arrow keys, a play button, or the address's "#frame=N"; beside it the step's
// figures from the run. The frames stay the PNG files beside the page.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "impulse2d/render/frame_writer.h"

namespace impulse2d::render {

/// Figures per frame: the column names (with units) and one row per frame written.
struct FigureTable {
  /// names, with units
  std::vector<std::string> columns;
  /// one per frame, one value per column
  std::vector<std::vector<double>> rows;
};

/// "index.html" for a run's frames (prefix == scene), else "PREFIX.html".
std::string viewerName(const FrameWriter& writer, const std::string& scene);

/// Writes the page for the writer's frames, showing `figures` (rows by frame number; fewer rows
/// than frames leaves the rest blank) and playing at framesPerSecond. Returns its path.
std::filesystem::path writeViewer(const FrameWriter& writer, const std::string& scene,
                                  const FigureTable& figures, double framesPerSecond);

}  // namespace impulse2d::render
