// A traced step tells each event in the lecture's words (render/trace.h): the closing speed it
// states before an impulse is the one the contact closes with, this step's gravity included.
#include <catch2/catch.hpp>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "impulse2d/render/frame.h"
#include "impulse2d/render/trace.h"
#include "impulse2d/scene/scene.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/world.h"
#include "render_fixtures.h"

using namespace impulse2d;
using namespace impulse2d::render;

namespace {

/// A ball of restitution 0.5 dropped 0.2 m onto static ground, at 60 Hz.
const std::string kDrop = R"([world]
gravity = [0.0, -9.81]
dt = 0.0166666667
solver = "micro"

[[body]]
name = "ground"
type = "static"
shape = "box"
size = [4.0, 1.0]
position = [0.0, -0.5]

[[body]]
name = "ball"
shape = "circle"
radius = 0.5
position = [0.0, 0.7]
restitution = 0.5
)";

/// Counts the solver's events.
struct EventCounter : SolverObserver {
  void onSolverEvent(const SolverEvent&, const std::vector<Body>&,
                     const std::vector<Manifold>&) override {
    ++events;
  }
  int events = 0;
};

/// The first step whose solve has an event, and the ball's speed at the end of the step before.
long firstStepWithEvent(const Scene& scene, double& speedBefore) {
  std::unique_ptr<World> world = buildWorld(scene);
  EventCounter counter;
  world->setObserver(&counter);
  while (counter.events == 0 && world->stepCount() < 60) {
    speedBefore = -world->bodies().back().velocity.y();
    world->step();
  }
  return world->stepCount();
}

}  // namespace

TEST_CASE("a traced bounce states the closing speed the contact closes with", "[trace]") {
  SceneFile scene = parseScene(kDrop, "drop.toml");
  const double g = 9.81;
  for (const std::string solver : {"micro", "sequential", "reference"}) {
    INFO(solver);
    scene.solver = solver;
    double speedBefore = 0.0;
    const long step = firstStepWithEvent(scene, speedBefore);
    REQUIRE(step < 60);
    std::unique_ptr<World> world = buildWorld(scene);
    RenderSettings settings;
    FrameRenderer renderer(fitCamera(world->bodies(), ViewDef{}, settings), "drop", settings);
    DrawingLog log;
    renderer.setLog(&log);
    traceStep(*world, step, renderer, test::scratchDirectory("trace_story_" + solver));
    double closing = -1.0;
    for (const DrawnShape& shape : log) {
      double after = 0.0;
      if (shape.kind == DrawnShape::Kind::Text &&
          std::sscanf(shape.text.c_str(), "closing speed %lf → %lf m/s", &closing, &after) == 2) {
        break;
      }
    }
    // The speed at the end of the last step plus this step's g·dt (0.164 m/s), to the last digit
    // the line prints (mm/s).
    CHECK(closing == Approx(speedBefore + g * scene.world.dt).margin(1e-3));
  }
}
