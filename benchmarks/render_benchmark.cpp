// How long one 960×540 frame of a 210-box pyramid (pyramid20) takes to draw with every overlay on
// and write as a PNG, encoding included (target: at most 10 ms median; the renderer before Cairo
// is compared in docs/design/drawing-with-cairo.md). The pyramid stands for one simulated second
// first, so every contact carries its impulses. Then the same frame as the browser sandbox makes
// it: the marks (render/marks.h) and their encoding for the page (web/mark_encoding.h), which
// callgrind counts alone with --toggle-collect='*pageFrame*'.
//
//   render_benchmark [frame.png]    (writes the benchmark frame there, to look at)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <vector>

#include "impulse2d/render/frame.h"
#include "impulse2d/render/marks.h"
#include "impulse2d/scene/scene.h"
#include "mark_encoding.h"

using namespace impulse2d;
using Clock = std::chrono::steady_clock;

namespace {

constexpr int pyramidRows = 20;  // 20 + 19 + ... + 1 = 210 boxes
constexpr int settleSteps = 60;
constexpr int renders = 30;
constexpr int frameWidth = 960;
constexpr int frameHeight = 540;
constexpr double targetMilliseconds = 10.0;

Scene pyramidScene() {
  Scene scene;
  scene.name = "pyramid210";
  scene.solver = "sequential";
  BodyDef ground;
  ground.name = "ground";
  ground.type = BodyType::Static;
  ground.shape = makeBox(60.0, 1.0);
  ground.position = Vec2(0.0, -0.5);
  scene.bodies.push_back(ground);
  addPyramid(scene, pyramidRows, Vec2(1.0, 1.0), Vec2::Zero(), BodyDef{});
  return scene;
}

double milliseconds(Clock::duration duration) {
  return std::chrono::duration<double, std::milli>(duration).count();
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

/// The sandbox's frame of the world: its marks, encoded for the page; returns the path data's
/// length. Kept out of line so callgrind can count exactly this.
[[gnu::noinline]] std::size_t pageFrame(render::FrameRenderer& renderer, const World& world,
                                        const std::string& scene,
                                        const render::RenderSettings& settings) {
  render::MarkList marks([](const std::string& text, double size) {
    return 0.6 * size * double(text.size());  // the page measures text; any width will do here
  });
  {
    render::Drawing drawing(marks);
    renderer.drawOnto(drawing, render::captureFrame(world, scene, settings));
  }
  return sandbox::encodeMarks(marks.marks()).paths.size();
}

}  // namespace

int main(int argc, char** argv) {
  const Scene scene = pyramidScene();
  const std::unique_ptr<World> world = buildWorld(scene);
  for (int i = 0; i < settleSteps; ++i) world->step();
  render::RenderSettings settings;
  render::FrameRenderer renderer(
      render::fitCamera(world->bodies(), ViewDef{}, settings, frameWidth, frameHeight), scene.name,
      settings);
  const std::filesystem::path path = argc > 1 ? argv[1] : "render_benchmark_frame.png";
  render::PictureWriter writer;  // as a run's FrameWriter holds one, reusing its buffers
  std::vector<double> drawTimes;
  std::vector<double> totalTimes;
  std::vector<double> processorTimes;  // immune to other programs sharing the machine
  for (int i = 0; i < renders; ++i) {
    const std::clock_t processorStart = std::clock();
    const Clock::time_point start = Clock::now();
    const render::Frame frame = renderer.draw(*world);
    const Clock::time_point drawn = Clock::now();
    writer.write(path, frame.picture, render::ImageFormat::Png);
    const Clock::time_point written = Clock::now();
    processorTimes.push_back(1000.0 * double(std::clock() - processorStart) / CLOCKS_PER_SEC);
    drawTimes.push_back(milliseconds(drawn - start));
    totalTimes.push_back(milliseconds(written - start));
  }
  std::printf("%zu bodies, %d contact points, %dx%d pixels\n", world->bodies().size(),
              contactPointCount(*world), frameWidth, frameHeight);
  std::printf(
      "recording the drawing calls: median %.2f ms; rasterising, encoding and writing the "
      "rest\n",
      median(drawTimes));
  std::printf(
      "frame drawn and written as PNG: median %.2f ms (%.2f ms of processor time) over %d frames "
      "(target <= %.0f ms)\n",
      median(totalTimes), median(processorTimes), renders, targetMilliseconds);
  std::printf("frame: %s, %ju bytes\n", path.c_str(),
              std::uintmax_t(std::filesystem::file_size(path)));

  std::vector<double> pageTimes;
  std::size_t pathBytes = 0;
  for (int i = 0; i < renders; ++i) {
    const Clock::time_point start = Clock::now();
    pathBytes = pageFrame(renderer, *world, scene.name, settings);
    pageTimes.push_back(milliseconds(Clock::now() - start));
  }
  std::printf(
      "the sandbox's frame: marks and their encoding for the page, median %.2f ms (%zu "
      "bytes of path data)\n",
      median(pageTimes), pathBytes);
  return 0;
}
