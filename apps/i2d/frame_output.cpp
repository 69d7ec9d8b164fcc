// Frames, sheets and videos of the i2d commands.
#include "frame_output.h"

#include "failures.h"
#include "impulse2d/render/animation.h"
#include "impulse2d/render/video.h"

namespace i2d {

using namespace impulse2d::render;

RenderSettings renderSettings(const FrameOptions& options) {
  RenderSettings settings;
  settings.overlays = options.overlays;
  return settings;
}

Camera sceneCamera(const impulse2d::SceneFile& scene, const RenderSettings& settings) {
  return fitCamera(impulse2d::buildBodies(scene), scene.view, settings);
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
                                          const FigureTable& figures) {
  std::vector<std::string> lines;
  lines.push_back("viewer       " + writeViewer(writer, scene, figures, framesPerSecond).string());
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
    : renderer_(sceneCamera(scene, renderSettings(options)), scene.name, renderSettings(options)),
      writer_(*options.directory, scene.name, every, "", renderSettings(options)),
      options_(options),
      scene_(scene.name) {}

void FrameRecorder::record(const impulse2d::Simulation& simulation, long lastStep) {
  const long step = simulation.stepCount();
  if (isRecorded(step, lastStep, writer_.every())) writer_.write(step, renderer_.draw(simulation));
}

std::vector<std::string> FrameRecorder::finish(double dt, const std::vector<StepFigures>& figures) {
  writer_.writeContactSheet();
  std::vector<std::string> lines = describeFrames(writer_);
  for (const std::string& line :
       writeFrameExtras(options_, writer_, scene_, 1.0 / (dt * writer_.every()),
                        figureTable(figures, writer_.steps()))) {
    lines.push_back(line);
  }
  return lines;
}

}  // namespace i2d
