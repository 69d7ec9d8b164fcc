// Islands and sleeping (docs/sleeping.md): bodies at rest stop costing, static contacts never
// wake them, an awake body touching an island wakes all of it, and the switch turns it off.
#include <catch2/catch.hpp>

#include "solver_scenes.h"

using namespace impulse2d;
using solvers::kDt;

namespace {

/// `count` unit boxes stacked on the ground (body 0) with sleeping switched on.
Scene sleepyStack(const std::string& solver, int count) {
  Scene scene = solvers::stackScene(solver, count, 0.6);
  scene.world.sleep = Sleep::KeepSpeedingUpAwake;
  return scene;
}

bool allAsleep(const World& world) {
  for (const Body& body : world.bodies()) {
    if (!body.isStatic() && !body.asleep) return false;
  }
  return true;
}

/// Steps until every dynamic body sleeps; returns the steps taken, or −1 after `limit`.
int stepsUntilAsleep(World& world, int limit) {
  for (int step = 1; step <= limit; ++step) {
    world.step();
    if (allAsleep(world)) return step;
  }
  return -1;
}

}  // namespace

TEST_CASE("a resting box falls asleep once it has rested timeToSleep, not before",
          "[sleeping][island]") {
  for (const std::string solver : {"micro", "sequential", "reference"}) {
    auto world = buildWorld(sleepyStack(solver, 1));
    const double timeToSleep = world->settings().timeToSleep;
    // It starts exactly touching, so it rests from the first step; settling may add 0.5 s.
    const int steps = stepsUntilAsleep(*world, solvers::stepsIn(timeToSleep + 0.5));
    INFO(solver << ": asleep after " << steps << " steps");
    CHECK(steps >= solvers::stepsIn(timeToSleep));
    REQUIRE(steps > 0);
    CHECK(world->bodies()[1].velocity == Vec2::Zero());
    CHECK(world->bodies()[1].angularVelocity == 0.0);
  }
}

TEST_CASE("the ground contact never wakes a sleeping box, and its narrow phase is skipped",
          "[sleeping][static]") {
  auto world = buildWorld(sleepyStack("sequential", 1));
  REQUIRE(stepsUntilAsleep(*world, solvers::stepsIn(2.0)) > 0);
  const Vec2 restingPosition = world->bodies()[1].position;
  for (int step = 0; step < solvers::stepsIn(5.0); ++step) {
    world->step();
    REQUIRE(world->bodies()[1].asleep);
  }
  CHECK(world->bodies()[1].position == restingPosition);
  const StepStatistics& statistics = world->lastStepStatistics();
  CHECK(statistics.narrowPhasePairs == 0);
  CHECK(statistics.awakeBodies == 0);
  CHECK(statistics.solvedManifolds == 0);
  CHECK(statistics.keptManifolds == 1);
  // The kept ground contact still carries the box's weight, m g dt, from its last awake step.
  CHECK(solvers::contactForce(*world, 0, 1) ==
        Approx(solvers::kBoxMass * solvers::kGravity).epsilon(0.01));
}

TEST_CASE("a sleeping pile runs no narrow phase for its sleeping pairs", "[sleeping][island]") {
  Scene scene = solvers::pyramidScene("sequential", 5, 0.6);
  scene.world.sleep = Sleep::KeepSpeedingUpAwake;
  auto world = buildWorld(scene);
  REQUIRE(stepsUntilAsleep(*world, solvers::stepsIn(3.0)) > 0);
  world->step();
  const StepStatistics& statistics = world->lastStepStatistics();
  CHECK(statistics.narrowPhasePairs == 0);
  CHECK(statistics.keptManifolds == int(world->manifolds().size()));
  CHECK(statistics.solvedManifolds == 0);
}

TEST_CASE("a box dropped onto a sleeping stack wakes its whole island, not another one",
          "[sleeping][island]") {
  Scene scene = sleepyStack("sequential", 3);  // bodies 1..3 at x = 0
  addStack(scene, 1, Vec2(1.0, 1.0), Vec2(5.0, 0.0), 0.0, solvers::unitBoxMaterial(0.6));
  auto world = buildWorld(scene);
  REQUIRE(stepsUntilAsleep(*world, solvers::stepsIn(3.0)) > 0);
  Body dropped = world->bodies()[3];
  dropped.position.y() += 1.5;  // half a metre above the top box
  dropped.asleep = false;
  dropped.sleepTime = 0.0;
  const int droppedIndex = world->addBody(dropped);
  bool touched = false;
  for (int step = 0; step < solvers::stepsIn(1.0) && !touched; ++step) {
    world->step();
    touched = solvers::contactForce(*world, 3, droppedIndex) > 0.0;
  }
  REQUIRE(touched);
  for (int box = 1; box <= 3; ++box) CHECK_FALSE(world->bodies()[box].asleep);
  CHECK(world->bodies()[4].asleep);  // the lone box at x = 5: its own island, ground between
}

TEST_CASE("a force, an impulse or a velocity given to a sleeping box wakes it",
          "[sleeping][wake]") {
  auto world = buildWorld(sleepyStack("sequential", 1));
  REQUIRE(stepsUntilAsleep(*world, solvers::stepsIn(2.0)) > 0);
  Body& box = world->bodies()[1];
  box.applyForce(Vec2(0.0, 20.0), box.position);
  CHECK_FALSE(box.asleep);
  REQUIRE(stepsUntilAsleep(*world, solvers::stepsIn(2.0)) > 0);
  box.applyImpulse(Vec2(1.0, 0.0), box.position);
  CHECK_FALSE(box.asleep);
  REQUIRE(stepsUntilAsleep(*world, solvers::stepsIn(3.0)) > 0);
  const double x = box.position.x();
  box.velocity = Vec2(1.0, 0.0);  // set by hand: the world notices at the next step
  world->step();
  CHECK_FALSE(box.asleep);
  CHECK(box.position.x() > x);
}

TEST_CASE("with sleep off nothing ever sleeps", "[sleeping][switch]") {
  Scene scene = solvers::pyramidScene("sequential", 5, 0.6);
  REQUIRE(scene.world.sleep == Sleep::Off);  // the default: tests see the solver, not the sleep
  auto world = buildWorld(scene);
  for (int step = 0; step < solvers::stepsIn(5.0); ++step) {
    world->step();
    REQUIRE(world->lastStepStatistics().awakeBodies == 15);
  }
  CHECK(world->lastStepStatistics().keptManifolds == 0);
}

namespace {

/// m. How far a disc (r 0.5 m, μ 1) placed on a ground tilted by `degrees` rolls in `seconds`,
/// with the given sleep settings.
double rolledOnGentleSlope(const std::string& solver, double degrees, Sleep sleep, double seconds) {
  Scene scene = lecture::sceneWith(solver, kDt);
  const double angle = degrees * std::acos(-1.0) / 180.0;
  scene.bodies.push_back(lecture::ground(1.0, angle));
  scene.bodies.push_back(lecture::diskOnSlope(0.5, angle, 1.0));
  scene.world.sleep = sleep;
  auto world = buildWorld(scene);
  const Vec2 start = world->bodies()[1].position;
  while (world->stepCount() * kDt < seconds) world->step();
  return (world->bodies()[1].position - start).norm();
}

}  // namespace

// A disc on a slope of 0.1° rolls at a = (2/3) g sin θ = 0.011 m/s², so it is still slower than
// the 0.01 m/s threshold when it has rested timeToSleep (0.006 m/s at 0.5 s). Box2D's rule puts it
// to sleep then, and since static bodies wake nothing it never moves again. Counting a body whose
// speed grew by a tenth of the threshold since its rest began as not resting keeps it awake until
// it passes the threshold, and it rolls as it does with sleeping off; a pile at rest does not
// speed up and still sleeps after timeToSleep.
TEST_CASE("a disc starting to roll down a gentle slope is not put to sleep while it speeds up",
          "[sleeping][speeding-up]") {
  for (const std::string solver : {"micro", "sequential", "reference", "soft_step"}) {
    const double awake = rolledOnGentleSlope(solver, 0.1, Sleep::Off, 6.0);
    const double kept = rolledOnGentleSlope(solver, 0.1, Sleep::KeepSpeedingUpAwake, 6.0);
    const double frozen = rolledOnGentleSlope(solver, 0.1, Sleep::Box2d, 6.0);
    INFO(solver << ": rolled " << awake << " m awake, " << kept << " m with sleeping on, " << frozen
                << " m under Box2D's rule");
    CHECK(awake > 0.15);  // (1/3) g sin θ t² = 0.205 m
    CHECK(kept == Approx(awake).epsilon(1e-9));
    CHECK(frozen < 0.01 * awake);
  }
  for (const std::string solver : {"micro", "sequential", "reference"}) {
    auto world = buildWorld(sleepyStack(solver, 10));
    INFO(solver << ": a 10-box stack");
    // It rests from its first steps, so it sleeps within timeToSleep and its settling: twice.
    CHECK(stepsUntilAsleep(*world, solvers::stepsIn(2.0 * WorldSettings{}.timeToSleep)) > 0);
  }
}
