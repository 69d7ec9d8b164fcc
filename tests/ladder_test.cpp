// The ladder against a wall, the textbook's statics problem with two contacts: a plank of length L
// and thickness t leans at α against a frictionless wall, its foot on a floor of friction μ. Its
// weight, the floor's push N and friction F at the foot, and the wall's push W at the top are
// three unknowns for three equations (statically determinate): N = m g, F = W, and moments about
// the foot, W h = m g d, where d is the centre's distance from the foot along the floor and h the
// top's height above it. So it holds while μ ≥ F / N = d / h = cot α / 2 − t / (2 L), and slides
// below that, its foot out and its top down the wall, with accelerations the same three laws give
// once friction is μN against the slip.
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "exact_motion.h"
#include "lecture_scenes.h"
#include "solver_scenes.h"

using namespace impulse2d;

namespace {

constexpr double kLength = 4.0;     // m
constexpr double kThickness = 0.2;  // m

/// μ at which the ladder leaning at `angle` just holds: d / h.
double holdingFriction(double angle) {
  return 0.5 / std::tan(angle) - kThickness / (2.0 * kLength);
}

/// A floor of friction `friction` (top y = 0), a frictionless wall whose face is at
/// x = L cos α, and the plank leaning at `angle` between them, its foot corner at the origin and
/// its top corner on the wall, at rest (body 2), `lift` above that.
Scene ladderScene(const std::string& solver, double dt, double angle, double friction,
                  double lift = 0.0) {
  Scene scene = lecture::sceneWith(solver, dt);
  scene.bodies.push_back(lecture::ground(friction));
  BodyDef wall;
  wall.name = "wall";
  wall.type = BodyType::Static;
  wall.shape = makeBox(1.0, 20.0);
  wall.position = Vec2(kLength * std::cos(angle) + 0.5, 10.0);
  wall.friction = 0.0;  // μ mixes as √(μA μB): frictionless whatever the plank's
  scene.bodies.push_back(wall);
  BodyDef plank;
  plank.name = "ladder";
  plank.shape = makeBox(kLength, kThickness);
  plank.angle = angle;
  const Vec2 along(std::cos(angle), std::sin(angle));
  const Vec2 across(-std::sin(angle), std::cos(angle));
  plank.position = 0.5 * kLength * along + 0.5 * kThickness * across + Vec2(0.0, lift);
  plank.friction = friction;
  scene.bodies.push_back(plank);
  return scene;
}

/// rad/s². The ladder's angular acceleration while its foot slides out (friction μN towards the
/// wall) and its top slides down the wall, both staying in contact: Newton's and Euler's laws
/// with the two contact conditions (foot's vertical and top's horizontal acceleration zero,
/// centripetal terms included), five linear equations in the centre's acceleration, the angular
/// acceleration, N and W.
double slidingAngularAcceleration(double angle, double spin, double friction, double mass,
                                  double inertia) {
  const Vec2 along(std::cos(angle), std::sin(angle));
  const Vec2 across(-std::sin(angle), std::cos(angle));
  const Vec2 foot = -0.5 * kLength * along - 0.5 * kThickness * across;  // from the centre
  const Vec2 top = 0.5 * kLength * along - 0.5 * kThickness * across;
  Eigen::Matrix<double, 5, 5> equations = Eigen::Matrix<double, 5, 5>::Zero();
  Eigen::Matrix<double, 5, 1> right;  // unknowns: ax, ay, angular acceleration, N, W
  equations.row(0) << mass, 0.0, 0.0, -friction, 1.0;
  right(0) = 0.0;
  equations.row(1) << 0.0, mass, 0.0, -1.0, 0.0;
  right(1) = -mass * lecture::kGravity;
  equations.row(2) << 0.0, 0.0, inertia, -(foot.x() - friction * foot.y()), -top.y();
  right(2) = 0.0;
  equations.row(3) << 0.0, 1.0, foot.x(), 0.0, 0.0;
  right(3) = spin * spin * foot.y();
  equations.row(4) << 1.0, 0.0, -top.y(), 0.0, 0.0;
  right(4) = spin * spin * top.x();
  return equations.fullPivLu().solve(right)(2);
}

}  // namespace

TEST_CASE("a ladder holds when μ ≥ cot α / 2 − t / (2 L), the wall pushing m g (d / h)",
          "[friction][static][ladder]") {
  for (const std::string solver : {"micro", "sequential", "soft_step", "reference"}) {
    for (const double degrees : {45.0, 60.0, 70.0}) {
      for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
        for (const double lift : {0.0, 0.05}) {  // placed, or dropped 5 cm onto the floor
          const double angle = degrees * kPi / 180.0;
          const double friction = 1.1 * holdingFriction(angle);
          auto world = buildWorld(ladderScene(solver, dt, angle, friction, lift));
          const Body& ladder = world->bodies()[2];
          const double weight = lecture::kGravity / ladder.inverseMass;
          while (world->stepCount() * dt < 1.0) world->step();
          const Vec2 landed = ladder.position;
          while (world->stepCount() * dt < 5.0) world->step();
          // d / h from where it stands now (a drop may have turned it a little).
          const Vec2 along(std::cos(ladder.angle), std::sin(ladder.angle));
          const Vec2 across(-std::sin(ladder.angle), std::cos(ladder.angle));
          const Vec2 foot = ladder.position - 0.5 * kLength * along - 0.5 * kThickness * across;
          const Vec2 top = ladder.position + 0.5 * kLength * along - 0.5 * kThickness * across;
          const double leverRatio = (ladder.position.x() - foot.x()) / (top.y() - foot.y());
          const double wallPush = solvers::contactForce(*world, 2, 1);   // N
          const double floorPush = solvers::contactForce(*world, 2, 0);  // N, normal only
          INFO(solver << ", " << degrees << "°, dt " << dt << ", dropped " << lift << " m: moved "
                      << (ladder.position - landed).norm() << " m from 1 s to 5 s, wall "
                      << wallPush / weight << " m g (analytic " << leverRatio << "), floor "
                      << floorPush / weight << " m g");
          CHECK((ladder.position - landed).norm() < 1e-3);
          // Statically determinate: every method's forces are the textbook's, to the 2 % the
          // stacks are held to (measured within 0.4 %).
          CHECK(wallPush == Approx(weight * leverRatio).epsilon(0.02));
          CHECK(floorPush == Approx(weight).epsilon(0.02));
        }
      }
    }
  }
}

// Sliding from rest, the ladder turns down as the two-contact equations say. Semi-implicit Euler
// lags a motion of constant angular acceleration by half its spin times dt, so the angle after
// 0.3 s is held to the exact one within the spin then times dt.
TEST_CASE("a ladder below its friction slides foot out, top down, as the two contacts dictate",
          "[friction][dynamic][ladder]") {
  const double seconds = 0.3;
  for (const double degrees : {45.0, 60.0, 70.0}) {
    for (const double share : {0.0, 0.5, 0.9}) {  // of the friction that would hold it
      const double angle = degrees * kPi / 180.0;
      const double friction = share * holdingFriction(angle);
      const Body plank = buildBodies(ladderScene("sequential", 1.0 / 60.0, angle, friction))[2];
      const auto acceleration = [&](double turnedTo, double spin) {
        return slidingAngularAcceleration(turnedTo, spin, friction, 1.0 / plank.inverseMass,
                                          1.0 / plank.inverseInertia);
      };
      const exact::Turn expected = exact::turnAfter({angle, 0.0}, seconds, 1e-3, acceleration);
      for (const std::string solver : {"micro", "sequential", "soft_step", "reference"}) {
        for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
          auto world = buildWorld(ladderScene(solver, dt, angle, friction));
          const Body& ladder = world->bodies()[2];
          while (world->stepCount() * dt < seconds - 0.5 * dt) world->step();
          INFO(solver << ", " << degrees << "°, μ " << share << " of d/h, dt " << dt << ": angle "
                      << ladder.angle << " rad at " << seconds << " s, exact " << expected.angle
                      << " (from " << angle << ")");
          // It does slide, and by more than the tolerance allows either way.
          CHECK(angle - expected.angle > 3.0 * std::abs(expected.spin) * dt);
          CHECK(std::abs(ladder.angle - expected.angle) < std::abs(expected.spin) * dt);
        }
      }
    }
  }
}
