// The world-level switches for hard scenes (settings.h, docs/rigid-bodies.md): substeps split a
// step into equal smaller ones; continuous collision and speculative contacts each stop a fast
// small body at a thin wall.
#include <catch2/catch.hpp>

#include "solver_scenes.h"

using namespace impulse2d;

namespace {

/// A 3-box stack with a ball falling onto it and a box sliding along the ground: contacts
/// that start, rest and slide.
Scene busyScene(const std::string& solver, double dt, int substeps) {
  Scene scene = solvers::stackScene(solver, 3, 0.6);
  scene.world.dt = dt;
  scene.world.substeps = substeps;
  BodyDef ball;
  ball.shape = makeCircle(0.3);
  ball.position = Vec2(0.2, 4.5);
  ball.restitution = 0.4;
  scene.bodies.push_back(ball);
  BodyDef slider = solvers::unitBoxMaterial(0.6);
  slider.shape = makeBox(1.0, 1.0);
  slider.position = Vec2(4.0, 0.5);
  slider.velocity = Vec2(-3.0, 0.0);
  scene.bodies.push_back(slider);
  return scene;
}

constexpr double kWallX = 5.0;               ///< m, centre of the wall
constexpr double kWallHalfThickness = 0.05;  ///< m: a 0.1 m thick wall
constexpr double kBallRadius = 0.05;         ///< m
constexpr double kBallSpeed = 200.0;         ///< m/s: 3.3 m a step at 60 Hz

/// A small fast ball flying at a thin static wall, without gravity, continuous collision off.
Scene bulletScene(const std::string& solver, bool speculative) {
  Scene scene;
  scene.solver = solver;
  scene.world.gravity = Vec2::Zero();
  scene.world.continuous = false;
  scene.world.speculativeContacts = speculative;
  BodyDef wall;
  wall.type = BodyType::Static;
  wall.shape = makeBox(2.0 * kWallHalfThickness, 2.0);
  wall.position = Vec2(kWallX, 0.0);
  scene.bodies.push_back(wall);
  BodyDef ball;
  ball.shape = makeCircle(kBallRadius);
  ball.velocity = Vec2(kBallSpeed, 0.0);
  scene.bodies.push_back(ball);
  return scene;
}

/// m. The ball's x after `steps` steps.
double ballXAfter(const Scene& scene, int steps) {
  auto world = buildWorld(scene);
  solvers::runSteps(*world, steps);
  return world->bodies()[1].position.x();
}

}  // namespace

TEST_CASE("substeps = 4 at dt = 1/15 is bit for bit four steps of dt/4", "[world][substeps]") {
  const double dt = 1.0 / 15.0;
  for (const std::string solver : {"micro", "sequential", "reference"}) {
    auto substepped = buildWorld(busyScene(solver, dt, 4));
    auto small = buildWorld(busyScene(solver, dt / 4.0, 1));
    solvers::runSteps(*substepped, 30);
    solvers::runSteps(*small, 120);
    INFO(solver);
    CHECK(substepped->stepCount() == 30);
    for (size_t i = 0; i < small->bodies().size(); ++i) {
      const Body& a = substepped->bodies()[i];
      const Body& b = small->bodies()[i];
      CHECK(a.position == b.position);
      CHECK(a.angle == b.angle);
      CHECK(a.velocity == b.velocity);
      CHECK(a.angularVelocity == b.angularVelocity);
    }
  }
}

TEST_CASE("a 0.05 m ball at 200 m/s tunnels through a 0.1 m wall at 60 Hz",
          "[world][speculative]") {
  for (const std::string solver : {"micro", "sequential", "reference"}) {
    INFO(solver);
    CHECK(ballXAfter(bulletScene(solver, false), 3) > kWallX + kWallHalfThickness + kBallRadius);
  }
}

TEST_CASE("with speculative contacts the same ball stops at the wall", "[world][speculative]") {
  const double touching = kWallX - kWallHalfThickness - kBallRadius;
  const double margin = WorldSettings{}.contactMargin;
  for (const std::string solver : {"micro", "sequential", "reference"}) {
    auto world = buildWorld(bulletScene(solver, true));
    for (int step = 0; step < 30; ++step) {
      world->step();
      INFO(solver << ", step " << step);
      REQUIRE(world->bodies()[1].position.x() <= touching + margin);
    }
    // Without restitution the ball ends at rest against the wall.
    CHECK(world->bodies()[1].position.x() == Approx(touching).margin(margin));
    CHECK(world->bodies()[1].velocity.x() == Approx(0.0).margin(1e-6));
  }
}

TEST_CASE("at the defaults a 0.1 m ball at 40 m/s stops at a 0.2 m wall at 60 Hz",
          "[world][continuous]") {
  // 0.67 m a step: without continuous collision its centre passes the wall's mid-plane in one.
  constexpr double wallX = 2.0;
  constexpr double halfThickness = 0.1;
  constexpr double radius = 0.1;
  const double touching = wallX - halfThickness - radius;
  const double margin = WorldSettings{}.contactMargin;
  for (const std::string solver : {"micro", "sequential", "soft_step", "reference"}) {
    Scene scene;
    scene.solver = solver;
    scene.world.gravity = Vec2::Zero();
    BodyDef wall;
    wall.type = BodyType::Static;
    wall.shape = makeBox(2.0 * halfThickness, 2.0);
    wall.position = Vec2(wallX, 0.0);
    scene.bodies.push_back(wall);
    BodyDef ball;
    ball.shape = makeCircle(radius);
    ball.velocity = Vec2(40.0, 0.0);
    scene.bodies.push_back(ball);
    auto world = buildWorld(scene);
    for (int step = 0; step < 30; ++step) {
      world->step();
      INFO(solver << ", step " << step);
      REQUIRE(world->bodies()[1].position.x() <= touching + margin);
    }
    // Without restitution the ball ends at rest against the wall.
    CHECK(world->bodies()[1].position.x() == Approx(touching).margin(margin));
    CHECK(world->bodies()[1].velocity.x() == Approx(0.0).margin(1e-6));
  }
}

namespace {

/// Steps in `seconds` of a 5-box stack (exactly touching, at rest) in which a contact point is
/// missing, under `solver` at `dt` with the contact margin `margin`.
int stepsMissingAPoint(const std::string& solver, double dt, double margin, double seconds) {
  Scene scene = solvers::stackScene(solver, 5, 0.5);
  scene.world.dt = dt;
  scene.world.contactMargin = margin;
  auto world = buildWorld(scene);
  int missing = 0;
  while (world->stepCount() * dt < seconds) {
    world->step();
    if (contactPointCount(*world) < 2 * 5) ++missing;
  }
  return missing;
}

}  // namespace

// The margin keeps a resting contact whose last solve left it a hair apart. Micro stops once no
// point needs more than its velocity epsilon ε, so a resting point may be left separating at up
// to ε, a gap of ε dt by the next step's collision. With a margin under ε dt the point is lost, the
// box falls g dt² for a step, lands, and the stack's contacts flicker from then on (at 60 Hz and a
// margin of 1e-6 m the stack topples). Above ε dt every point is kept. The rigid methods leave
// resting points closed, so they keep them at either margin.
TEST_CASE("a resting stack keeps its contacts only with a contact margin above micro's ε dt",
          "[world][margin]") {
  const double epsilon = MicroCollisionSettings{}.velocityEpsilon;
  for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
    INFO("dt " << dt << ", ε dt " << epsilon * dt << " m");
    CHECK(stepsMissingAPoint("micro", dt, 2.0 * epsilon * dt, 3.0) == 0);
    CHECK(stepsMissingAPoint("micro", dt, 0.5 * epsilon * dt, 3.0) > 10);
    CHECK(stepsMissingAPoint("sequential", dt, 0.5 * epsilon * dt, 3.0) == 0);
    CHECK(stepsMissingAPoint("reference", dt, 0.5 * epsilon * dt, 3.0) == 0);
  }
}
