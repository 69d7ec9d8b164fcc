// Inputs the fuzzers (fuzz/, docs/hardening.md) found, each kept as the fact it broke: a scene the
// loader accepted but the engine could not simulate, and contact pairs at the edge of collide()'s
// promises. The same inputs are in the seed corpus under tests/fuzz_corpus/.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "impulse2d/collide.h"
#include "impulse2d/scene/scene_file.h"

using namespace impulse2d;

namespace {

/// The message parseScene rejects the text with; empty when it loads.
std::string rejection(const std::string& text) {
  try {
    parseScene(text, "found.toml");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

bool simulable(const Body& body) {
  return std::isfinite(body.inverseMass) && body.inverseMass > 0.0 &&
         std::isfinite(body.inverseInertia) && body.inverseInertia > 0.0;
}

Body box(double width, double height, const Vec2& position, double angle) {
  return makeBody("box", BodyType::Dynamic, makeBox(width, height), 1.0, position, angle);
}

/// m. Round-off allowed between anchors and penetration for coordinates of about 10 m.
constexpr double kTolerance = 1e-9;

void checkAnchorsAgree(const Body& a, const Body& b, const Manifold& manifold) {
  for (int i = 0; i < manifold.pointCount; ++i) {
    const ContactPoint& point = manifold.points[i];
    const Vec2 apart = a.toWorld(point.anchorA) - b.toWorld(point.anchorB);
    CHECK((apart - point.penetration * manifold.normal).norm() < kTolerance);
  }
}

/// m. The deepest point's penetration.
double deepest(const Manifold& manifold) {
  double depth = -INFINITY;
  for (int i = 0; i < manifold.pointCount; ++i) {
    depth = std::max(depth, manifold.points[i].penetration);
  }
  return depth;
}

}  // namespace

TEST_CASE("a body whose mass overflows or underflows is rejected where it is written",
          "[fuzz][scene]") {
  // Each number is finite and in range; their products are not. Before, these loaded with an
  // infinite mass, or a zero mass and so an infinite inverse mass, and the first step gave NaN.
  CHECK(rejection("[[body]]\nshape = \"circle\"\nradius = 1e200\n")
            .rfind("found.toml:1:1: body 'body0' has mass inf kg", 0) == 0);
  CHECK(rejection("[[body]]\nshape = \"box\"\nsize = [1e-320, 1e-320]\n")
            .rfind("found.toml:1:1: body 'body0' has mass 0 kg", 0) == 0);
  CHECK(rejection("[[body]]\nname = \"speck\"\nshape = \"circle\"\nradius = 1e-170\n")
            .find("2:8: body 'speck' has mass") != std::string::npos);
  const Scene ordinary = parseScene("[[body]]\nshape = \"circle\"\nradius = 1e-3\n", "s.toml");
  CHECK(simulable(buildBodies(ordinary).front()));
}

TEST_CASE("a generator that places boxes at infinity or makes them too heavy is rejected",
          "[fuzz][scene]") {
  // Box k of a stack is at base + k * level_offset: 1e308 + 1e308 overflows.
  CHECK(
      rejection("[[stack]]\ncount = 3\nsize = [1, 1]\nbase = [1e308, 0]\nlevel_offset = 1e308\n") ==
      "found.toml:1:1: body 'box1' is placed at a non-finite position; its numbers are too large");
  // A 1e308 m box has a finite mass, but its moment of inertia overflows (to NaN: inf − inf).
  const std::string heavy = rejection(
      "[[body]]\nshape = \"circle\"\nradius = 1\n"
      "[[pyramid]]\nrows = 3\nsize = [1e308, 1]\nbase = [0, 0]\n");
  CHECK(heavy.rfind("found.toml:4:1: body 'box1' has mass 1e+308 kg and moment of inertia ", 0) ==
        0);
}

TEST_CASE("two circles on one centre touch along +y in either order", "[fuzz][collide]") {
  // Their direction is undefined (collide.cpp: kCoincidentCentres); the fallback normal is +y
  // whichever is A, so swapping them does not negate it, unlike every other pair.
  const Body a = makeBody("a", BodyType::Dynamic, makeCircle(0.01), 1.0, Vec2(-10, -10), 0.0);
  const Body b = a;
  Manifold ab;
  Manifold ba;
  REQUIRE(collide(a, b, 0.0, ab) == 1);
  REQUIRE(collide(b, a, 0.0, ba) == 1);
  CHECK(ab.normal == Vec2(0.0, 1.0));
  CHECK(ba.normal == Vec2(0.0, 1.0));
  CHECK(ab.points[0].penetration == Approx(0.02));
}

TEST_CASE("two thin boxes lying on each other keep their anchors a penetration apart",
          "[fuzz][collide]") {
  // Found by the collide fuzzer: 10 m and 9.14 m long, 1 cm thick, nearly on one centre and turned
  // half a turn. Each box's own face separates least, so the two orders choose faces of different
  // bodies and both normals point the same way; each manifold is still consistent.
  const Body a = box(9.9999994045535736, 0.01, Vec2(-9.9996960256248713, -9.9999999999272404),
                     -3.1414967797905722);
  const Body b = box(9.1413319397146218, 0.01, Vec2(-10.0, -10.0), -kPi);
  Manifold ab;
  Manifold ba;
  REQUIRE(collide(a, b, 0.0, ab) == 2);
  REQUIRE(collide(b, a, 0.0, ba) == 2);
  CHECK(ab.normal.norm() == Approx(1.0));
  CHECK(ba.normal.norm() == Approx(1.0));
  checkAnchorsAgree(a, b, ab);
  checkAnchorsAgree(b, a, ba);
  CHECK(ab.points[0].id != ab.points[1].id);
}

TEST_CASE("two crossing slivers may take their normals from different bodies' faces",
          "[fuzz][collide]") {
  // Found by the collide fuzzer in CI: a 0.6 m pentagon 1 cm thick and a 7.2 m triangle 2 cm
  // wide, both nearly upright, crossing at their ends. A's face and B's face separate them by
  // 0.30 and 0.21 mm, within kReferenceFaceTolerance of each other, so each order keeps its first
  // body's face, and both normals point the same way (-x): each sliver's tip pokes out of the
  // other on the same side. Each manifold is still consistent.
  const Body a = makeBody("a", BodyType::Dynamic,
                          makePolygon({{0.32836302270559314, -0.005235393188804385},
                                       {0.0048101550504930108, 0.0047646068202814671},
                                       {-0.12130618207876664, 0.0039736620003989181},
                                       {-0.22747230649839623, 0.001725946279703623},
                                       {-0.27937374890091721, -0.00045471514498021323}})
                              .shape,
                          1.0, Vec2(-4.9019607843137258, -4.9019607843137258), -1.5399963988185261);
  const Body b = makeBody("b", BodyType::Dynamic,
                          makePolygon({{0.012397371030366701, 2.3234811047444111},
                                       {-0.0076795852370288541, 2.4461927428346071},
                                       {-0.0047177857933378455, -4.7696738475790177}})
                              .shape,
                          1.0, Vec2(-4.9019607854980052, -9.9800857808441634), 3.1415926535897931);
  Manifold ab;
  Manifold ba;
  REQUIRE(collide(a, b, 0.0, ab) >= 1);
  REQUIRE(collide(b, a, 0.0, ba) >= 1);
  CHECK(std::abs(deepest(ab) - deepest(ba)) <= kReferenceFaceTolerance);
  CHECK(ab.normal.dot(ba.normal) > 0.0);
  checkAnchorsAgree(a, b, ab);
  checkAnchorsAgree(b, a, ba);
}
