// Static and dynamic friction of the micro-collision resolver on slopes (lecture 3.6):
// a box or a regular pentagon on a static slope of 5° to 25° holds still when μ > tan θ and
// slides at a = g(sin θ − μ cos θ) when μ < tan θ, whether it starts at rest on the slope or lands
// on it from a small drop.
#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>
#include <string>

#include "lecture_scenes.h"

using namespace impulse2d;

namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kDrop = 0.02;        ///< m: the small drop onto the slope
constexpr double kSettled = 1.0;      ///< s: landing is over by then (a 2 cm fall takes 0.064 s)
constexpr double kHoldSeconds = 5.0;  ///< s: how long a holding body is watched
constexpr double kHoldMargin = 0.1;   ///< μ − tan θ of a body that must hold
constexpr double kSlideMargin = 0.05;
/// m. The velocity solve stops once no slip exceeds velocityEpsilon (1e-4 m/s), so a resolver
/// that starts every step from zero totals may creep at up to that speed: 0.5 mm in 5 s. Warm
/// started from the totals that held it last step, a body keeps no creep in one direction; half
/// that bound (the issue asks for < 1 mm) fails the resolver as it was (0.55 mm at 25°).
constexpr double kHoldBound = 0.5 * 1e-4 * kHoldSeconds;  ///< tan θ − μ of a body that must slide
constexpr double kPentagonRadius = 0.6;                   ///< m, centre to corner

double degrees(double d) {
  return d * kPi / 180.0;
}

BodyDef bodyOnSlope(const std::string& shape, double angle, double friction, double lift) {
  if (shape == "box") return lecture::boxOnSlope(Vec2(1.0, 1.0), angle, friction, lift);
  BodyDef pentagon = lecture::polygonOnSlope(5, kPentagonRadius, angle, friction, lift);
  pentagon.name = "pentagon";
  return pentagon;
}

struct SlopeRun {
  double moved = 0.0;         ///< m down the slope in kHoldSeconds from `watchFrom`
  double turned = 0.0;        ///< rad in the same time
  double acceleration = 0.0;  ///< m/s² down the slope over the 2 s after kSettled
};

/// How the slope experiment is run: the lecture's resolver at 60 Hz with the ground listed
/// first, unless a test says otherwise. Restitution is set on the body and the ground alike.
struct SlopeSetup {
  std::string solver = "micro";
  double dt = kDt;
  double restitution = 0.0;
  bool groundLast = false;  ///< list the body first: the ground is then body B of the contact
};

/// Runs the body on the slope. It is watched for kHoldSeconds from the start when placed at rest
/// (the first steps from rest are where a resolver lets go), from kSettled when dropped.
SlopeRun runOnSlope(BodyDef body, double angle, double friction, bool dropped,
                    const SlopeSetup& setup = {}) {
  Scene scene = lecture::sceneWith(setup.solver, setup.dt);
  BodyDef ground = lecture::ground(friction, angle);
  ground.restitution = body.restitution = setup.restitution;
  scene.bodies =
      setup.groundLast ? std::vector<BodyDef>{body, ground} : std::vector<BodyDef>{ground, body};
  const int index = setup.groundLast ? 0 : 1;
  auto world = buildWorld(scene);
  const Vec2 down = lecture::downSlope(angle);
  const int settledStep = int(std::lround(kSettled / setup.dt));
  const int watchFrom = dropped ? settledStep : 0;
  const int lastStep = watchFrom + int(std::lround(kHoldSeconds / setup.dt));
  const int twoSecondsLater = settledStep + int(std::lround(2.0 / setup.dt));
  Vec2 watchedFrom = world->bodies()[index].position;
  double watchedAngle = world->bodies()[index].angle;
  double settledSpeed = 0.0;
  SlopeRun run;
  for (int step = 1; step <= lastStep; ++step) {
    world->step();
    const Body& moving = world->bodies()[index];
    if (step == watchFrom) {
      watchedFrom = moving.position;
      watchedAngle = moving.angle;
    }
    if (step == settledStep) settledSpeed = moving.velocity.dot(down);
    if (step == twoSecondsLater) {
      run.acceleration = (moving.velocity.dot(down) - settledSpeed) / 2.0;
    }
  }
  run.moved = (world->bodies()[index].position - watchedFrom).dot(down);
  run.turned = world->bodies()[index].angle - watchedAngle;
  return run;
}

}  // namespace

TEST_CASE("boxes and pentagons hold on slopes steeper than 5° when μ > tan θ",
          "[friction][static][slope]") {
  for (const std::string shape : {"box", "pentagon"}) {
    for (double angleDegrees : {5.0, 10.0, 20.0, 25.0}) {
      for (double lift : {0.0, kDrop}) {
        const double angle = degrees(angleDegrees);
        const double friction = std::tan(angle) + kHoldMargin;
        const SlopeRun run =
            runOnSlope(bodyOnSlope(shape, angle, friction, lift), angle, friction, lift > 0.0);
        std::cout << "figure: " << shape << " on " << angleDegrees << " deg, mu " << friction
                  << (lift > 0.0 ? ", dropped" : ", at rest") << ": moved " << run.moved * 1e3
                  << " mm in " << kHoldSeconds << " s\n";
        INFO(shape << " on " << angleDegrees << " deg, lift " << lift);
        CHECK(std::abs(run.moved) < kHoldBound);
      }
    }
  }
}

TEST_CASE("boxes and pentagons slide at g(sin θ − μ cos θ) when μ < tan θ",
          "[friction][dynamic][slope]") {
  for (const std::string shape : {"box", "pentagon"}) {
    for (double angleDegrees : {5.0, 10.0, 20.0, 25.0}) {
      for (double lift : {0.0, kDrop}) {
        const double angle = degrees(angleDegrees);
        const double friction = std::tan(angle) - kSlideMargin;
        const SlopeRun run =
            runOnSlope(bodyOnSlope(shape, angle, friction, lift), angle, friction, lift > 0.0);
        const double expected = lecture::kGravity * (std::sin(angle) - friction * std::cos(angle));
        std::cout << "figure: " << shape << " on " << angleDegrees << " deg, mu " << friction
                  << (lift > 0.0 ? ", dropped" : ", at rest") << ": a = " << run.acceleration
                  << " m/s^2, analytic " << expected << "\n";
        INFO(shape << " on " << angleDegrees << " deg, lift " << lift);
        CHECK(run.acceleration == Approx(expected).epsilon(0.02));
      }
    }
  }
}

// Restitution on a resting contact: the closing speed gravity adds in a step at 30 Hz (0.33 m/s
// on level ground) is above the restitution limit (0.25 m/s), and the bounce −e(vs − vacc) is
// then zero only to round-off. A round-off "bounce" once marked the point as bounced, so it
// started the next step without its warm-start total while its partner kept its own: the
// partner's carried impulse turned the box, the cold corner then closed faster than gravity
// alone and truly bounced, and the box rocked and crept down (6 mm in 5 s on 5°, 66 mm on 15°
// with the ground listed last). A bounce below the solve's own tolerance is none now.
TEST_CASE("a box with restitution placed at rest on a slope holds at 30 and 60 Hz",
          "[friction][static][slope][restitution]") {
  for (const std::string shape : {"box", "pentagon"}) {
    for (double angleDegrees : {5.0, 15.0}) {
      for (double dt : {1.0 / 30.0, kDt}) {
        for (bool groundLast : {false, true}) {
          const double angle = degrees(angleDegrees);
          const double friction = std::tan(angle) + kHoldMargin;
          SlopeSetup setup;
          setup.dt = dt;
          setup.restitution = 0.3;
          setup.groundLast = groundLast;
          const SlopeRun run =
              runOnSlope(bodyOnSlope(shape, angle, friction, 0.0), angle, friction, false, setup);
          INFO(shape << " on " << angleDegrees << " deg at " << 1.0 / dt << " Hz, ground "
                     << (groundLast ? "last" : "first") << ": moved " << run.moved * 1e3
                     << " mm, turned " << run.turned << " rad");
          CHECK(std::abs(run.moved) < kHoldBound);
          // Turned by kHoldBound about a corner, half a metre from the centre, at most.
          CHECK(std::abs(run.turned) < kHoldBound / 0.5);
        }
      }
    }
  }
}

// A box hopping down a slope 5° below its tipping angle: dropped 10 cm onto 40° (a 1 × 1 box
// tips at 45°) with e = 0.3, it bounces off and falls back exactly as its gap closes in the
// step. Round-off once engaged one corner and not the other: the first was resolved alone,
// the box spun at 0.26 rad/s and tumbled away down the slope (19 m in 5 s), where sequential
// impulses, the reference and Box2D 2.4.1 land it flat and hold it. μ 0.94 > tan 40° holds it and
// the vertical through its centre stays inside its base (tan 40° < 1), so after landing it
// must rest. Gaps are now compared to within touchingTolerance, and both corners act together.
TEST_CASE("a box hopping onto a slope near its tipping angle lands flat and holds",
          "[friction][static][slope][restitution]") {
  for (const std::string solver : {"micro", "sequential", "reference"}) {
    for (double size : {1.0, 0.3}) {
      const double angle = degrees(40.0);
      const double friction = std::tan(angle) + kHoldMargin;
      SlopeSetup setup;
      setup.solver = solver;
      setup.restitution = 0.3;
      const BodyDef box = lecture::boxOnSlope(Vec2(size, size), angle, friction, 0.1);
      const SlopeRun run = runOnSlope(box, angle, friction, true, setup);
      INFO(solver << ", " << size << " m box: moved " << run.moved * 1e3 << " mm, turned "
                  << run.turned << " rad");
      CHECK(std::abs(run.moved) < kHoldBound);
      CHECK(std::abs(run.turned) < kHoldBound / (0.5 * size));
    }
  }
}
