// How long one 800×600 frame of a 210-box pyramid takes to draw with every overlay on (target:
// under 5 ms), and how long writing it as a PNG takes. The pyramid stands for one simulated
// second first, so every contact carries its impulses.
//
//   render_benchmark [frame.png]    (writes the benchmark frame there, to look at)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <vector>

#include "impulse2d/render/frame.h"
#include "impulse2d/render/png.h"
#include "impulse2d/scene/scene.h"

using namespace impulse2d;
using Clock = std::chrono::steady_clock;

namespace {

constexpr int pyramidRows = 20;  // 20 + 19 + ... + 1 = 210 boxes
constexpr int settleSteps = 60;
constexpr int renders = 50;

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

}  // namespace

int main(int argc, char** argv) {
  const Scene scene = pyramidScene();
  const std::unique_ptr<World> world = buildWorld(scene);
  for (int i = 0; i < settleSteps; ++i) world->step();
  render::RenderSettings settings;
  render::FrameRenderer renderer(render::fitCamera(world->bodies(), ViewDef{}, settings),
                                 scene.name, settings);
  std::vector<double> wallTimes;
  std::vector<double> processorTimes;  // immune to other programs sharing the machine
  for (int i = 0; i < renders; ++i) {
    const Clock::time_point start = Clock::now();
    const std::clock_t processorStart = std::clock();
    renderer.draw(*world);
    processorTimes.push_back(1000.0 * double(std::clock() - processorStart) / CLOCKS_PER_SEC);
    wallTimes.push_back(milliseconds(Clock::now() - start));
  }
  std::printf("%zu bodies, %d contact points, %dx%d pixels\n", world->bodies().size(),
              contactPointCount(*world), renderer.camera().width, renderer.camera().height);
  std::printf(
      "render: median %.2f ms per frame (%.2f ms of processor time) over %d frames "
      "(target < 5 ms)\n",
      median(wallTimes), median(processorTimes), renders);
  const std::filesystem::path path = argc > 1 ? argv[1] : "render_benchmark_frame.png";
  const Clock::time_point start = Clock::now();
  render::writePng(path, renderer.canvas());
  std::printf("write PNG: %.1f ms (%s)\n", milliseconds(Clock::now() - start), path.c_str());
  return 0;
}
