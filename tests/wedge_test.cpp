// A block on a free wedge, the textbook's problem of two moving bodies in contact: a block of mass
// m on the slope θ of a wedge of mass M that stands on frictionless ground. Without friction the
// wedge's push N on the block is normal to the slope, and momentum along the ground is kept, so
// Newton's laws for both bodies with the block staying on the slope give constant accelerations:
// the wedge recoils at A = m g sin θ cos θ / (M + m sin² θ) and the block slides down the slope,
// relative to the wedge, at a = (M + m) g sin θ / (M + m sin² θ). Both bodies move, so a method
// must share every impulse between them through the contact's effective mass; a static slope
// (the slope tests) never checks that. With friction above tan θ the block sticks and nothing
// moves at all: no force along the ground acts on the pair.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "lecture_scenes.h"

using namespace impulse2d;

namespace {

constexpr double kWedgeMass = 1.0;    // kg
constexpr double kWedgeBase = 3.0;    // m
constexpr double kDrop = 0.015;       // m above the slope, for the runs that land first
constexpr double kFirstSample = 0.2;  // s: a dropped block has landed by then (0.055 s to fall)
constexpr double kLastSample = 0.45;  // s: the block is still on the slope

constexpr int kWedge = 1;
constexpr int kBlock = 2;

/// A frictionless ground, a right-angled wedge (mass kWedgeMass) whose slope of `angle` falls
/// towards +x from its upright side at x = 0, and a block (`size`, mass `ratio` · kWedgeMass) at
/// rest half way down that slope, `lift` above it. Both have friction `friction`; the ground has
/// none, so only the block's contact with the wedge has friction.
Scene wedgeScene(const std::string& solver, double dt, double angle, double ratio, double friction,
                 const Vec2& size, double lift) {
  Scene scene = lecture::sceneWith(solver, dt);
  scene.bodies.push_back(lecture::ground(0.0));
  const double height = kWedgeBase * std::tan(angle);
  const CentredPolygon triangle =
      makePolygon({Vec2(0.0, 0.0), Vec2(kWedgeBase, 0.0), Vec2(0.0, height)});
  BodyDef wedge;
  wedge.name = "wedge";
  wedge.shape = triangle.shape;
  wedge.position = triangle.centroid;
  wedge.density = kWedgeMass / (0.5 * kWedgeBase * height);
  wedge.friction = friction;
  scene.bodies.push_back(wedge);
  const Vec2 down(std::cos(angle), -std::sin(angle));
  const Vec2 normal(std::sin(angle), std::cos(angle));
  BodyDef block;
  block.name = "block";
  block.shape = makeBox(size.x(), size.y());
  block.angle = -angle;
  block.position = Vec2(0.0, height) + 0.5 * kWedgeBase / std::cos(angle) * down +
                   (0.5 * size.y() + lift) * normal;
  block.density = ratio * kWedgeMass / (size.x() * size.y());
  block.friction = friction;
  scene.bodies.push_back(block);
  return scene;
}

struct Accelerations {
  double wedge = 0.0;  ///< m/s² along the ground
  double block = 0.0;  ///< m/s² down the slope, relative to the wedge
};

Accelerations exactAccelerations(double angle, double ratio) {
  const double m = ratio * kWedgeMass;
  const double sin = std::sin(angle);
  const double shared = kWedgeMass + m * sin * sin;
  return {-m * lecture::kGravity * sin * std::cos(angle) / shared,
          (kWedgeMass + m) * lecture::kGravity * sin / shared};
}

/// The accelerations between kFirstSample and kLastSample, from the velocities then.
Accelerations measuredAccelerations(World& world, double dt, double angle) {
  const Vec2 down(std::cos(angle), -std::sin(angle));
  const auto velocities = [&] {
    const Vec2 wedge = world.bodies()[kWedge].velocity;
    return Accelerations{wedge.x(), (world.bodies()[kBlock].velocity - wedge).dot(down)};
  };
  while (world.stepCount() < std::lround(kFirstSample / dt)) world.step();
  const Accelerations first = velocities();
  while (world.stepCount() < std::lround(kLastSample / dt)) world.step();
  const Accelerations last = velocities();
  const double span = kLastSample - kFirstSample;
  return {(last.wedge - first.wedge) / span, (last.block - first.block) / span};
}

}  // namespace

// Placed on the slope and dropped onto it, at 20°, 30° and 45°, with the block a fifth of the
// wedge's mass, equal to it and five times it. The accelerations are constant, which semi-implicit
// Euler integrates exactly, so the only error left is the solver's: micro stops once every
// contact closes by less than its velocity epsilon ε (1e-4 m/s). A normal impulse δP short at the
// slope changes that closing speed by δP (1/m + sin² θ / M) and the wedge's speed by
// δP sin θ / M, so the wedge may be off by ε m sin θ / (M + m sin² θ), and the block's speed
// along the slope relative to it by that times cos θ; the ground's own contacts add at most ε.
// Each velocity sample may be off so, hence the bound on an acceleration over the 0.25 s between
// them. Measured at most 0.48 of it (micro, landed), 1e-6 m/s² (sequential impulses) and 0 (the
// reference).
TEST_CASE("a block on a free frictionless wedge pushes it back at m g sin θ cos θ / (M + m sin² θ)",
          "[wedge][contact]") {
  const double epsilon = MicroCollisionSettings{}.velocityEpsilon;  // m/s
  for (const std::string solver : {"micro", "sequential", "reference"}) {
    for (const double degrees : {20.0, 30.0, 45.0}) {
      for (const double ratio : {0.2, 1.0, 5.0}) {
        for (const double lift : {0.0, kDrop}) {
          for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
            const double angle = degrees * kPi / 180.0;
            auto world =
                buildWorld(wedgeScene(solver, dt, angle, ratio, 0.0, Vec2(0.4, 0.4), lift));
            const Accelerations measured = measuredAccelerations(*world, dt, angle);
            const Accelerations exact = exactAccelerations(angle, ratio);
            const double m = ratio * kWedgeMass;
            const double share =
                m * std::sin(angle) / (kWedgeMass + m * std::pow(std::sin(angle), 2));
            const double bound = 2.0 * epsilon * (1.0 + share) / (kLastSample - kFirstSample);
            INFO(solver << ", " << degrees << "°, m / M = " << ratio << ", dropped " << lift
                        << " m, dt " << dt << ": wedge " << measured.wedge << " (exact "
                        << exact.wedge << "), block " << measured.block << " (exact " << exact.block
                        << ") m/s²");
            CHECK(measured.wedge == Approx(exact.wedge).margin(bound));
            CHECK(measured.block == Approx(exact.block).margin(bound));
          }
        }
      }
    }
  }
}

// The same wedges with friction 1.2 tan θ on the block's contact: it sticks, so the pair is one
// rigid body on frictionless ground that no horizontal force acts on, and stays at rest. The
// block is flat (0.8 × 0.2): a square block at 45° would stand on its tipping edge, its uphill
// corner carrying nothing (w / h = tan θ), where any disturbance tips it. Held to the slope
// tests' bound, half a millimetre in 2 s (measured 3e-5 m for micro, 2e-5 m for sequential
// impulses, 0 for the reference).
TEST_CASE("a block sticking to a free wedge on frictionless ground keeps both at rest",
          "[wedge][friction]") {
  for (const std::string solver : {"micro", "sequential", "reference"}) {
    for (const double degrees : {20.0, 30.0, 45.0}) {
      for (const double ratio : {0.2, 1.0, 5.0}) {
        for (const double lift : {0.0, kDrop}) {
          const double dt = 1.0 / 60.0;
          const double angle = degrees * kPi / 180.0;
          auto world = buildWorld(
              wedgeScene(solver, dt, angle, ratio, 1.2 * std::tan(angle), Vec2(0.8, 0.2), lift));
          while (world->stepCount() * dt < 0.5) world->step();  // landed
          const Vec2 wedge = world->bodies()[kWedge].position;
          const Vec2 block = world->bodies()[kBlock].position;
          while (world->stepCount() * dt < 2.5) world->step();
          const double wedgeMoved = (world->bodies()[kWedge].position - wedge).norm();
          const double blockMoved = (world->bodies()[kBlock].position - block).norm();
          INFO(solver << ", " << degrees << "°, m / M = " << ratio << ", dropped " << lift
                      << " m: wedge moved " << wedgeMoved << " m, block " << blockMoved << " m");
          CHECK(wedgeMoved < 0.5e-3);
          CHECK(blockMoved < 0.5e-3);
        }
      }
    }
  }
}
