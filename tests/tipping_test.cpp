// Tipping on a slope: a box held by friction (μ = 1, above every tan θ here) stands while the
// vertical through its centre of mass falls inside its base, i.e. while tan θ < w / h, and tips
// over once it falls outside. Not a friction fact but a torque one: gravity's moment about the
// downhill corner against the contact impulses', which every method must get from the contact
// points and arms. Each box is tried 2° either side of atan(w / h), placed on the slope and
// dropped onto it from 2 cm.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "lecture_scenes.h"

using namespace impulse2d;

namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kPi = 3.14159265358979323846;
constexpr double kFriction = 1.0;

struct TippingRun {
  double largestTurn = 0.0;  ///< rad, the most the box turned from the slope at any step
  double finalTurn = 0.0;    ///< rad, after 4 s
  double slid = 0.0;         ///< m along the slope from t = 1 s (landed) to 4 s
};

TippingRun runTipping(const std::string& solver, const Vec2& size, double angle, double lift) {
  Scene scene = lecture::sceneWith(solver, kDt);
  scene.bodies.push_back(lecture::ground(kFriction, angle));
  scene.bodies.push_back(lecture::boxOnSlope(size, angle, kFriction, lift));
  auto world = buildWorld(scene);
  Vec2 landed = Vec2::Zero();
  TippingRun run;
  for (int step = 1; step <= 240; ++step) {
    world->step();
    if (step == 60) landed = world->bodies()[1].position;
    run.largestTurn = std::max(run.largestTurn, std::abs(world->bodies()[1].angle - angle));
  }
  run.finalTurn = world->bodies()[1].angle - angle;
  run.slid = (world->bodies()[1].position - landed).dot(lecture::downSlope(angle));
  return run;
}

}  // namespace

TEST_CASE("a tall box on a slope stands while tan θ < w / h and tips over beyond it",
          "[tipping][slope]") {
  for (const std::string solver : {"micro", "sequential", "soft_step", "reference"}) {
    for (const Vec2& size : {Vec2(0.5, 2.0), Vec2(0.6, 1.2)}) {
      const double tippingAngle = std::atan(size.x() / size.y());  // 14.0° and 26.6°
      for (const double lift : {0.0, 0.02}) {
        const double margin = 2.0 * kPi / 180.0;  // rad either side of the tipping angle
        const double below = tippingAngle - margin;
        const TippingRun stands = runTipping(solver, size, below, lift);
        INFO(solver << ", " << size.x() << " x " << size.y() << ", lift " << lift << ", "
                    << below * 180.0 / kPi << " deg: turned at most " << stands.largestTurn
                    << " rad, " << stands.finalTurn << " rad at the end, slid " << stands.slid
                    << " m after landing");
        // Turned by the margin about its downhill corner it would be past tipping: it must rock
        // less (soft step's compliant landing rocks it 0.012 rad), and end level on its face to
        // 1e-3 rad (half a millimetre across the narrower base), not sliding.
        CHECK(stands.largestTurn < margin);
        CHECK(std::abs(stands.finalTurn) < 1e-3);
        CHECK(std::abs(stands.slid) < 1e-3);
        const double beyond = tippingAngle + margin;
        const TippingRun tips = runTipping(solver, size, beyond, lift);
        INFO(beyond * 180.0 / kPi << " deg: turned " << tips.finalTurn << " rad");
        CHECK(std::abs(tips.finalTurn) == Approx(kPi / 2.0).margin(0.01));  // on its side
      }
    }
  }
}
