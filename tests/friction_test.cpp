// Friction as impulses (lecture 3.6): the 2×2 contact matrix, static friction that holds a box on
// a gentle incline, dynamic friction that lets it slide at g(sin θ − μ cos θ), and the coupling
// of spin and slip that makes a disk roll at (2/3) g sin θ.
#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>
#include <string>
#include <tuple>

#include "impulse2d/solvers/contact_math.h"
#include "impulse2d/solvers/micro_collision.h"
#include "lecture_scenes.h"

using namespace impulse2d;

namespace {

constexpr double kDt = 1.0 / 60.0;

double degrees(double d) {
  return d * kPi / 180.0;
}

/// The text's unit-impulse probe: apply a unit impulse along `direction` (+ to B, − to A) on
/// copies of the bodies and measure how the contact velocity (normal, tangent) changes.
Vec2 probe(Body a, Body b, const Vec2& point, const Vec2& normal, const Vec2& direction) {
  const Vec2 before = contactVelocity(a, b, point, normal);
  a.applyImpulse(-direction, point);
  b.applyImpulse(direction, point);
  return contactVelocity(a, b, point, normal) - before;
}

struct SlopeRun {
  double distance = 0.0;         ///< m travelled down the slope
  double acceleration = 0.0;     ///< m/s², from the velocity between t = 1 s and t = 3 s
  double rollingMismatch = 0.0;  ///< |v − ω r| / |v| at the end, for disks
};

/// The body on `ground(friction, angle)` in `scene` (its solver and settings), run for `seconds`.
SlopeRun runOnSlopeIn(Scene scene, const BodyDef& body, double angle, double friction,
                      double seconds) {
  scene.bodies.push_back(lecture::ground(friction, angle));
  scene.bodies.push_back(body);
  auto world = buildWorld(scene);
  const Vec2 down = lecture::downSlope(angle);
  const Vec2 start = world->bodies()[1].position;
  double speedAtOne = 0.0;
  double speedAtThree = 0.0;
  for (int step = 1; step * kDt <= seconds + 1e-9; ++step) {
    world->step();
    const double speed = world->bodies()[1].velocity.dot(down);
    if (step == 60) speedAtOne = speed;
    if (step == 180) speedAtThree = speed;
  }
  const Body& end = world->bodies()[1];
  SlopeRun run;
  run.distance = (end.position - start).dot(down);
  run.acceleration = (speedAtThree - speedAtOne) / 2.0;
  if (end.shape.type == ShapeType::Circle && end.velocity.norm() > 0.0) {
    // Rolling down a slope that falls to the left means turning counter-clockwise.
    run.rollingMismatch = std::abs(end.velocity.norm() - end.angularVelocity * end.shape.radius) /
                          end.velocity.norm();
  }
  return run;
}

SlopeRun runOnSlope(const BodyDef& body, double angle, double friction, double seconds,
                    const std::string& solver = "micro") {
  return runOnSlopeIn(lecture::sceneWith(solver, kDt), body, angle, friction, seconds);
}

}  // namespace

TEST_CASE("the contact matrix equals the unit-impulse probe", "[friction][contact-matrix]") {
  Body a = makeBody("a", BodyType::Dynamic, makeBox(1.2, 0.7), 2.0, Vec2(0.3, -0.2), 0.4);
  Body b = makeBody("b", BodyType::Dynamic, makeCircle(0.45), 0.8, Vec2(0.9, 0.6), -1.1);
  a.velocity = Vec2(0.5, -0.25);
  a.angularVelocity = 1.5;
  b.velocity = Vec2(-1.0, 0.3);
  b.angularVelocity = -0.7;
  const Vec2 point(0.71, 0.18);  // off both centres
  const Vec2 normal = Vec2(0.6, 0.8);
  const Mat2 matrix = contactMatrix(a, b, point, normal);
  const Vec2 normalColumn = probe(a, b, point, normal, normal);
  const Vec2 tangentColumn = probe(a, b, point, normal, leftPerpendicular(normal));
  CHECK((matrix.col(0) - normalColumn).norm() < 1e-12);
  CHECK((matrix.col(1) - tangentColumn).norm() < 1e-12);
  CHECK(std::abs(matrix(0, 1) - matrix(1, 0)) < 1e-15);  // symmetric, as it must be

  Body ground = makeBody("ground", BodyType::Static, makeBox(4.0, 1.0), 1.0, Vec2(0, -2), 0.2);
  const Mat2 againstStatic = contactMatrix(ground, a, point, normal);
  CHECK((againstStatic.col(0) - probe(ground, a, point, normal, normal)).norm() < 1e-12);
}

TEST_CASE("static friction holds a box on an incline with tan θ < μ", "[friction][static]") {
  const double angle = degrees(20.0);  // tan θ = 0.36
  const double friction = 0.5;
  const SlopeRun run =
      runOnSlope(lecture::boxOnSlope(Vec2(1.0, 0.5), angle, friction), angle, friction, 5.0);
  std::cout << "figure: box on a 20 deg incline, mu 0.5: moved " << run.distance << " m in 5 s\n";
  CHECK(std::abs(run.distance) < 1e-3);
}

TEST_CASE("dynamic friction lets a box slide at g(sin θ − μ cos θ)", "[friction][dynamic]") {
  const double angle = degrees(30.0);  // tan θ = 0.58
  const double friction = 0.3;
  const SlopeRun run =
      runOnSlope(lecture::boxOnSlope(Vec2(1.0, 0.5), angle, friction), angle, friction, 3.0);
  const double expected = lecture::kGravity * (std::sin(angle) - friction * std::cos(angle));
  std::cout << "figure: box sliding on a 30 deg incline, mu 0.3: a = " << run.acceleration
            << " m/s^2, analytic " << expected << "\n";
  CHECK(run.acceleration == Approx(expected).epsilon(0.02));
}

TEST_CASE("a sliding box's points report dynamic friction at every step, solved or carried",
          "[friction][dynamic]") {
  // tan 30° = 0.58 > μ = 0.3: the box slides, so every point that carries weight is on the
  // friction cone. Under micro, a warm-started step may carry its totals and resolve nothing;
  // the state frames and `i2d run --contacts` show must still be the one those totals are in.
  const double angle = degrees(30.0);
  const double friction = 0.3;
  for (const std::string solver : {"micro", "sequential", "reference"}) {
    Scene scene = lecture::sceneWith(solver, 1.0 / 60.0);
    scene.bodies = {lecture::ground(friction, angle),
                    lecture::boxOnSlope(Vec2(1.0, 0.5), angle, friction)};
    auto world = buildWorld(scene);
    int loaded = 0;
    int notSliding = 0;
    for (int step = 0; step < 120; ++step) {
      world->step();
      if (step < 10) continue;  // the first steps settle the landing
      for (const Manifold& manifold : world->manifolds()) {
        for (int p = 0; p < manifold.pointCount; ++p) {
          const ContactPoint& point = manifold.points[p];
          if (point.normalImpulse <= 0.0) continue;
          ++loaded;
          if (point.friction != FrictionState::Dynamic) ++notSliding;
        }
      }
    }
    INFO(solver << ": " << notSliding << " of " << loaded
                << " weight-carrying points of the sliding box not reported as sliding");
    // The box rests on the slope through the 110 steps inspected: a point carries its weight in
    // each of them.
    CHECK(loaded >= 110);
    CHECK(notSliding == 0);
  }
}

TEST_CASE("a disk with enough friction rolls at (2/3) g sin θ", "[friction][rolling]") {
  const double angle = degrees(20.0);
  const double friction = 0.6;  // rolling needs μ ≥ tan θ / 3 = 0.12
  const SlopeRun run = runOnSlope(lecture::diskOnSlope(0.5, angle, friction), angle, friction, 3.0);
  const double expected = 2.0 / 3.0 * lecture::kGravity * std::sin(angle);
  std::cout << "figure: disk rolling on a 20 deg incline: a = " << run.acceleration
            << " m/s^2, analytic " << expected << ", |v - w r|/|v| = " << run.rollingMismatch
            << "\n";
  CHECK(run.acceleration == Approx(expected).epsilon(0.02));
  CHECK(run.rollingMismatch < 0.01);
}

// Soft step measures a contact's separation within the step from how far its anchors moved. A
// disc's anchor turned with the disc lifts off the slope by r(1 − cos Δθ), so a small disc that
// turns far in a step reads a gap and is held up less: 0.1 m on 30° at 60 Hz turns 0.5–1.6 rad a
// step between 1 and 3 s and rolled 3.2 % slow. A circle's surface under the contact does not
// change as it turns: with round surfaces the anchor follows the centre alone.
TEST_CASE("soft step: a small disc turning fast rolls at (2/3) g sin θ with round surfaces",
          "[friction][rolling][soft_step]") {
  const double friction = 0.6;  // rolling needs μ ≥ tan θ / 3, at most 0.33 here
  for (const double degreesOfSlope : {10.0, 20.0, 30.0}) {  // 3 s of rolling stay on the slope
    const double angle = degrees(degreesOfSlope);
    const double expected = 2.0 / 3.0 * lecture::kGravity * std::sin(angle);
    for (const bool round : {true, false}) {
      Scene scene = lecture::sceneWith("soft_step", kDt);
      scene.solverSettings.softStep.roundSurfaces = round;
      const SlopeRun run =
          runOnSlopeIn(scene, lecture::diskOnSlope(0.1, angle, friction), angle, friction, 3.0);
      INFO(degreesOfSlope << " deg, round surfaces " << round << ": a = " << run.acceleration
                          << " m/s^2, analytic " << expected);
      if (round) {
        CHECK(run.acceleration == Approx(expected).epsilon(0.005));
        CHECK(run.rollingMismatch < 0.005);
      } else if (degreesOfSlope >= 20.0) {  // up to 1.1 and 1.6 rad a step: 2.7, 3.2 % slow
        CHECK(run.acceleration < (1.0 - 0.02) * expected);
      }
    }
  }
}

// Friction turns spin into rolling: a disc spinning in place on the ground slips, friction μmg
// speeds it up and slows its spin until v = ω r, after which nothing changes. Angular momentum
// about the contact point is kept through the slip (the friction force passes through it):
// I ω₀ = I ω + m v r with v = ω r gives v = ω₀ r / 3 for a disc (I = ½ m r²).
TEST_CASE("a disc spinning in place rolls off at ω₀ r / 3", "[friction][rolling]") {
  const double spin = 20.0;  // rad/s, clockwise: it rolls to the right
  for (const std::string solver : {"micro", "sequential", "soft_step", "reference"}) {
    for (const double radius : {0.1, 0.5}) {
      Scene scene = lecture::sceneWith(solver, kDt);
      scene.bodies.push_back(lecture::ground(0.3));
      BodyDef disc = lecture::diskOnSlope(radius, 0.0, 0.3);
      disc.angularVelocity = -spin;
      scene.bodies.push_back(disc);
      auto world = buildWorld(scene);
      for (int step = 0; step < 240; ++step) world->step();  // slips until ω₀ r / (3 μ g) ≤ 1.2 s
      const Body& end = world->bodies()[1];
      const double expected = spin * radius / 3.0;
      INFO(solver << ", radius " << radius << ": v = " << end.velocity.x() << " m/s, ω r = "
                  << -end.angularVelocity * radius << " m/s, analytic " << expected);
      CHECK(end.velocity.x() == Approx(expected).epsilon(0.01));
      CHECK(std::abs(end.velocity.x() + end.angularVelocity * radius) < 0.01 * expected);
    }
  }
}

// After a landing every method carries the landing's impulses into the next steps (warm
// starting); the slip must still be resolved in each of them. Micro once kept a landed disk's
// friction total step after step, its normal need met by the carried total and its slip never
// looked at: on 10° after a 5 cm drop it slipped ever faster, a = 1.169 m/s² for 1.136.
TEST_CASE("a disk that lands on a slope rolls, or slips, at the analytic acceleration",
          "[friction][rolling][landing]") {
  const double lift = 0.05;
  for (const std::string solver : {"micro", "sequential", "soft_step", "reference"}) {
    for (const double degreesOfSlope : {10.0, 20.0, 25.0}) {  // 3 s of slipping stay on the slope
      const double angle = degrees(degreesOfSlope);
      for (const double radius : {0.25, 1.0}) {
        // Rolling needs μ ≥ tan θ / 3: twice that rolls, half of it slips.
        for (const bool rolls : {true, false}) {
          const double friction = (rolls ? 2.0 : 0.5) * std::tan(angle) / 3.0;
          const double expected =
              rolls ? 2.0 / 3.0 * lecture::kGravity * std::sin(angle)
                    : lecture::kGravity * (std::sin(angle) - friction * std::cos(angle));
          const SlopeRun run = runOnSlope(lecture::diskOnSlope(radius, angle, friction, lift),
                                          angle, friction, 3.0, solver);
          INFO(solver << ", " << degreesOfSlope << " deg, radius " << radius
                      << (rolls ? ", rolls" : ", slips") << ": a = " << run.acceleration
                      << " m/s^2, analytic " << expected);
          CHECK(run.acceleration == Approx(expected).epsilon(0.02));
          if (rolls) CHECK(run.rollingMismatch < 0.02);
        }
      }
    }
  }
}

// Friction opposes the slip, whichever way it goes. A box sent up a slope slides against gravity
// and friction together, a = −g(sin θ + μ cos θ); once it stops, static friction holds it if
// μ > tan θ, or it slides back down with friction now pointing up the slope, a = g(sin θ − μ cos
// θ).
TEST_CASE("a box sent up a slope decelerates at g(sin θ + μ cos θ), then holds or slides back",
          "[friction][dynamic][static]") {
  const double launch = 3.0;  // m/s up the slope
  for (const std::string solver : {"micro", "sequential", "soft_step", "reference"}) {
    for (const double degreesOfSlope : {15.0, 25.0}) {
      const double angle = degrees(degreesOfSlope);
      for (const double friction : {0.3, 0.6}) {  // below tan 25° = 0.47, above it
        Scene scene = lecture::sceneWith(solver, kDt);
        scene.bodies.push_back(lecture::ground(friction, angle));
        BodyDef box = lecture::boxOnSlope(Vec2(1.0, 1.0), angle, friction);
        const Vec2 down = lecture::downSlope(angle);
        box.velocity = -launch * down;
        scene.bodies.push_back(box);
        auto world = buildWorld(scene);
        std::vector<double> speedDown;  // after each step, m/s down the slope
        std::vector<double> distanceDown;
        for (int step = 0; step < 180; ++step) {
          world->step();
          speedDown.push_back(world->bodies()[1].velocity.dot(down));
          distanceDown.push_back(world->bodies()[1].position.dot(down));
        }
        const double g = lecture::kGravity;
        const double climbing = g * (std::sin(angle) + friction * std::cos(angle));
        const double aUp = (speedDown[10] - speedDown[2]) / (8 * kDt);  // stops after 0.3 s
        INFO(solver << ", " << degreesOfSlope << " deg, mu " << friction << ": climbing a = " << aUp
                    << " m/s^2, analytic " << climbing);
        CHECK(aUp == Approx(climbing).epsilon(0.01));
        if (friction > std::tan(angle)) {
          INFO("after stopping it moved " << distanceDown[179] - distanceDown[59] << " m in 2 s");
          CHECK(std::abs(distanceDown[179] - distanceDown[59]) < 1e-3);
        } else {
          const double back = g * (std::sin(angle) - friction * std::cos(angle));
          const double aDown = (speedDown[179] - speedDown[119]) / (60 * kDt);
          INFO("sliding back a = " << aDown << " m/s^2, analytic " << back);
          CHECK(aDown == Approx(back).epsilon(0.01));
        }
      }
    }
  }
}

// Rolling stores energy in the turn as well: a disc rolling up a slope at v₀ (ω₀ = v₀ / r) climbs
// on ½ m v₀² + ½ (½ m r²) ω₀² = ¾ m v₀², so it stops after 3 v₀² / (4 g sin θ) along the slope,
// half as far again as a body sliding without friction. Static friction, which carries the
// turn's energy into the climb, needs only tan θ / 3 (0.19 at 30°). Semi-implicit Euler moves
// each step at the step's end velocity, so its turning point falls short by about v₀ dt / 2;
// held to a step's travel v₀ dt (measured half that; soft step a quarter, in its substeps).
TEST_CASE("a disc rolled up a slope stops after 3 v₀² / (4 g sin θ), then rolls back",
          "[friction][rolling]") {
  const double launch = 2.0;  // m/s up the slope
  const double radius = 0.3;
  for (const std::string solver : {"micro", "sequential", "soft_step", "reference"}) {
    for (const double degreesOfSlope : {10.0, 20.0, 30.0}) {
      for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
        const double angle = degrees(degreesOfSlope);
        Scene scene = lecture::sceneWith(solver, dt);
        scene.bodies.push_back(lecture::ground(0.5, angle));
        BodyDef disc = lecture::diskOnSlope(radius, angle, 0.5);
        const Vec2 up = -lecture::downSlope(angle);
        disc.velocity = launch * up;
        disc.angularVelocity = -launch / radius;
        scene.bodies.push_back(disc);
        auto world = buildWorld(scene);
        const Vec2 start = disc.position;
        double farthest = 0.0;
        double lastSpeed = launch;
        while (world->stepCount() * dt < 2.0) {
          world->step();
          farthest = std::max(farthest, (world->bodies()[1].position - start).dot(up));
          lastSpeed = world->bodies()[1].velocity.dot(up);
        }
        const double exact = 3.0 * launch * launch / (4.0 * lecture::kGravity * std::sin(angle));
        INFO(solver << ", " << degreesOfSlope << "°, dt " << dt << ": turned back after "
                    << farthest << " m (" << exact << "), speed up the slope at 2 s " << lastSpeed
                    << " m/s");
        CHECK(farthest == Approx(exact).margin(launch * dt));
        CHECK(lastSpeed < 0.0);  // rolling back down
      }
    }
  }
}

// A disc thrown along the ground without spin slides; friction μmg slows it and spins it up until
// v = ω r. Angular momentum about the contact line is kept (friction acts on it), so
// m v₀ r = m v r + ½ m r² (v / r): v = (2/3) v₀, reached after v₀ / (3 μ g).
TEST_CASE("a disc thrown sliding rolls off at (2/3) v₀ after v₀ / (3 μ g)", "[friction][rolling]") {
  const double thrown = 4.0;  // m/s
  for (const std::string solver : {"micro", "sequential", "soft_step", "reference"}) {
    for (const double radius : {0.1, 0.5}) {
      for (const double friction : {0.2, 0.6}) {
        Scene scene = lecture::sceneWith(solver, kDt);
        scene.bodies.push_back(lecture::ground(friction));
        BodyDef disc = lecture::diskOnSlope(radius, 0.0, friction);
        disc.position.x() = -15.0;
        disc.velocity = Vec2(thrown, 0.0);
        scene.bodies.push_back(disc);
        auto world = buildWorld(scene);
        const double slipTime = thrown / (3.0 * friction * lecture::kGravity);
        double rollingFrom = -1.0;  // s: the first step that ends with the slip under 1 mm/s
        for (int step = 1; step * kDt < slipTime + 1.0; ++step) {
          world->step();
          const Body& moving = world->bodies()[1];
          const double slip = moving.velocity.x() + moving.angularVelocity * radius;
          if (rollingFrom < 0.0 && std::abs(slip) < 1e-3) rollingFrom = step * kDt;
        }
        const double speed = world->bodies()[1].velocity.x();
        INFO(solver << ", radius " << radius << ", mu " << friction << ": v = " << speed
                    << " m/s (analytic " << 2.0 / 3.0 * thrown << "), rolling from " << rollingFrom
                    << " s (analytic " << slipTime << ")");
        CHECK(speed == Approx(2.0 / 3.0 * thrown).epsilon(0.005));
        CHECK(std::abs(rollingFrom - slipTime) < 0.02 * slipTime + kDt);
      }
    }
  }
}

// Friction between two moving bodies: a box pushed along frictionless ground carries the box on
// it while the pair's acceleration F / 2m needs less than static friction can give the top box
// (μ g), and slides from under it beyond that: the top box then gets μ g, the bottom one
// (F − μ m g) / m. Both boxes 1 kg, μ 0.5 between them, so the limit is F = 2 μ m g = 9.81 N.
TEST_CASE("a pushed box carries the box on it below F = 2 μ m g and slides from under it above",
          "[friction][static][dynamic]") {
  const double friction = 0.5;
  const double g = lecture::kGravity;
  for (const std::string solver : {"micro", "sequential", "soft_step", "reference"}) {
    for (const double push : {4.0, 15.0}) {  // N
      Scene scene = lecture::sceneWith(solver, kDt);
      scene.bodies.push_back(lecture::ground(0.0));  // frictionless: μ mixes as √(μA μB)
      BodyDef bottom = lecture::boxOnSlope(Vec2(1.0, 1.0), 0.0, friction);
      bottom.load.force = Vec2(push, 0.0);
      BodyDef top = lecture::boxOnSlope(Vec2(1.0, 1.0), 0.0, friction, 1.0);
      top.position.y() = 1.5;  // exactly on the bottom box
      scene.bodies.push_back(bottom);
      scene.bodies.push_back(top);
      auto world = buildWorld(scene);
      // The top box slides off after √(2 · 0.5 m / 5.2 m/s²) = 0.44 s: measure over 0.05–0.3 s.
      Vec2 speedsAt3 = Vec2::Zero();  // (bottom, top) m/s after step 3
      Vec2 speeds = Vec2::Zero();
      for (int step = 1; step <= 18; ++step) {
        world->step();
        speeds = Vec2(world->bodies()[1].velocity.x(), world->bodies()[2].velocity.x());
        if (step == 3) speedsAt3 = speeds;
      }
      const Vec2 accelerations = (speeds - speedsAt3) / (15 * kDt);
      const bool carried = push / 2.0 < friction * g;
      const Vec2 expected =
          carried ? Vec2(push / 2.0, push / 2.0) : Vec2(push - friction * g, friction * g);
      INFO(solver << ", push " << push << " N: bottom a = " << accelerations.x()
                  << ", top a = " << accelerations.y() << " m/s^2; analytic " << expected.x()
                  << ", " << expected.y());
      CHECK(accelerations.x() == Approx(expected.x()).epsilon(0.005));
      CHECK(accelerations.y() == Approx(expected.y()).epsilon(0.005));
    }
  }
}

// Dynamic friction between two moving bodies until it turns static: a box thrown along a long
// board lying on frictionless ground drags the board with it until both move at the velocity
// momentum leaves them, v = m₁v₀ / (m₁ + m₂). Friction μ m₁ g decelerates the box and accelerates
// the board, so the box slips v₀² m₂ / (2 μ g (m₁ + m₂)) along the board first. Semi-implicit
// Euler, slowing the slip by a dt a step and moving with the slowed speed, slips v₀ dt / 2 less
// than that (measured −0.48 to −0.50 v₀ dt; soft step's substeps −0.12 to +0.25), so within a
// step's slip, v₀ dt. Once the slip stops they move together to within micro's velocity epsilon.
TEST_CASE("a box thrown along a free board slides to their common velocity m1 v0 / (m1 + m2)",
          "[friction][dynamic][momentum]") {
  const double g = lecture::kGravity;
  const double v0 = 3.0;  // m/s
  for (const std::string solver : {"micro", "sequential", "soft_step", "reference"}) {
    for (const double massRatio : {0.2, 5.0}) {  // box : board
      for (const double friction : {0.3, 0.6}) {
        for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
          Scene scene = lecture::sceneWith(solver, dt);
          scene.bodies.push_back(lecture::ground(0.0));  // frictionless: μ mixes as √(μA μB)
          BodyDef board = lecture::boxOnSlope(Vec2(6.0, 0.5), 0.0, friction);
          BodyDef box = lecture::boxOnSlope(Vec2(1.0, 0.5), 0.0, friction, 0.5);
          box.position.x() = -2.4;
          box.velocity = Vec2(v0, 0.0);
          box.density = massRatio * 6.0;  // the board is six times the box's area
          scene.bodies.push_back(board);
          scene.bodies.push_back(box);
          auto world = buildWorld(scene);
          const double m2 = 1.0 / world->bodies()[1].inverseMass;
          const double m1 = 1.0 / world->bodies()[2].inverseMass;
          const double common = m1 * v0 / (m1 + m2);
          const double slipTime = v0 * m2 / (friction * g * (m1 + m2));
          const double slip = v0 * v0 * m2 / (2.0 * friction * g * (m1 + m2));
          const double startGap = world->bodies()[2].position.x() - world->bodies()[1].position.x();
          while (world->stepCount() * dt < slipTime + 0.5) world->step();
          const Body& boardNow = world->bodies()[1];
          const Body& boxNow = world->bodies()[2];
          const double momentum = m1 * boxNow.velocity.x() + m2 * boardNow.velocity.x();
          const double slipped = boxNow.position.x() - boardNow.position.x() - startGap;
          INFO(solver << ", m1/m2 " << massRatio << ", mu " << friction << ", dt " << dt << ": box "
                      << boxNow.velocity.x() << " m/s, board " << boardNow.velocity.x()
                      << " m/s (analytic " << common << "), slipped " << slipped << " m (analytic "
                      << slip << ")");
          const double velocityEpsilon = MicroCollisionSettings{}.velocityEpsilon;
          CHECK(std::abs(boxNow.velocity.x() - common) < velocityEpsilon);
          CHECK(std::abs(boardNow.velocity.x() - common) < velocityEpsilon);
          CHECK(momentum == Approx(m1 * v0).epsilon(1e-9));
          CHECK(std::abs(slipped - slip) < v0 * dt);
        }
      }
    }
  }
}

// A disc rolling down a slope onto flat ground: where the slope meets the ground it touches both,
// the ground stops its fall (e = 0) and friction its slip, both through the new contact point,
// so its angular momentum about that point is kept: m r v cos θ + I v / r = (m r + I / r) v′, and
// for a disc (I = m r² / 2) it rolls on at v′ = v (1 + 2 cos θ) / 3, v its speed in the last step
// before the ground pushes. The landing falls within the next step, in which the slope may add up
// to (2/3) g sin θ dt (measured: at most a quarter of that). It lands up to a step's fall into
// the ground, and turns fast (16 rad/s for r = 0.25 m from 3 m of 30°): micro's penetration phase
// must lift it out to its position epsilon although the point of its rim that touched has turned
// away (Pose::anchorNow).
TEST_CASE("a disc rolling off a slope onto flat ground rolls on at v (1 + 2 cos θ) / 3",
          "[friction][rolling][landing]") {
  for (const std::string solver : {"micro", "sequential", "reference"}) {
    for (const double angle : {degrees(10.0), degrees(20.0), degrees(30.0)}) {
      for (const double radius : {0.25, 0.5}) {
        for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
          Scene scene = lecture::sceneWith(solver, dt);
          scene.bodies.push_back(lecture::ground(0.6, -angle));  // falls to the right
          BodyDef flat = lecture::ground(0.6);
          flat.name = "flat";
          flat.position.x() += 20.0;  // its top face's left end at the slope's foot, the origin
          scene.bodies.push_back(flat);
          BodyDef disc = lecture::diskOnSlope(radius, -angle, 0.6);
          disc.position += 3.0 * Vec2(-std::cos(angle), std::sin(angle));  // 3 m up the slope
          scene.bodies.push_back(disc);
          auto world = buildWorld(scene);
          const auto touchesFlat = [&world] {  // the flat ground pushes the disc
            for (const Manifold& manifold : world->manifolds()) {
              if (manifold.bodyA != 1 && manifold.bodyB != 1) continue;
              for (int p = 0; p < manifold.pointCount; ++p) {
                if (manifold.points[p].normalImpulse > 0.0) return true;
              }
            }
            return false;
          };
          double before = 0.0;  // m/s, the disc's speed before the ground pushes
          while (!touchesFlat() && world->stepCount() * dt < 5.0) {
            before = world->bodies()[2].velocity.norm();
            world->step();
          }
          const long landed = world->stepCount();
          while (world->stepCount() < landed + std::lround(1.0 / dt)) world->step();
          const Body& after = world->bodies()[2];
          const double expected = before * (1.0 + 2.0 * std::cos(angle)) / 3.0;
          INFO(solver << ", " << angle * 180.0 / kPi << " deg, r " << radius << ", dt " << dt
                      << ": " << before << " m/s before, " << after.velocity.x()
                      << " m/s a second later (analytic " << expected << "), centre "
                      << after.position.y() << " m above the ground");
          const double landingStepGain = 2.0 / 3.0 * lecture::kGravity * std::sin(angle) * dt;
          CHECK(std::abs(after.velocity.x() - expected) < landingStepGain);
          CHECK(std::abs(after.velocity.y()) < MicroCollisionSettings{}.velocityEpsilon);
          if (solver == "micro") {
            CHECK(after.position.y() > radius - MicroCollisionSettings{}.positionEpsilon);
          }
        }
      }
    }
  }
}

namespace {

/// A pile of three discs on a flat ground of friction μ_ground: two of radius `bottom` with a gap
/// between them and one of radius `top` resting on both, the lines from its centre to theirs at
/// `alpha` from the vertical, all at rest and exactly touching. The discs' own friction is
/// `discs`; the ground's is chosen so that a disc on it mixes to `discGround` (√(μA μB)).
Scene discPyramid(const std::string& solver, double alpha, double bottom, double top, double discs,
                  double discGround) {
  Scene scene = lecture::sceneWith(solver, kDt);
  scene.bodies.push_back(lecture::ground(discGround * discGround / discs));
  const double reach = bottom + top;
  for (const double side : {-1.0, 1.0}) {
    BodyDef disc;
    disc.shape = makeCircle(bottom);
    disc.position = Vec2(side * reach * std::sin(alpha), bottom);
    disc.friction = discs;
    scene.bodies.push_back(disc);
  }
  BodyDef disc;
  disc.shape = makeCircle(top);
  disc.position = Vec2(0.0, bottom + reach * std::cos(alpha));
  disc.friction = discs;
  scene.bodies.push_back(disc);
  return scene;
}

}  // namespace

// Three discs piled as a pyramid, the bottom two apart (the contact lines at α from the vertical).
// A bottom disc (mass m) is pushed by the top one (mass M) with N along the contact line and f
// along the tangent, and held by the ground's G and F. Its moments about its centre give f = F;
// its horizontal forces N sin α = f (1 + cos α), so f = N tan(α/2) whatever the radii; the top
// disc's vertical forces then give N = M g / 2 (cos α + tan(α/2) sin α = 1), and G = (m + M/2) g.
// The pile stands iff the discs' friction reaches tan(α/2) and the ground's M tan(α/2) / (2m + M)
// (tan(α/2) / 3 for equal discs). Below the first the bottom discs roll apart under the top one;
// below the second they slide apart.
TEST_CASE(
    "three discs piled stand iff μ reaches tan(α/2) between them, M tan(α/2) / (2m + M) "
    "on the ground",
    "[friction][pile]") {
  struct Pile {
    double alpha, bottom, top;
  };
  for (const Pile pile : {Pile{degrees(32.0), 0.3, 0.3}, Pile{degrees(40.0), 0.4, 0.4},
                          Pile{degrees(45.0), 0.5, 0.25}, Pile{degrees(35.0), 0.25, 0.5}}) {
    const double half = std::tan(0.5 * pile.alpha);
    const double ratio = pile.top * pile.top / (pile.bottom * pile.bottom);  // M / m
    const double onGround = ratio * half / (2.0 + ratio);
    for (const std::string solver : {"micro", "sequential", "reference", "soft_step"}) {
      // (discs' μ, ground's μ, stands): each at 15 % above or below its threshold, the other 1.
      for (const auto& [discs, ground, stands] :
           {std::tuple{1.15 * half, 1.0, true}, std::tuple{1.0, 1.15 * onGround, true},
            std::tuple{0.85 * half, 1.0, false}, std::tuple{1.0, 0.85 * onGround, false}}) {
        auto world =
            buildWorld(discPyramid(solver, pile.alpha, pile.bottom, pile.top, discs, ground));
        while (world->stepCount() * kDt < 0.5) world->step();
        const Vec2 settled = world->bodies()[1].position;
        const double top = world->bodies()[3].mass;
        const double weight = top * lecture::kGravity;
        double upper = 0.0, upperFriction = 0.0, below = 0.0;
        for (const Manifold& manifold : world->manifolds()) {
          if (manifold.bodyA != 1 && manifold.bodyB != 1) continue;
          const bool onGroundContact = manifold.bodyA == 0 || manifold.bodyB == 0;
          for (int i = 0; i < manifold.pointCount; ++i) {
            const ContactPoint& point = manifold.points[size_t(i)];
            (onGroundContact ? below : upper) += point.normalImpulse / kDt;
            if (!onGroundContact) upperFriction += std::abs(point.tangentImpulse) / kDt;
          }
        }
        while (world->stepCount() * kDt < 3.0) world->step();
        const double moved = (world->bodies()[1].position - settled).norm();
        const double bottomWeight = world->bodies()[1].mass * lecture::kGravity;
        INFO(solver << ", α " << pile.alpha * 180.0 / kPi << "°, radii " << pile.bottom << " / "
                    << pile.top << ", μ discs " << discs << " (threshold " << half << "), ground "
                    << ground << " (" << onGround << "): bottom disc moved " << moved
                    << " m from 0.5 to 3 s; at 0.5 s N " << upper << " (" << 0.5 * weight << "), f "
                    << upperFriction << " (" << 0.5 * weight * half << "), G " << below << " ("
                    << bottomWeight + 0.5 * weight << ") N");
        if (!stands) {
          CHECK(moved > 0.05);
          continue;
        }
        CHECK(moved < 1e-3);
        CHECK(upper == Approx(0.5 * weight).epsilon(1e-3));
        CHECK(upperFriction == Approx(0.5 * weight * half).epsilon(1e-2));
        CHECK(below == Approx(bottomWeight + 0.5 * weight).epsilon(1e-3));
      }
    }
  }
}
