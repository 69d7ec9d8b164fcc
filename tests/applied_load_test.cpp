// Applied loads (body.h AppliedLoad, scene keys force, force_rate, force_point, torque) and the
// static-to-dynamic transition of lecture 3.6: a box pushed by a force growing at rate k starts
// to slide when k t = μ m g, and a push below μ m g never moves it.
#include <catch2/catch.hpp>

#include <iostream>

#include "exact_motion.h"
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
  REQUIRE(analytic == Approx(148.15).margin(0.01));
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

namespace {

/// A tall box (w × h, density 1) standing on the ground of friction μ, pushed sideways by a
/// constant force F at height `height` above the ground on its left face.
Scene pushedTallBox(const std::string& solver, double dt, const Vec2& size, double friction,
                    double force, double height) {
  Scene scene = lecture::sceneWith(solver, dt);
  scene.bodies.push_back(lecture::ground(friction));
  BodyDef box = lecture::boxOnSlope(size, 0.0, friction);
  box.load.force = Vec2(force, 0.0);
  box.load.point = Vec2(-0.5 * size.x(), height - 0.5 * size.y());
  scene.bodies.push_back(box);
  return scene;
}

/// rad after `seconds` from rest: the box turning clockwise about its front bottom corner, which
/// stays put, under the push (its point turning with the box) and its weight.
double tippedAngle(const Vec2& size, double force, double height, double seconds) {
  const double mass = size.x() * size.y();
  const double aboutCorner = mass * (size.squaredNorm() / 12.0 + size.squaredNorm() / 4.0);
  const auto acceleration = [&](double angle, double) {
    const Mat2 turn = rotation(angle);
    const Vec2 pushedPoint = turn * Vec2(-size.x(), height);  // from the corner
    const Vec2 centre = turn * Vec2(-0.5 * size.x(), 0.5 * size.y());
    return (-pushedPoint.y() * force - centre.x() * mass * lecture::kGravity) / aboutCorner;
  };
  return exact::turnAfter({0.0, 0.0}, seconds, 1e-4, acceleration).angle;
}

}  // namespace

// A push at height H on a box of width w tips it about its front corner once F H > m g w / 2, and
// slides it once F > μ m g: whichever threshold is lower decides. Pushed high, a 0.5 × 2 box tips
// at a fifth of the force that would slide it; pushed 0.2 m up, it slides at half the force that
// would tip it. Below both it stands. Semi-implicit Euler lags a motion of constant acceleration
// by half a step's velocity, so the angle is held to the exact turn within its spin times dt
// (bounded here by the angle's rate over the whole run, 2 θ / t) and the slide to a dt² n (n + 1)
// / 2, the discrete answer, within micro's velocity epsilon for the whole run.
TEST_CASE("a box pushed high tips once F h > m g w / 2, pushed low slides once F > μ m g",
          "[load][tipping][friction]") {
  const Vec2 size(0.5, 2.0);
  const double friction = 0.6;
  const double seconds = 0.2;
  const double weight = size.x() * size.y() * lecture::kGravity;
  for (const std::string solver : {"micro", "sequential", "reference"}) {
    for (const double height : {2.0, 1.5, 0.2}) {
      const double tipping = weight * 0.5 * size.x() / height;
      const double sliding = friction * weight;
      for (const double share : {0.9, 1.1, 1.5}) {  // of the lower threshold
        for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
          const double force = share * std::min(tipping, sliding);
          auto world = buildWorld(pushedTallBox(solver, dt, size, friction, force, height));
          const int steps = int(std::lround(seconds / dt));
          for (int step = 0; step < steps; ++step) world->step();
          const Body& box = world->bodies()[1];
          const Vec2 corner =
              box.position + rotation(box.angle) * (0.5 * Vec2(size.x(), -size.y()));
          INFO(solver << ", pushed at " << height << " m with " << share << " of "
                      << (tipping < sliding ? "tipping" : "sliding") << " (" << force << " N), dt "
                      << dt << ": angle " << box.angle << ", x " << box.position.x()
                      << ", front corner at x " << corner.x());
          if (share < 1.0) {  // stands
            CHECK(std::abs(box.angle) < 1e-6);
            CHECK(std::abs(box.position.x()) < 1e-6);
          } else if (tipping < sliding) {  // tips about its front corner, which does not slip
            const double exact = tippedAngle(size, force, height, seconds);
            CHECK(std::abs(box.angle - exact) < 2.0 * std::abs(exact) / seconds * dt);
            CHECK(exact < -1e-3);
            // Its velocity is stopped every step, but a step's turn about the centre still moves
            // it by about ω² r dt² (measured up to 4.8e-6 m in all): within micro's position
            // epsilon.
            CHECK(std::abs(corner.x() - 0.5 * size.x()) < MicroCollisionSettings{}.positionEpsilon);
          } else {  // slides without turning
            const double acceleration = (force - sliding) / (size.x() * size.y());
            const double discrete = acceleration * dt * dt * steps * (steps + 1) / 2.0;
            CHECK(std::abs(box.position.x() - discrete) <
                  MicroCollisionSettings{}.velocityEpsilon * seconds);
            CHECK(std::abs(box.angle) < 1e-6);
          }
        }
      }
    }
  }
}
