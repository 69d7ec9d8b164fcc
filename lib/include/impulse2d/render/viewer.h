// A run's frames as one page to open from disk: DIR/<scene>/index.html (PREFIX.html for traces
// and comparisons), with no network and no server. It shows one frame at a time, moved with a
// slider, the arrow keys, a play button, or the address's "#frame=N"; beside it the step's
// figures from the run, and plots of the run (gnuplot SVGs beside the page) with a cursor at the
// frame's time. The frames stay the files beside the page.
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

/// A plot the page shows under the frame: an image beside the page whose x axis is time, from
/// timeMin at `left` to timeMax at `right` (fractions of the image's width), so the page can put
/// a cursor at a frame's time.
struct ViewerPlot {
  std::string file;      ///< the image's name, beside the page
  double timeMin = 0.0;  ///< s
  double timeMax = 1.0;  ///< s
  double left = 0.0;     ///< where timeMin lies, as a fraction of the image's width
  double right = 1.0;    ///< where timeMax lies, as a fraction of the image's width
};

/// "index.html" for a run's frames (prefix == scene), else "PREFIX.html".
std::string viewerName(const FrameWriter& writer, const std::string& scene);

/// Writes the page for the writer's frames, showing `figures` (rows by frame number; fewer rows
/// than frames leaves the rest blank) and playing at framesPerSecond; with `plots`, each under
/// the frame with its cursor at step × secondsPerStep. Returns its path.
std::filesystem::path writeViewer(const FrameWriter& writer, const std::string& scene,
                                  const FigureTable& figures, double framesPerSecond,
                                  const std::vector<ViewerPlot>& plots = {},
                                  double secondsPerStep = 0.0);

}  // namespace impulse2d::render
