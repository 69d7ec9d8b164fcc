// Frames, sheets and videos of the i2d commands.
#include "frame_output.h"

#include <cstdio>

#include "failures.h"
#include "impulse2d/render/animation.h"
#include "impulse2d/render/video.h"
#include "plots.h"

namespace i2d {

using namespace impulse2d::render;

RenderSettings renderSettings(const FrameOptions& options) {
  RenderSettings settings;
  settings.overlays = options.overlays;
  if (options.printTheme) settings.colours = printPalette();
  return settings;
}

RunCamera runCamera(const impulse2d::SceneFile& scene, const FrameOptions& options,
                    const RenderSettings& settings) {
  const int width = options.size ? options.size->width : scene.view.width;
  const int height = options.size ? options.size->height : scene.view.height;
  return RunCamera(scene.view, settings, width, height);
}

Camera sceneCamera(const impulse2d::SceneFile& scene, const FrameOptions& options,
                   const RenderSettings& settings) {
  RunCamera camera = runCamera(scene, options, settings);
  const std::vector<impulse2d::Body> bodies = impulse2d::buildBodies(scene);
  camera.add(bodies);
  return camera.cameraFor(bodies);
}

std::string viewLine(const impulse2d::Aabb& shown) {
  char text[160];
  std::snprintf(text, sizeof text, "view         %.3f .. %.3f m, %.3f .. %.3f m", shown.lower.x(),
                shown.upper.x(), shown.lower.y(), shown.upper.y());
  return text;
}

void checkVideoPossible(const FrameOptions& options) {
  if (options.video && !findFfmpeg()) {
    throw RunFailure(
        "--video needs ffmpeg on PATH; install it, or leave out --video and make "
        "the video by hand (docs/rendering.md)");
  }
  if (options.animation == std::optional<std::string>("mp4") && !findFfmpeg()) {
    throw RunFailure(
        "--animation mp4 needs ffmpeg on PATH, which is not there; use --animation gif, or "
        "install ffmpeg");
  }
}

std::vector<std::string> writeFrameExtras(const FrameOptions& options, const FrameWriter& writer,
                                          const std::string& scene, double framesPerSecond,
                                          const FigureTable& figures,
                                          const std::vector<ViewerPlot>& plots,
                                          double secondsPerStep) {
  std::vector<std::string> lines;
  lines.push_back(
      "viewer       " +
      writeViewer(writer, scene, figures, framesPerSecond, plots, secondsPerStep).string());
  if (options.video || options.animation == std::optional<std::string>("mp4")) {
    lines.push_back("video        " + writeVideo(writer, framesPerSecond).string());
  }
  if (options.animation == std::optional<std::string>("gif")) {
    lines.push_back("animation    " + writeGif(writer, framesPerSecond).string());
  }
  return lines;
}

bool isRecorded(long step, long lastStep, int every) {
  return step % every == 0 || step == lastStep;
}

std::vector<std::string> describeFrames(const FrameWriter& writer) {
  const int count = writer.frameCount();
  return {"frames       " + writer.framePath(0).string() + " ... " +
              writer.framePath(count - 1).filename().string() + " (" + std::to_string(count) +
              " frames)",
          "sheet        " + writer.sheetPath().string()};
}

FrameRecorder::FrameRecorder(const FrameOptions& options, const impulse2d::SceneFile& scene,
                             int every)
    : settings_(renderSettings(options)),
      writer_(*options.directory, scene.name, every, "", settings_, options.format),
      options_(options),
      scene_(scene.name) {}

void FrameRecorder::record(const impulse2d::Simulation& simulation, long lastStep) {
  const long step = simulation.stepCount();
  if (step == 0) loads_ = hasLoads(simulation);
  if (!isRecorded(step, lastStep, writer_.every())) return;
  states_.push_back(captureFrame(simulation, scene_, settings_));
  steps_.push_back(step);
}

std::vector<std::string> FrameRecorder::finish(const RunCamera& camera, double dt,
                                               const std::vector<StepFigures>& figures) {
  if (states_.empty()) return {};
  FrameRenderer renderer(camera.cameraFor(states_.front().bodies), scene_, settings_);
  renderer.fitForces(states_.front());
  for (std::size_t k = 0; k < states_.size(); ++k) {
    renderer.setCamera(camera.cameraFor(states_[k].bodies));
    writer_.write(steps_[k], renderer.draw(states_[k]));
    states_[k] = FrameState{};  // drawn: its frame keeps what a sheet needs
  }
  writer_.writeContactSheet();
  std::vector<std::string> lines = describeFrames(writer_);
  const std::vector<ViewerPlot> plots =
      writeViewerPlots(writer_.directory(), writer_.prefix(), {{scene_, figures}}, loads_);
  for (const std::string& line :
       writeFrameExtras(options_, writer_, scene_, 1.0 / (dt * writer_.every()),
                        figureTable(figures, writer_.steps()), plots, dt)) {
    lines.push_back(line);
  }
  return lines;
}

}  // namespace i2d
