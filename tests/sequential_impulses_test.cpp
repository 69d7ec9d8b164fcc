// Sequential impulses: accumulated impulses, warm starting, the penetration bias, restitution,
// speculative gaps and the trace — each shown by the failure without it.
#include <catch2/catch.hpp>

#include "impulse2d/solvers/sequential_impulses.h"
#include "impulse2d/world.h"
#include "solver_scenes.h"

using namespace impulse2d;
using namespace solvers;

namespace {

/// The top box's displacement from where it started, after `seconds`.
double topBoxTravel(const Scene& scene, double seconds) {
  auto world = buildWorld(scene);
  runSteps(*world, stepsIn(seconds));
  return (world->bodies().back().position - scene.bodies.back().position).norm();
}

/// A unit box whose bottom face sits `overlap` below the ground's top face, at rest.
Scene overlappingBox(double overlap) {
  Scene scene = groundScene("sequential", 0.6);
  BodyDef box = unitBoxMaterial(0.6);
  box.shape = makeBox(1.0, 1.0);
  box.position = Vec2(0.0, 0.5 - overlap);
  scene.bodies.push_back(box);
  return scene;
}

/// A disk of radius 0.5 whose lowest point is `height` above the ground, moving at `velocity`.
Scene diskAbove(double height, double velocity, double restitution) {
  Scene scene = groundScene("sequential", 0.6);
  scene.world.gravity = Vec2::Zero();
  BodyDef disk = unitBoxMaterial(0.6);
  disk.shape = makeCircle(0.5);
  disk.position = Vec2(0.0, 0.5 + height);
  disk.velocity = Vec2(0.0, velocity);
  disk.restitution = restitution;
  scene.bodies.push_back(disk);
  return scene;
}

/// Every contact of a resting stack of `boxes` unit boxes carries the weight above it, within the
/// relative `tolerance`.
void checkEachContactCarriesWeightAbove(const World& world, int boxes, double tolerance) {
  for (int level = 0; level < boxes; ++level) {
    const double weightAbove = (boxes - level) * kBoxMass * kGravity;
    INFO("level " << level);
    CHECK(contactForce(world, level, level + 1) == Approx(weightAbove).epsilon(tolerance));
  }
}

class CountingObserver : public SolverObserver {
 public:
  void onSolverEvent(const SolverEvent& event, const std::vector<Body>&,
                     const std::vector<Manifold>&) override {
    if (event.phase == SolverEvent::Phase::Velocity) ++velocityEvents;
    if (event.phase == SolverEvent::Phase::Push) ++pushEvents;
    lastSweep = std::max(lastSweep, event.iteration);
  }
  int velocityEvents = 0;
  int pushEvents = 0;
  int lastSweep = -1;
};

}  // namespace

TEST_CASE("10-box stack, warm started: every contact carries the weight above it within 2%",
          "[sequential][stack][force][warm_starting]") {
  constexpr int kBoxes = 10;
  auto world = buildWorld(stackScene("sequential", kBoxes, 0.6));
  runSteps(*world, stepsIn(1.0));
  for (int step = 0; step < stepsIn(1.0); ++step) {
    world->step();
    INFO("step " << step);
    checkEachContactCarriesWeightAbove(*world, kBoxes, 0.02);
  }
}

TEST_CASE("20-box stack stands with the defaults: the top moves < 1 cm from 1 s to 10 s",
          "[sequential][stack][stability]") {
  constexpr int kBoxes = 20;
  const Scene scene = stackScene("sequential", kBoxes, 0.6);
  auto world = buildWorld(scene);
  runSteps(*world, stepsIn(1.0));
  const Vec2 settled = world->bodies().back().position;
  double largestMove = 0.0;
  for (int step = 0; step < stepsIn(9.0); ++step) {
    world->step();
    largestMove = std::max(largestMove, (world->bodies().back().position - settled).norm());
  }
  CHECK(largestMove < 0.01);
  // Each of the 20 contacts may overlap by up to the slop before the bias and the position
  // pass act, so the top may sink at most 20 × slop.
  const double sink = scene.bodies.back().position.y() - world->bodies().back().position.y();
  CHECK(sink >= 0.0);
  CHECK(sink < kBoxes * scene.solverSettings.sequential.targets.allowedPenetration);
}

TEST_CASE("20-box stack without accumulated impulses or warm starting sinks or topples",
          "[sequential][stack][accumulation][warm_starting]") {
  constexpr int kBoxes = 20;
  Scene scene = stackScene("sequential", kBoxes, 0.6);
  const double slopAllowance = kBoxes * scene.solverSettings.sequential.targets.allowedPenetration;
  CHECK(topBoxTravel(scene, 10.0) < slopAllowance);
  SECTION("without accumulation each impulse is clamped alone and cannot be taken back") {
    scene.solverSettings.sequential.impulses = ImpulseAccumulation::ClampedEach;
    CHECK(topBoxTravel(scene, 10.0) > slopAllowance);
  }
  SECTION("without warm starting the weight never reaches the bottom within a step") {
    // The text's sweeps: the conjugate gradient's push would carry the weight further a sweep.
    scene.solverSettings.sequential.impulses = ImpulseAccumulation::Accumulated;
    scene.solverSettings.sequential.conjugateGradient = false;
    CHECK(topBoxTravel(scene, 10.0) > slopAllowance);
  }
}

TEST_CASE("the penetration bias pushes an overlap out to the slop; without it the overlap stays",
          "[sequential][bias]") {
  constexpr double kOverlap = 0.05;
  Scene scene = overlappingBox(kOverlap);
  scene.solverSettings.sequential.positionPass.iterations = 0;
  const double slop = scene.solverSettings.sequential.targets.allowedPenetration;
  SECTION("with the bias") {
    auto world = buildWorld(scene);
    runSteps(*world, stepsIn(2.0));
    CHECK(largestPenetration(*world) < slop + 1e-4);
  }
  SECTION("without the bias") {
    scene.solverSettings.sequential.targets.penetrationBias = false;
    auto world = buildWorld(scene);
    runSteps(*world, stepsIn(2.0));
    CHECK(largestPenetration(*world) > kOverlap - 1e-3);
  }
}

TEST_CASE("restitution comes from the closing speed before the solve, none under the threshold",
          "[sequential][restitution]") {
  const double threshold = SequentialImpulseSettings{}.targets.restitutionThreshold;
  SECTION("a fast ball bounces at e × its closing speed") {
    auto world = buildWorld(diskAbove(0.5, -5.0, 0.5));
    runSteps(*world, stepsIn(1.0));
    CHECK(world->bodies()[1].velocity.y() == Approx(2.5).epsilon(1e-9));
  }
  SECTION("a slow ball stops") {
    auto world = buildWorld(diskAbove(0.5, -0.5 * threshold, 0.5));
    runSteps(*world, stepsIn(2.0));
    CHECK(std::abs(world->bodies()[1].velocity.y()) < 1e-12);
  }
}

TEST_CASE("a gap is speculative: approach is allowed up to gap/dt, then the ball lands exactly",
          "[sequential][speculative]") {
  constexpr double kGap = 0.004;  // within the world's contact margin
  SECTION("slow enough not to close the gap in a step: no impulse") {
    auto world = buildWorld(diskAbove(kGap, -0.5 * kGap / kDt, 0.0));
    world->step();
    REQUIRE(world->manifolds().size() == 1);
    CHECK(world->manifolds()[0].points[0].normalImpulse == 0.0);
  }
  SECTION("fast enough to close it: stopped touching, no bounce, no overlap") {
    auto world = buildWorld(diskAbove(kGap, -3.0 * kGap / kDt, 0.0));
    world->step();
    CHECK(world->bodies()[1].position.y() - 0.5 == Approx(0.0).margin(1e-12));
    CHECK(world->bodies()[1].velocity.y() == Approx(-kGap / kDt).epsilon(1e-9));
  }
}

TEST_CASE("friction is dynamic on a slope steeper than the friction angle, static below it",
          "[sequential][friction]") {
  for (const auto& [angle, expected] :
       {std::pair{0.2, FrictionState::Static}, std::pair{0.6, FrictionState::Dynamic}}) {
    Scene scene = lecture::sceneWith("sequential", kDt);
    scene.bodies.push_back(lecture::ground(0.4, angle));
    scene.bodies.push_back(lecture::boxOnSlope(Vec2(1.0, 1.0), angle, 0.4));
    auto world = buildWorld(scene);
    runSteps(*world, stepsIn(0.5));
    INFO("slope " << angle);
    REQUIRE(world->manifolds().size() == 1);
    for (int i = 0; i < world->manifolds()[0].pointCount; ++i) {
      CHECK(world->manifolds()[0].points[i].friction == expected);
    }
  }
}

TEST_CASE("an observer sees one event per point per sweep, and per point per push",
          "[sequential][trace]") {
  auto world = buildWorld(stackScene("sequential", 3, 0.6));
  CountingObserver observer;
  world->setObserver(&observer);
  world->step();
  const int sweeps = world->solver().lastReport().iterations;
  const int points = contactPointCount(*world);
  CHECK(sweeps > 1);  // from rest the weight needs several
  CHECK(observer.velocityEvents == sweeps * points);
  CHECK(observer.lastSweep == sweeps - 1);
  // The conjugate gradient pushes between sweeps, never after the last; a restart pushes nothing.
  CHECK(observer.pushEvents > 0);
  CHECK(observer.pushEvents % points == 0);
  CHECK(observer.pushEvents <= (sweeps - 1) * points);
}

TEST_CASE(
    "the sweeps stop once converged: a settled stack takes few, with the forces of the full count",
    "[sequential][converged]") {
  constexpr int kBoxes = 10;
  const int allSweeps = SequentialImpulseSettings{}.velocityIterations;
  Scene scene = stackScene("sequential", kBoxes, 0.6);
  auto early = buildWorld(scene);
  scene.solverSettings.sequential.convergedImpulseChange = 0.0;
  auto full = buildWorld(scene);
  early->step();
  full->step();
  CHECK(early->solver().lastReport().iterations == allSweeps);  // from rest the weight needs all
  runSteps(*early, stepsIn(2.0));
  runSteps(*full, stepsIn(2.0));
  INFO("sweeps in a settled step: " << early->solver().lastReport().iterations);
  CHECK(early->solver().lastReport().iterations <= allSweeps / 4);
  for (int level = 0; level < kBoxes; ++level) {
    INFO("level " << level);
    CHECK(contactForce(*early, level, level + 1) ==
          Approx(contactForce(*full, level, level + 1)).epsilon(1e-4));
  }
}

// Plain sweeps pass a stack's weight down a few contacts per sweep: the slowest error of an
// n-box column shrinks by about 1 − c/n² a sweep, so from rest a 20-box stack runs to the cap
// of 40 sweeps for most of its first second. The conjugate gradient's push carries the error
// along the direction the sweeps keep moving it, about 1 − c/n a sweep; it ends at the same
// answer, since it stops on the same test.
TEST_CASE("the conjugate gradient's push settles a 20-box stack in a quarter of the plain sweeps",
          "[sequential][converged][conjugate-gradient]") {
  constexpr int kBoxes = 20;
  Scene scene = stackScene("sequential", kBoxes, 0.6);
  auto pushed = buildWorld(scene);
  scene.solverSettings.sequential.conjugateGradient = false;
  auto plain = buildWorld(scene);
  scene.solverSettings.sequential.convergedImpulseChange = 0.0;
  auto full = buildWorld(scene);
  int pushedSweeps = 0;
  int plainSweeps = 0;
  for (int step = 0; step < stepsIn(1.0); ++step) {
    pushed->step();
    plain->step();
    full->step();
    pushedSweeps += pushed->solver().lastReport().iterations;
    plainSweeps += plain->solver().lastReport().iterations;
  }
  INFO("sweeps in the first second: " << pushedSweeps << " pushed, " << plainSweeps << " plain");
  CHECK(4 * pushedSweeps < plainSweeps);
  runSteps(*pushed, stepsIn(1.0));
  runSteps(*full, stepsIn(1.0));
  for (int level = 0; level < kBoxes; ++level) {
    INFO("level " << level);
    CHECK(contactForce(*pushed, level, level + 1) ==
          Approx(contactForce(*full, level, level + 1)).epsilon(1e-4));
  }
}

// Contact recycling: a resting stack moves micrometres a step, far less than the recycle distance
// (5 mm), so every manifold is kept as found and none is clipped again; the kept points still
// carry the weight above them. A box sliding at over 0.3 m/s moves more than 5 mm a step, so
// its manifold is found anew every step until it has nearly stopped.
TEST_CASE(
    "a resting stack's contacts are kept as found and carry its weight; a sliding box's "
    "are found anew",
    "[sequential][recycling]") {
  constexpr int kBoxes = 10;
  auto world = buildWorld(stackScene("sequential", kBoxes, 0.6));
  runSteps(*world, stepsIn(1.0));
  for (int step = 0; step < stepsIn(0.5); ++step) {
    world->step();
    const StepStatistics& statistics = world->lastStepStatistics();
    CHECK(statistics.reusedManifolds == kBoxes);
    CHECK(statistics.narrowPhasePairs == 0);
    INFO("step " << step);
    checkEachContactCarriesWeightAbove(*world, kBoxes, 1e-4);
  }

  Scene sliding = groundScene("sequential", 0.6);
  BodyDef box = unitBoxMaterial(0.6);
  box.shape = makeBox(1.0, 1.0);
  box.position = Vec2(0.0, 0.5);
  box.velocity = Vec2(3.0, 0.0);
  sliding.bodies.push_back(box);
  auto slide = buildWorld(sliding);
  const double recycleDistance = SequentialImpulseSettings{}.recycling.distance;
  while (slide->bodies()[1].velocity.x() * kDt > recycleDistance) {
    slide->step();
    CHECK(slide->lastStepStatistics().reusedManifolds == 0);
  }
  runSteps(*slide, stepsIn(0.5));
  CHECK(slide->bodies()[1].velocity.norm() < 1e-6);  // at rest
  CHECK(slide->lastStepStatistics().reusedManifolds == 1);

  sliding.solverSettings.sequential.recycling.rule = RecyclingRule::Off;
  auto clipped = buildWorld(sliding);
  runSteps(*clipped, stepsIn(1.0));
  CHECK(clipped->lastStepStatistics().reusedManifolds == 0);
}
