// The position pass (position_correction.h) that sequential impulses and the reference share:
// non-linear Gauss–Seidel on penetrations. It removes a fixed fraction of the overlap beyond the
// slop per sweep, caps each correction, splits a correction by inverse mass, never touches
// velocities, and corrects a flat contact's corners together so neither is favoured.
#include <catch2/catch.hpp>

#include <cmath>

#include "impulse2d/collide.h"
#include "impulse2d/solvers/contact_math.h"
#include "impulse2d/solvers/position_correction.h"
#include "solver_scenes.h"

using namespace impulse2d;
using namespace solvers;

namespace {

constexpr double kOverlap = 0.05;  ///< m

/// Two bodies and the manifold between them, as a position pass sees them after integration.
struct Overlap {
  std::vector<Body> bodies;
  std::vector<Manifold> manifolds = std::vector<Manifold>(1);

  double penetration(int point) const {
    return currentPenetration(bodies[0], bodies[1], manifolds[0], point);
  }
  void correct(const PositionPassSettings& pass, double slop) {
    correctPositions(StepContext{bodies, manifolds, kDt}, pass, slop,
                     BlockSolveSettings{}.conditionLimit);
  }
};

/// A unit box (body 1) whose bottom face sits `overlap` below the top of body 0: the ground, or
/// with `lowerDensity` > 0 another unit box of that density.
Overlap boxSunkInto(double overlap, double lowerDensity = 0.0) {
  Scene scene = groundScene("sequential", 0.6);
  if (lowerDensity > 0.0) {
    scene.bodies[0] = unitBoxMaterial(0.6);
    scene.bodies[0].shape = makeBox(1.0, 1.0);
    scene.bodies[0].density = lowerDensity;
    scene.bodies[0].position = Vec2(0.0, -0.5);
  }
  BodyDef box = unitBoxMaterial(0.6);
  box.shape = makeBox(1.0, 1.0);
  box.position = Vec2(0.0, 0.5 - overlap);
  scene.bodies.push_back(box);
  Overlap result{buildBodies(scene)};
  result.manifolds[0].bodyA = 0;
  result.manifolds[0].bodyB = 1;
  REQUIRE(collide(result.bodies[0], result.bodies[1], 0.005, result.manifolds[0]) == 2);
  return result;
}

}  // namespace

TEST_CASE("each sweep removes the correction factor of the overlap beyond the slop",
          "[position][geometric]") {
  Overlap overlap = boxSunkInto(kOverlap);
  const PositionPassSettings pass;
  const double slop = ContactTargetSettings{}.allowedPenetration;
  overlap.correct(pass, slop);
  const double remaining =
      slop + (kOverlap - slop) * std::pow(1.0 - pass.correctionFactor, pass.iterations);
  for (int i = 0; i < 2; ++i) CHECK(overlap.penetration(i) == Approx(remaining).epsilon(1e-9));
  SECTION("and adds no velocity") {
    CHECK(overlap.bodies[1].velocity.norm() == 0.0);
    CHECK(overlap.bodies[1].angularVelocity == 0.0);
  }
}

TEST_CASE("the slop is left alone and zero sweeps move nothing", "[position][slop]") {
  const double slop = ContactTargetSettings{}.allowedPenetration;
  Overlap withinSlop = boxSunkInto(0.5 * slop);
  const Vec2 before = withinSlop.bodies[1].position;
  withinSlop.correct(PositionPassSettings{}, slop);
  CHECK(withinSlop.bodies[1].position == before);

  Overlap deep = boxSunkInto(kOverlap);
  PositionPassSettings off;
  off.iterations = 0;
  deep.correct(off, slop);
  CHECK(deep.penetration(0) == Approx(kOverlap).epsilon(1e-12));
}

TEST_CASE("one sweep corrects a deep overlap by at most the largest correction",
          "[position][cap]") {
  Overlap overlap = boxSunkInto(0.5);
  PositionPassSettings pass;
  pass.iterations = 1;
  pass.correctionFactor = 1.0;
  overlap.correct(pass, 0.0);
  for (int i = 0; i < 2; ++i) {
    CHECK(overlap.penetration(i) == Approx(0.5 - pass.maxCorrection).epsilon(1e-9));
  }
}

TEST_CASE("a correction between two bodies is split in inverse proportion to their masses",
          "[position][mass]") {
  constexpr double kLowerDensity = 3.0;
  Overlap overlap = boxSunkInto(kOverlap, kLowerDensity);
  const Vec2 lowerBefore = overlap.bodies[0].position;
  const Vec2 upperBefore = overlap.bodies[1].position;
  overlap.correct(PositionPassSettings{}, 0.0);
  const double lowerMove = (overlap.bodies[0].position - lowerBefore).y();
  const double upperMove = (overlap.bodies[1].position - upperBefore).y();
  REQUIRE(upperMove > 0.0);
  // The centre of mass stays put, as a pair of equal and opposite impulses would leave it.
  CHECK(kLowerDensity * lowerMove + upperMove == Approx(0.0).margin(1e-12));
  CHECK(overlap.bodies[1].angle == Approx(0.0).margin(1e-12));
}

TEST_CASE("the block correction treats both corners alike; one at a time favours the first",
          "[position][block]") {
  const double slop = ContactTargetSettings{}.allowedPenetration;
  PositionPassSettings pass;
  pass.iterations = 1;
  Overlap together = boxSunkInto(kOverlap);
  together.correct(pass, slop);
  CHECK(together.penetration(0) == Approx(together.penetration(1)).margin(1e-12));
  CHECK(together.bodies[1].angle == Approx(0.0).margin(1e-12));

  PositionPassSettings apart = pass;
  apart.blockSolve = false;
  Overlap oneByOne = boxSunkInto(kOverlap);
  oneByOne.correct(apart, slop);
  // Pushing one corner of a unit box (arms (±0.5, −0.5), m = 1, I = 1/6) moves the other by
  // K01/K00 = (1 − 6·0.25)/(1 + 6·0.25) = −0.2 of the push: the first corner's correction sinks
  // the second deeper, whose correction then sinks the first. Worked through once:
  const double f = pass.correctionFactor;
  const double first = f * (kOverlap - slop);
  const double secondDepth = kOverlap + 0.2 * first;
  const double second = f * (secondDepth - slop);
  const double tilt = (kOverlap - first + 0.2 * second) - (secondDepth - second);
  CHECK(oneByOne.penetration(0) - oneByOne.penetration(1) == Approx(tilt).epsilon(0.03));
  CHECK(std::abs(oneByOne.bodies[1].angle) > 0.5 * tilt);
}
