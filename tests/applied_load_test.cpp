// Applied loads (body.h AppliedLoad, scene keys force, force_rate, force_point, torque) and the
// static-to-dynamic transition of lecture 3.6: a box pushed by a force growing at rate k starts
// to slide when k t = μ m g, and a push below μ m g never moves it.
#include <catch2/catch.hpp>

#include <iostream>

#include "impulse2d/box2d/box2d_simulation.h"
#include "impulse2d/scene/scene_file.h"
#include "lecture_scenes.h"

using namespace impulse2d;

namespace {

const std::string kPushedBox = std::string(IMPULSE2D_SOURCE_DIR) + "/demos/scenes/pushed_box.toml";

/// m/s. Faster than this the box slides: the first sliding step gains 0.028 N · dt / m = 4.7e-4
/// m/s (the push at its start exceeds μ m g by k · 147.15 · dt − 4.905 = 0.028 N).
constexpr double kSlidingSpeed = 1e-4;

SceneFile pushedBox(const std::string& solver) {
  SceneFile scene = loadSceneFile(kPushedBox);
  scene.solver = solver;
  return scene;
}

/// The step N at whose start the push first exceeds μ m g: the push at the start of step N is
/// k (N − 1) dt, so N = μ m g / (k dt) + 1, as a real number.
double analyticSlidingStep(const Scene& scene) {
  const BodyDef& box = scene.bodies[1];
  const double mass = computeMass(box.shape, box.density).mass;
  const double mu = mixFriction(box.friction, scene.bodies[0].friction);
  const double limit = mu * mass * -scene.world.gravity.y();
  return limit / (box.load.forceRate.x() * scene.world.dt) + 1.0;
}

/// The step from which the box moves faster than kSlidingSpeed to the end of the 300-step run
/// (0: it does not). Micro-collisions resolve one point at a time, so while the push tips the
/// load from one point to the other a point can slip for a step (up to 1.3e-4 m/s) and stick
/// again: that is not yet sliding.
long firstSlidingStep(Simulation& simulation) {
  long sliding = 0;
  for (long step = 1; step <= 300; ++step) {
    simulation.step();
    if (simulation.bodies()[1].velocity.x() <= kSlidingSpeed) {
      sliding = 0;
    } else if (sliding == 0) {
      sliding = step;
    }
  }
  return sliding;
}

}  // namespace

TEST_CASE("pushed_box.toml reads its ramping push", "[load]") {
  const SceneFile scene = loadSceneFile(kPushedBox);
  REQUIRE(scene.bodies.size() == 2);
  CHECK(scene.bodies[1].load.forceRate == Vec2(2.0, 0.0));
  CHECK(scene.bodies[1].load.force == Vec2::Zero());
  CHECK(scene.bodies[0].load.isZero());
}

TEST_CASE("a ramping push starts the box sliding within one step of F = mu m g", "[load]") {
  const double analytic = analyticSlidingStep(pushedBox("sequential"));
  CHECK(analytic == Approx(148.15).margin(0.01));
  for (const std::string solver : {"micro", "sequential", "reference", "box2d"}) {
    const SceneFile scene = pushedBox(solver);
    const std::unique_ptr<Simulation> simulation = makeSimulation(scene);
    const long sliding = firstSlidingStep(*simulation);
    std::cout << "figure: " << solver << " first sliding step " << sliding << " (analytic "
              << analytic << ")\n";
    if (solver == kBox2dName) continue;  // reported, not asserted: Box2D's skin and slop differ
    INFO(solver);
    CHECK(std::abs(double(sliding) - analytic) <= 1.0);
  }
}

TEST_CASE("a constant push below mu m g moves the box less than 1 mm in 5 s", "[load]") {
  for (const std::string solver : {"micro", "sequential", "reference"}) {
    SceneFile scene = pushedBox(solver);
    scene.bodies[1].load.forceRate.setZero();
    scene.bodies[1].load.force = Vec2(0.8 * 0.5 * 1.0 * lecture::kGravity, 0.0);  // 0.8 μ m g
    const std::unique_ptr<Simulation> simulation = makeSimulation(scene);
    const Vec2 start = simulation->bodies()[1].position;
    for (int step = 0; step < 300; ++step) simulation->step();
    const double moved = (simulation->bodies()[1].position - start).norm();
    std::cout << "figure: " << solver << " moved " << moved << " m under 0.8 mu m g in 5 s\n";
    INFO(solver);
    CHECK(moved < 1e-3);
  }
}

TEST_CASE("a force at a body point also turns the body; torque alone only turns it", "[load]") {
  Scene scene = lecture::sceneWith("sequential", 1.0 / 60.0);
  scene.world.gravity = Vec2::Zero();
  BodyDef box = lecture::boxOnSlope(Vec2(1.0, 1.0), 0.0, 0.5, 5.0);
  box.load.force = Vec2(0.0, 1.0);
  box.load.point = Vec2(0.5, 0.0);  // the right edge: torque r × F = 0.5 N m
  scene.bodies.push_back(box);
  box.name = "spun";
  box.position.x() += 3.0;
  box.load = AppliedLoad{};
  box.load.torque = 0.5;
  scene.bodies.push_back(box);
  auto world = buildWorld(scene);
  world->step();
  const double dt = scene.world.dt;
  const double inertia = 1.0 / 6.0;  // a 1 kg unit square: m (w² + h²) / 12
  const Body& pushed = world->bodies()[0];
  const Body& spun = world->bodies()[1];
  CHECK(pushed.velocity.y() == Approx(1.0 * dt).epsilon(1e-9));
  CHECK(pushed.angularVelocity == Approx(0.5 / inertia * dt).epsilon(1e-9));
  CHECK(spun.velocity.norm() == 0.0);
  CHECK(spun.angularVelocity == Approx(0.5 / inertia * dt).epsilon(1e-9));
}

TEST_CASE("loads in scene files: located errors for bad values", "[load]") {
  const std::string head = "[[body]]\nshape = \"circle\"\nradius = 1\n";
  CHECK_THROWS_WITH(parseScene(head + "force = [1.0]\n", "bad.toml"),
                    Catch::StartsWith("bad.toml:4:"));
  CHECK_THROWS_WITH(parseScene(head + "torque = \"a lot\"\n", "bad.toml"),
                    Catch::StartsWith("bad.toml:4:"));
  CHECK_THROWS_WITH(parseScene(head + "force_rate = [1.0, nan]\n", "bad.toml"),
                    Catch::StartsWith("bad.toml:4:"));
  CHECK_THROWS_WITH(parseScene(head + "type = \"static\"\nforce = [1.0, 0.0]\n", "bad.toml"),
                    Catch::Contains("static body never moves"));
}
