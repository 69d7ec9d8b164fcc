// Numbered frames of a run, every K-th step, and the run's contact sheet, as PNG, SVG or PDF:
//   ROOT/SCENE/PREFIX_00000.png, PREFIX_00001.png, ...  (numbered from 0 without gaps, ready for
//   `ffmpeg -i PREFIX_%05d.png`), and ROOT/SCENE/PREFIX_sheet.png.
// The writer keeps each frame's picture (a recording of its drawing calls, not its pixels) for
// the sheet and the GIF.
// PREFIX is the scene's name for a run; traces and comparisons use their own (tracePrefix,
// comparePrefix) so their frames sit beside the run's without mixing with them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "impulse2d/render/drawing.h"
#include "impulse2d/render/frame.h"
#include "impulse2d/render/png.h"
#include "impulse2d/render/render_settings.h"

namespace impulse2d::render {

/// "SCENE_step00042": the prefix of the frames tracing step 42.
std::string tracePrefix(const std::string& scene, long step);
/// "SCENE_compare": the prefix of the side-by-side frames of `i2d compare`.
std::string comparePrefix(const std::string& scene);

/// Writes a run's numbered PNG frames and its contact sheet into one directory.
class FrameWriter {
 public:
  /// Frames go to root/scene/. Creates root (whose parent must exist) and root/scene, removes
  /// frames of an earlier run with the same prefix (so ffmpeg sees only the frames written now),
  /// and checks the directory is writable. Throws one RenderError naming the path when it is not.
  FrameWriter(const std::filesystem::path& root, const std::string& scene, int every = 1,
              const std::string& prefix = "", const RenderSettings& settings = {},
              ImageFormat format = ImageFormat::Png);

  /// True for the steps whose frames are kept: 0, every, 2·every, ...
  bool wants(long step) const { return step % every_ == 0; }
  /// Writes the next numbered frame, of the given step; returns its path. A `preferred` frame
  /// goes on the sheet before the others (chooseFrames).
  std::filesystem::path write(long step, const Frame& frame, bool preferred = false);
  /// Writes PREFIX_sheet from the frames written so far; returns its path. Throws RenderError
  /// when no frame was written.
  std::filesystem::path writeContactSheet() const;

  /// Path of frame number `index`: directory()/PREFIX_%05d.png (.svg, .pdf).
  std::filesystem::path framePath(int index) const;
  /// Path of the contact sheet: directory()/PREFIX_sheet.png.
  std::filesystem::path sheetPath() const;
  /// ROOT/SCENE
  const std::filesystem::path& directory() const { return directory_; }
  /// the start of every file name
  const std::string& prefix() const { return prefix_; }
  /// steps between frames
  int every() const { return every_; }
  /// frames written so far
  int frameCount() const { return int(steps_.size()); }
  /// The step of each frame written, by frame number.
  const std::vector<long>& steps() const { return steps_; }
  /// The frames written, by frame number.
  const std::vector<Frame>& frames() const { return frames_; }
  /// The frames' file format.
  ImageFormat format() const { return format_; }

 private:
  void prepareDirectory(const std::filesystem::path& root);
  void removeEarlierFrames() const;

  std::filesystem::path directory_;
  std::string prefix_;
  int every_ = 1;
  RenderSettings settings_;
  ImageFormat format_ = ImageFormat::Png;
  PictureWriter pictures_;
  std::vector<long> steps_;
  std::vector<Frame> frames_;
  std::vector<bool> preferred_;
};

}  // namespace impulse2d::render
