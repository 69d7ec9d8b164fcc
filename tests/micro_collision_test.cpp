// The micro-collision resolver's own rules: the lecture's desired velocity change, worst contact
// first, and penetration moved out without adding velocity.
#include <catch2/catch.hpp>

#include <algorithm>
#include <utility>
#include <vector>

#include "impulse2d/solvers/micro_collision.h"
#include "lecture_scenes.h"
#include "solver_scenes.h"

using namespace impulse2d;

namespace {

/// Records every solver event of a step.
struct EventLog : SolverObserver {
  std::vector<SolverEvent> events;
  void onSolverEvent(const SolverEvent& event, const std::vector<Body>&,
                     const std::vector<Manifold>&) override {
    events.push_back(event);
  }
};

/// One step of `scene`: the impulses (Velocity) or moves (Position) the resolver took in it, and
/// the box (body 1) after it.
std::pair<int, Body> firstStep(const Scene& scene, SolverEvent::Phase phase) {
  auto world = buildWorld(scene);
  EventLog log;
  world->setObserver(&log);
  world->step();
  int taken = 0;
  for (const SolverEvent& event : log.events) {
    if (event.phase == phase) taken = std::max(taken, event.iteration + 1);
  }
  return {taken, world->bodies()[1]};
}

/// The first step of a stack from rest: how velocity resolution ended and how fast the fastest
/// box still moves.
struct FirstStepOfStack {
  SolveReport report;
  int points = 0;
  double fastestBox = 0.0;  ///< m/s
};

FirstStepOfStack firstStepOfStack(const Scene& scene) {
  auto world = buildWorld(scene);
  world->step();
  FirstStepOfStack result;
  result.report = world->solver().lastReport();
  for (const Manifold& manifold : world->manifolds()) result.points += manifold.pointCount;
  for (const Body& body : world->bodies()) {
    result.fastestBox = std::max(result.fastestBox, body.velocity.norm());
  }
  return result;
}

}  // namespace

TEST_CASE("the desired velocity change is −vs − c·(vs − vacc)", "[micro][acceleration]") {
  const double dt = 1.0 / 60.0;
  const double restitution = 0.5;
  Scene scene = lecture::sceneWith("micro", dt);
  scene.solverSettings.micro.lowerRestitutionAtLowSpeed = false;
  scene.bodies.push_back(lecture::ground(0.0));
  BodyDef ball = lecture::diskOnSlope(0.25, 0.0, 0.0, -0.001);  // 1 mm into the ground
  ball.restitution = restitution;
  ball.velocity = Vec2(0.0, -2.0);
  scene.bodies.push_back(ball);

  for (bool removeAcceleration : {true, false}) {
    scene.solverSettings.micro.removeAccelerationVelocity = removeAcceleration;
    auto world = buildWorld(scene);
    EventLog log;
    world->setObserver(&log);
    world->step();
    REQUIRE(!log.events.empty());
    const double vs = -2.0 - lecture::kGravity * dt;  // separating velocity after gravity
    const double vacc = removeAcceleration ? -lecture::kGravity * dt : 0.0;
    CHECK(log.events[0].desiredChange == Approx(-vs - restitution * (vs - vacc)).epsilon(1e-12));
    CHECK(world->bodies()[1].velocity.y() == Approx(-restitution * (vs - vacc)).epsilon(1e-9));
  }
}

TEST_CASE("velocity resolution takes the worst contact first", "[micro][worst-first]") {
  Scene scene = lecture::sceneWith("micro", 1.0 / 60.0);
  scene.bodies.push_back(lecture::ground(0.0));
  BodyDef slow = lecture::diskOnSlope(0.25, 0.0, 0.0, -0.001);
  slow.position.x() = -3.0;
  slow.velocity = Vec2(0.0, -0.5);
  BodyDef fast = slow;
  fast.position.x() = 3.0;
  fast.velocity = Vec2(0.0, -3.0);
  scene.bodies.push_back(slow);
  scene.bodies.push_back(fast);
  auto world = buildWorld(scene);
  EventLog log;
  world->setObserver(&log);
  world->step();
  std::vector<double> velocityChanges;
  for (const SolverEvent& event : log.events) {
    if (event.phase == SolverEvent::Phase::Velocity) velocityChanges.push_back(event.desiredChange);
  }
  REQUIRE(velocityChanges.size() == 2);
  CHECK(world->manifolds()[log.events[0].manifold].bodyB == 2);  // the fast ball first
  CHECK(velocityChanges[0] > velocityChanges[1]);
}

TEST_CASE("penetration resolution moves bodies apart without changing velocity",
          "[micro][penetration]") {
  Scene scene = lecture::sceneWith("micro", 1.0 / 60.0);
  scene.world.gravity = Vec2::Zero();
  scene.bodies.push_back(lecture::ground(0.5));
  scene.bodies.push_back(lecture::boxOnSlope(Vec2(1.0, 1.0), 0.0, 0.5, -0.05));  // 5 cm deep
  auto world = buildWorld(scene);
  world->step();
  const Body& box = world->bodies()[1];
  CHECK(box.velocity.norm() < 1e-12);
  CHECK(box.angularVelocity == Approx(0.0).margin(1e-12));
  // Flat on the ground: both corners equally deep, so the moves cancel in angle and lift it out.
  CHECK(box.position.y() - 0.5 == Approx(0.0).margin(scene.solverSettings.micro.positionEpsilon));
  // Each corner is left within positionEpsilon, so the 1 m wide box tilts by at most 2·ε / 1 m.
  CHECK(std::abs(box.angle) <= 2.0 * scene.solverSettings.micro.positionEpsilon / 1.0);
}

TEST_CASE("pair moves lift a box sunk flat into the ground out level, in one move",
          "[micro][penetration][pair-moves]") {
  // Both corners 5 cm deep. Moved together, one move of the box takes both out: the position
  // impulses x = K⁻¹d are equal by symmetry, so their torques cancel. One corner at a time, each
  // move also turns the box (Millington's angular share), which the other corner's moves must undo.
  Scene scene = lecture::sceneWith("micro", 1.0 / 60.0);
  scene.world.gravity = Vec2::Zero();
  scene.bodies.push_back(lecture::ground(0.5));
  scene.bodies.push_back(lecture::boxOnSlope(Vec2(1.0, 1.0), 0.0, 0.5, -0.05));
  const auto [blockMovesTaken, lifted] = firstStep(scene, SolverEvent::Phase::Position);
  CHECK(blockMovesTaken == 1);
  CHECK(lifted.position.y() == Approx(0.5).margin(1e-12));
  CHECK(lifted.angle == Approx(0.0).margin(1e-12));
  scene.solverSettings.micro.blockMoves = false;
  const auto [singleMovesTaken, turned] = firstStep(scene, SolverEvent::Phase::Position);
  WARN("figure: box sunk 5 cm flat: one corner at a time, "
       << singleMovesTaken << " moves, left at angle " << turned.angle << " rad");
  CHECK(singleMovesTaken > 2);
  CHECK(std::abs(turned.angle) > 1e-9);
}

TEST_CASE("a pair impulse stops a box on a slope that holds it, in one micro-collision",
          "[micro][friction][pair-impulses]") {
  // A unit box placed at rest on a 20° slope with μ 0.5 > tan 20°. After gravity's update both
  // corners close and the face slips; the pair's contact matrix turns the three wanted changes
  // (both normals, the one slip) into impulses that stop the box, within the friction cone. One
  // corner at a time, each impulse turns the box and the other corner needs more.
  const double angle = 20.0 * kPi / 180.0;
  Scene scene = lecture::sceneWith("micro", 1.0 / 60.0);
  scene.bodies.push_back(lecture::ground(0.5, angle));
  scene.bodies.push_back(lecture::boxOnSlope(Vec2(1.0, 1.0), angle, 0.5));
  const auto [pairImpulsesTaken, stopped] = firstStep(scene, SolverEvent::Phase::Velocity);
  CHECK(pairImpulsesTaken == 1);
  CHECK(stopped.velocity.norm() < 1e-12);
  CHECK(std::abs(stopped.angularVelocity) < 1e-12);
  scene.solverSettings.micro.impulses = MicroCollisionImpulses::PointTotals;
  const auto [singleImpulsesTaken, rocked] = firstStep(scene, SolverEvent::Phase::Velocity);
  WARN("figure: box at rest on 20°, one corner at a time: "
       << singleImpulsesTaken << " impulses in the first step, leaving " << rocked.velocity.norm()
       << " m/s");
  CHECK(singleImpulsesTaken > 2);
  CHECK(rocked.velocity.norm() > stopped.velocity.norm());
}

TEST_CASE("past the cap while progressing: a 20-box stack from rest is held in its first step",
          "[micro][progress]") {
  // From rest the weight of 20 boxes passes down one contact at a time, and the desired velocity
  // changes still waiting fall steadily until all are resolved: about 340 impulses per point,
  // past the cap of 200. Resolved, every contact closes at most velocityEpsilon, so a box k
  // levels up sinks at most k·ε: no box faster than 20·ε. Stopped at the cap, the stack still
  // falls onto itself faster than that.
  Scene scene = solvers::stackScene("micro", 20, 0.6);
  const MicroCollisionSettings& settings = scene.solverSettings.micro;
  const double heldSpeed = 20 * settings.velocityEpsilon;
  const FirstStepOfStack passing = firstStepOfStack(scene);
  WARN("figure: 20-box stack, first step from rest: "
       << double(passing.report.iterations) / passing.points << " impulses per point, fastest box "
       << passing.fastestBox << " m/s");
  CHECK(passing.report.converged);
  CHECK(passing.report.iterations > settings.velocityIterationsPerContact * passing.points);
  CHECK(passing.fastestBox <= heldSpeed);

  scene.solverSettings.micro.passCapWhileProgressing = false;
  const FirstStepOfStack capped = firstStepOfStack(scene);
  WARN("figure: the same at the cap: fastest box " << capped.fastestBox << " m/s");
  CHECK_FALSE(capped.report.converged);
  CHECK(capped.report.iterations == settings.velocityIterationsPerContact * capped.points);
  CHECK(capped.fastestBox > heldSpeed);
}

TEST_CASE("past the cap only while progressing: no progress, no impulse past the cap",
          "[micro][progress]") {
  // Asked for more progress than Gauss–Seidel makes (the waiting total to vanish within
  // progressRounds rounds), the same step stops at the cap exactly as without the switch.
  Scene scene = solvers::stackScene("micro", 20, 0.6);
  scene.solverSettings.micro.minimumProgress = 1.0;
  const FirstStepOfStack stalled = firstStepOfStack(scene);
  CHECK_FALSE(stalled.report.converged);
  CHECK(stalled.report.iterations ==
        scene.solverSettings.micro.velocityIterationsPerContact * stalled.points);
}

namespace {

/// J. The kinetic energy of the two bodies' motion relative to their centre of mass.
double internalEnergy(const World& world) {
  double mass = 0.0;
  double energy = 0.0;
  Vec2 momentum = Vec2::Zero();
  for (const Body& body : world.bodies()) {
    mass += body.mass;
    momentum += body.mass * body.velocity;
    energy += 0.5 * body.mass * body.velocity.squaredNorm() +
              0.5 * body.inertia * body.angularVelocity * body.angularVelocity;
  }
  return energy - 0.5 * momentum.squaredNorm() / mass;
}

}  // namespace

// A face striking a face with a bounce (e 1) and friction (μ 1): a spinning hexagon meets a
// spinning triangle face to face, two points (a case a probe of 4,000 random impacts found). Once
// the pair has bounced, both points separate at their bounce, and the slip left at one point is
// stopped by friction alone: a bounce is never taken back, and a point that separates faster than
// its bounce asks nothing along the normal. Stopping the slip while holding that point's normal
// velocity instead pushed it, and the two points, each stopping the slip the other's impulse left,
// pushed each other apart for the whole step: +67 % of the impact's energy. The reference loses
// 26.6 %; micro must not keep more than 2 % of the energy above it (measured 0.9 % below).
TEST_CASE("micro: friction after a bounce does not push a face's two points apart",
          "[micro][restitution][friction]") {
  const auto hexagon = [](double radius) {
    std::vector<Vec2> vertices;
    for (int i = 0; i < 6; ++i) {
      const double at = 2.0 * kPi * i / 6.0;
      vertices.emplace_back(radius * std::cos(at), radius * std::sin(at));
    }
    return makePolygon(vertices).shape;
  };
  const auto energyAfter = [&](const std::string& solver, double& before) {
    Scene scene = lecture::sceneWith(solver, 1.0 / 60.0);
    scene.world.gravity = Vec2::Zero();
    BodyDef a;
    a.shape = hexagon(0.35052007114536826);
    a.position = Vec2(-0.39069206817212843, -0.72982047385780435);
    a.angle = 4.2590005991130466;
    a.velocity = Vec2(1.7273201263840721, 2.8760234527331168);
    a.angularVelocity = -0.55458511777735175;
    a.restitution = 1.0;
    a.friction = 1.0;
    BodyDef b = a;
    b.shape = makePolygon({Vec2(0.42626262458128111, 0.16001336925988693),
                           Vec2(-0.58568796625308961, 0.021511399631585014),
                           Vec2(0.15942534167180838, -0.18152476889147198)})
                  .shape;
    b.density = 4.5008759980735196;
    b.position = Vec2(0.098418380021199681, 0.21082121161961487);
    b.angle = 6.2774570965615855;
    b.velocity = Vec2(-0.074023237840026512, -0.21646577142698897);
    b.angularVelocity = 1.903670478178273;
    scene.bodies = {a, b};
    auto world = buildWorld(scene);
    before = internalEnergy(*world);
    while (world->stepCount() < 40) world->step();  // they meet in step 11 and part
    return internalEnergy(*world);
  };
  double before = 0.0;
  const double micro = energyAfter("micro", before);
  const double exact = energyAfter("reference", before);
  INFO("energy " << before << " J before, after: micro " << micro << ", reference " << exact);
  CHECK(exact < before);
  CHECK(micro < exact + 0.02 * before);
}
