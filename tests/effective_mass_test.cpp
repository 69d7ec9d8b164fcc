// The impulse per unit of velocity change: the closed form against the text's unit-impulse probe
// ("apply a unit impulse to copies of the bodies and measure the relative velocity again").
#include <catch2/catch.hpp>

#include "impulse2d/solvers/contact_math.h"

using namespace impulse2d;

namespace {

/// The probe, done literally on copies: +d on B and −d on A at the point, then the change of the
/// relative velocity along d.
double probeUnitImpulse(Body a, Body b, const Vec2& point, const Vec2& direction) {
  const double before = relativeVelocity(a, b, point, direction);
  a.applyImpulse(-direction, point);
  b.applyImpulse(direction, point);
  return relativeVelocity(a, b, point, direction) - before;
}

/// Two rotated boxes of different sizes and densities, moving and spinning, and a contact point
/// off both centres.
struct RotatedPair {
  Body a = makeBody("a", BodyType::Dynamic, makeBox(2.0, 0.7), 1.3, Vec2(0.2, -0.4), 0.7);
  Body b = makeBody("b", BodyType::Dynamic, makeBox(0.9, 1.6), 0.6, Vec2(0.9, 1.1), -1.2);
  Vec2 point = Vec2(0.65, 0.35);
  RotatedPair() {
    a.velocity = Vec2(0.3, -1.0);
    a.angularVelocity = 2.0;
    b.velocity = Vec2(-0.5, 0.2);
    b.angularVelocity = -0.7;
  }
};

/// Relative round-off of a handful of products on numbers of order 1.
constexpr double kRoundOff = 1e-12;

}  // namespace

TEST_CASE("closed-form unit-impulse response equals the probe on rotated off-centre contacts",
          "[effective_mass][probe]") {
  const RotatedPair pair;
  for (double normalAngle : {0.3, 1.9, -2.4}) {
    const Vec2 normal(std::cos(normalAngle), std::sin(normalAngle));
    for (const Vec2& direction : {normal, leftPerpendicular(normal)}) {
      const double closedForm = unitImpulseResponse(pair.a, pair.b, pair.point, direction);
      const double probe = probeUnitImpulse(pair.a, pair.b, pair.point, direction);
      CHECK(closedForm == Approx(probe).epsilon(kRoundOff));
    }
  }
}

TEST_CASE("against a static body only the dynamic body responds", "[effective_mass][probe]") {
  const RotatedPair pair;
  const Body ground =
      makeBody("ground", BodyType::Static, makeBox(10.0, 1.0), 1.0, Vec2(0.0, -2.0), 0.1);
  const Vec2 normal(std::sin(0.1), std::cos(0.1));
  const double closedForm = unitImpulseResponse(ground, pair.a, pair.point, normal);
  CHECK(closedForm ==
        Approx(probeUnitImpulse(ground, pair.a, pair.point, normal)).epsilon(kRoundOff));
  const Vec2 arm = pair.point - pair.a.position;
  CHECK(closedForm ==
        Approx(pair.a.inverseMass + pair.a.inverseInertia * cross(arm, normal) * cross(arm, normal))
            .epsilon(kRoundOff));
}

TEST_CASE("an impulse through the centre of mass only moves the body: response 1/m",
          "[effective_mass]") {
  const RotatedPair pair;
  const Body ground =
      makeBody("ground", BodyType::Static, makeBox(10.0, 1.0), 1.0, Vec2(0.0, -2.0), 0.0);
  const double response = unitImpulseResponse(ground, pair.b, pair.b.position, Vec2(0.0, 1.0));
  CHECK(response == Approx(1.0 / pair.b.mass).epsilon(kRoundOff));
}

TEST_CASE("the response between two points is reciprocal (Maxwell–Betti)", "[effective_mass]") {
  const RotatedPair pair;
  const Vec2 other(1.1, 0.9);
  const Vec2 d1(0.6, 0.8);
  const Vec2 d2(-0.28, 0.96);
  CHECK(velocityPerUnitImpulse(pair.b, pair.point, d1, other, d2) ==
        Approx(velocityPerUnitImpulse(pair.b, other, d2, pair.point, d1)).epsilon(kRoundOff));
}
