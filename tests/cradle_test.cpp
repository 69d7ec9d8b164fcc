// Newton's cradle (lecture 3.6): the micro-collision resolver recomputes a contact's
// bounce from its closing velocity at the moment it is resolved, so an impulse that stops one
// ball makes the next contact close, and the collision passes along a row of touching balls to
// the far ball. A bounce target fixed once per step cannot: the row moves off together.
#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>

#include "lecture_scenes.h"

using namespace impulse2d;

namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kStrikeSpeed = 2.0;  ///< m/s, above the low-speed restitution limit
constexpr double kStrikeGap = 0.25;   ///< m between the striker and the row
constexpr int kSteps = 60;            ///< 1 s: the strike lands after 0.125 s
constexpr double kRadius = 0.5;

/// How a cradle is set up: the striker's gap to the row and its speed, the balls' radius, and how
/// many strikers, touching one another, strike together.
struct Strike {
  double gap = kStrikeGap;
  double speed = kStrikeSpeed;
  double radius = kRadius;
  double dt = kDt;
  int strikers = 1;
};

/// The strikers strike.gap short of `balls` touching balls, elastic (e = 1) and frictionless, no
/// gravity.
Scene cradle(int balls, const std::string& solver, const Strike& strike = {}) {
  Scene scene = lecture::sceneWith(solver, strike.dt);
  scene.world.gravity = Vec2::Zero();
  BodyDef ball;
  ball.shape = makeCircle(strike.radius);
  ball.friction = 0.0;
  ball.restitution = 1.0;
  ball.velocity = Vec2(strike.speed, 0.0);
  for (int k = strike.strikers; k >= 1; --k) {
    ball.position = Vec2(-2.0 * strike.radius * k - strike.gap, 0.0);
    scene.bodies.push_back(ball);
  }
  ball.velocity = Vec2::Zero();
  for (int k = 0; k < balls; ++k) {
    ball.position = Vec2(2.0 * strike.radius * k, 0.0);
    scene.bodies.push_back(ball);
  }
  return scene;
}

double momentum(const World& world) {
  double total = 0.0;
  for (const Body& body : world.bodies()) total += body.velocity.x() / body.inverseMass;
  return total;
}

double kineticEnergy(const World& world) {
  double total = 0.0;
  for (const Body& body : world.bodies()) {
    total += 0.5 * body.velocity.squaredNorm() / body.inverseMass;
  }
  return total;
}

/// What a strike left after `steps` steps: the slowest of the `leaving` far balls, the fastest of
/// the others, and the momentum and kinetic energy before and after.
struct StrikeOutcome {
  double farSpeed = 0.0;
  double fastestOther = 0.0;
  double momentumBefore = 0.0;
  double momentumAfter = 0.0;
  double energyBefore = 0.0;
  double energyAfter = 0.0;
};

StrikeOutcome runStrike(const Scene& scene, int steps, int leaving = 1) {
  auto world = buildWorld(scene);
  StrikeOutcome outcome;
  outcome.momentumBefore = momentum(*world);
  outcome.energyBefore = kineticEnergy(*world);
  for (int step = 0; step < steps; ++step) world->step();
  const auto& bodies = world->bodies();
  const int firstLeaving = int(bodies.size()) - leaving;
  outcome.farSpeed = bodies.back().velocity.x();
  for (int k = 0; k < int(bodies.size()); ++k) {
    if (k < firstLeaving) {
      outcome.fastestOther = std::max(outcome.fastestOther, bodies[k].velocity.norm());
    } else {
      outcome.farSpeed = std::min(outcome.farSpeed, bodies[k].velocity.x());
    }
  }
  outcome.momentumAfter = momentum(*world);
  outcome.energyAfter = kineticEnergy(*world);
  return outcome;
}

/// The conditions: the far ball leaves with at least 90 % of the striker's speed, every
/// other ball under 10 %, momentum kept to 1e-9 of itself, and no energy gained beyond round-off.
void checkPassedAlong(const StrikeOutcome& outcome, double strikeSpeed) {
  CHECK(outcome.farSpeed >= 0.9 * strikeSpeed);
  CHECK(outcome.fastestOther < 0.1 * strikeSpeed);
  CHECK(std::abs(outcome.momentumAfter - outcome.momentumBefore) < 1e-9 * outcome.momentumBefore);
  CHECK(outcome.energyAfter <= outcome.energyBefore * (1.0 + 1e-12));
}

}  // namespace

TEST_CASE("a collision passes along a row of touching balls to the far ball",
          "[restitution][cradle][micro]") {
  // The propagation is the lecture's own: it holds with our refinements and without them.
  for (const bool lecturePreset : {false, true}) {
    for (int balls = 2; balls <= 10; ++balls) {
      Scene scene = cradle(balls, "micro");
      if (lecturePreset) scene.solverSettings.micro = MicroCollisionSettings::lecture();
      const StrikeOutcome outcome = runStrike(scene, kSteps);
      std::cout << "figure: " << (lecturePreset ? "lecture preset, " : "") << "cradle of " << balls
                << " balls + striker: far ball " << outcome.farSpeed << " m/s, fastest other "
                << outcome.fastestOther << " m/s, momentum change "
                << outcome.momentumAfter - outcome.momentumBefore << ", energy change "
                << outcome.energyAfter - outcome.energyBefore << " J\n";
      INFO(balls << " balls");
      checkPassedAlong(outcome, kStrikeSpeed);
    }
  }
}

// Whether a row's neighbours read as touching is round-off: the penetration phase leaves a
// resolved pair at zero overlap, and the next step's contact may read it 1.7e-16 m apart. Seven
// balls of 0.1 m struck from touching at 0.5 m/s did that at the sixth pair: the lecture preset
// (no speculative gaps) stopped the collision there, and the sixth ball pushed the far one along
// by penetration moves alone (far ball 0 m/s, the sixth at 0.5). touchingTolerance counts such
// a pair as touching. Every size, speed, gap and step here passes along, with either preset.
TEST_CASE("the collision passes along rows of any size, speed, gap and time step",
          "[restitution][cradle][micro]") {
  int runs = 0;
  for (const bool lecturePreset : {false, true}) {
    for (const double radius : {0.1, 0.5, 2.0}) {
      for (const double speed : {0.5, 2.0, 5.0}) {
        for (const double gap : {0.0, 1e-3, 0.05}) {
          for (const double dt : {1.0 / 30.0, 1.0 / 60.0, 1.0 / 240.0}) {
            for (int balls = 2; balls <= 10; ++balls) {
              Scene scene = cradle(balls, "micro", {gap, speed, radius, dt});
              if (lecturePreset) scene.solverSettings.micro = MicroCollisionSettings::lecture();
              // Until half a second after the striker reaches the row.
              const int steps = int(std::lround((gap / speed + 0.5) / dt)) + 2;
              INFO((lecturePreset ? "lecture preset, " : "")
                   << balls << " balls of radius " << radius << " struck at " << speed
                   << " m/s from " << gap << " m, dt " << dt);
              checkPassedAlong(runStrike(scene, steps), speed);
              ++runs;
            }
          }
        }
      }
    }
  }
  std::cout << "figure: " << runs << " cradles, every one passed along\n";
}

// Two or three balls striking together send as many out at the far end, as in a real cradle:
// the book's resolver recomputes a contact's bounce whenever it closes again, so when the second
// striker hits the first, stopped by its own bounce, that contact bounces once more and passes
// the second collision along behind the first. A point that had bounced once used to be only
// kept from closing: the rest of the row then moved off together (two strikers into three balls:
// far ball 2 m/s, the four balls behind it 0.333 m/s, a third of the energy lost).
TEST_CASE("two or three balls striking a row send as many out", "[restitution][cradle][micro]") {
  for (const bool lecturePreset : {false, true}) {
    for (const int strikers : {2, 3}) {
      for (const double dt : {1.0 / 30.0, kDt, 1.0 / 240.0}) {
        for (int balls = strikers; balls <= 8; ++balls) {
          Strike strike;
          strike.strikers = strikers;
          strike.dt = dt;
          Scene scene = cradle(balls, "micro", strike);
          if (lecturePreset) scene.solverSettings.micro = MicroCollisionSettings::lecture();
          INFO((lecturePreset ? "lecture preset, " : "")
               << strikers << " strikers into " << balls << " balls, dt " << dt);
          const int steps = int(std::lround((kStrikeGap / kStrikeSpeed + 0.5) / dt)) + 2;
          checkPassedAlong(runStrike(scene, steps, strikers), kStrikeSpeed);
        }
      }
    }
  }
}
