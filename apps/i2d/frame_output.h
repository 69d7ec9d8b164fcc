// Frame output of the commands: a run's numbered frames, its contact sheet and optional video, as
// docs/rendering.md lays them out under --frames DIR.
#pragma once

#include <string>
#include <vector>

#include "impulse2d/render/frame.h"
#include "impulse2d/render/frame_writer.h"
#include "impulse2d/render/viewer.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/simulation.h"
#include "options.h"
#include "run_figures.h"

namespace i2d {

/// The default render settings with the command line's overlay switches and theme.
impulse2d::render::RenderSettings renderSettings(const FrameOptions& options);

/// The camera of a run's frames, in a frame of --size or the [render] table's size, before the
/// run's states are added to it.
impulse2d::render::RunCamera runCamera(const impulse2d::SceneFile& scene,
                                       const FrameOptions& options,
                                       const impulse2d::render::RenderSettings& settings);

/// The camera of frames of the scene as it starts (a traced step's).
impulse2d::render::Camera sceneCamera(const impulse2d::SceneFile& scene,
                                      const FrameOptions& options,
                                      const impulse2d::render::RenderSettings& settings);

/// The summary's line naming the world rectangle the frames show:
/// "view         X0 .. X1 m, Y0 .. Y1 m".
std::string viewLine(const impulse2d::Aabb& shown);

/// Throws RunFailure before a run when --video or --animation mp4 was asked for and ffmpeg is
/// not on PATH.
void checkVideoPossible(const FrameOptions& options);

/// The video, animation and viewer page of written frames, as asked for; returns summary lines.
/// The viewer is always written: `figures` fills its table, `plots` go under the frame with a
/// cursor at each frame's time (step × secondsPerStep).
std::vector<std::string> writeFrameExtras(const FrameOptions& options,
                                          const impulse2d::render::FrameWriter& writer,
                                          const std::string& scene, double framesPerSecond,
                                          const impulse2d::render::FigureTable& figures,
                                          const std::vector<impulse2d::render::ViewerPlot>& plots,
                                          double secondsPerStep);

/// True for the steps a run records: every K-th, and the last.
bool isRecorded(long step, long lastStep, int every);

/// The summary lines of written frames: where they are, the sheet, the video.
std::vector<std::string> describeFrames(const impulse2d::render::FrameWriter& writer);

/// The frames of one run: every K-th step and the last, kept as the run goes and drawn when it
/// ends, through the camera fitted to them all; then the sheet and the video.
class FrameRecorder {
 public:
  /// Creates DIR/<scene>/ and checks it is writable (RenderError naming the path).
  FrameRecorder(const FrameOptions& options, const impulse2d::SceneFile& scene, int every);

  /// Keeps the state of the simulation's current step if the run records it.
  void record(const impulse2d::Simulation& simulation, long lastStep);
  /// Draws and writes the kept states through `camera` (every kept state added to it), then the
  /// contact sheet, the viewer page (its table and plots from `figures`, by step) and the video
  /// or animation when asked; returns the summary lines.
  std::vector<std::string> finish(const impulse2d::render::RunCamera& camera, double dt,
                                  const std::vector<StepFigures>& figures);

 private:
  impulse2d::render::RenderSettings settings_;
  impulse2d::render::FrameWriter writer_;
  FrameOptions options_;
  std::string scene_;
  std::vector<impulse2d::render::FrameState> states_;
  std::vector<long> steps_;
  bool loads_ = false;  ///< the scene has applied loads: the viewer plots force against friction
};

}  // namespace i2d
