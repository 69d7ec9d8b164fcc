// The narrow phase: normal direction (from A to B), depth, point count, anchors, the speculative
// margin and feature ids, for every pair of shapes, following the sign convention of contact.h.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "impulse2d/collide.h"

using namespace impulse2d;

namespace {

/// m. The world's default contact margin.
constexpr double kMargin = 0.005;
/// m. Round-off of a handful of double operations on lengths of order 1 m.
constexpr double kExact = 1e-12;

/// A 20 m × 1 m static slab whose top face is the line y = 0.
Body ground() {
  return makeBody("ground", BodyType::Static, makeBox(20.0, 1.0), 0.0, Vec2(0.0, -0.5), 0.0);
}

Body box(double width, double height, const Vec2& position, double angle = 0.0) {
  return makeBody("box", BodyType::Dynamic, makeBox(width, height), 1.0, position, angle);
}

Body circle(double radius, const Vec2& position) {
  return makeBody("circle", BodyType::Dynamic, makeCircle(radius), 1.0, position, 0.0);
}

/// A polygon body from vertices given in the world frame at angle 0: its position is their
/// centroid, so the vertices land where they were given.
Body polygon(const std::vector<Vec2>& worldVertices) {
  const CentredPolygon centred = makePolygon(worldVertices);
  return makeBody("polygon", BodyType::Dynamic, centred.shape, 1.0, centred.centroid, 0.0);
}

Manifold collideOnce(const Body& a, const Body& b, double margin = kMargin) {
  Manifold manifold;
  const int count = collide(a, b, margin, manifold);
  REQUIRE(count == manifold.pointCount);
  return manifold;
}

bool near(const Vec2& actual, const Vec2& expected, double tolerance = kExact) {
  return (actual - expected).norm() <= tolerance;
}

/// The anchors are the two surface points: B's lies penetration·n behind A's along the normal
/// (pA − pB = d·n, so an overlap d > 0 puts B's surface point on A's side), and the point where
/// impulses act is midway between them.
void checkAnchorsMapBack(const Body& a, const Body& b, const Manifold& manifold) {
  CHECK(manifold.normal.norm() == Approx(1.0).margin(kExact));
  for (int i = 0; i < manifold.pointCount; ++i) {
    const ContactPoint& point = manifold.points[i];
    const Vec2 onA = a.toWorld(point.anchorA);
    const Vec2 onB = b.toWorld(point.anchorB);
    CHECK(near(onB - onA, -point.penetration * manifold.normal));
    CHECK(near(point.point, 0.5 * (onA + onB)));
  }
}

/// Swapping A and B turns the normal round and keeps the depths and the world points.
void checkSwapSymmetry(const Body& a, const Body& b) {
  const Manifold forward = collideOnce(a, b);
  const Manifold backward = collideOnce(b, a);
  REQUIRE(backward.pointCount == forward.pointCount);
  CHECK(near(backward.normal, -forward.normal));
  checkAnchorsMapBack(b, a, backward);
  for (int i = 0; i < forward.pointCount; ++i) {
    bool matched = false;
    for (int j = 0; j < backward.pointCount; ++j) {
      matched =
          matched ||
          (near(forward.points[i].point, backward.points[j].point) &&
           std::abs(forward.points[i].penetration - backward.points[j].penetration) <= kExact);
    }
    CHECK(matched);
  }
}

std::vector<FeatureId> ids(const Manifold& manifold) {
  std::vector<FeatureId> result;
  for (int i = 0; i < manifold.pointCount; ++i) result.push_back(manifold.points[i].id);
  return result;
}

}  // namespace

TEST_CASE("overlapping circles touch along the line of centres", "[contact][circle]") {
  const Body a = circle(1.0, Vec2(0.0, 0.0));
  const Body b = circle(0.75, Vec2(1.5, 0.5));
  const double distance = std::sqrt(1.5 * 1.5 + 0.5 * 0.5);
  const Manifold manifold = collideOnce(a, b);
  REQUIRE(manifold.pointCount == 1);
  CHECK(near(manifold.normal, Vec2(1.5, 0.5) / distance));
  CHECK(manifold.points[0].penetration == Approx(1.75 - distance).margin(kExact));
  CHECK(manifold.points[0].id == 0);
  checkAnchorsMapBack(a, b, manifold);
  CHECK(near(a.toWorld(manifold.points[0].anchorA), a.position + 1.0 * manifold.normal));
  checkSwapSymmetry(a, b);
}

TEST_CASE("circles: a gap within the margin is a speculative point, beyond it none",
          "[contact][circle][margin]") {
  const Body a = circle(0.5, Vec2(0.0, 0.0));
  const Manifold within = collideOnce(a, circle(0.5, Vec2(1.003, 0.0)));
  REQUIRE(within.pointCount == 1);
  CHECK(within.points[0].penetration == Approx(-0.003).margin(kExact));
  CHECK(collideOnce(a, circle(0.5, Vec2(1.006, 0.0))).pointCount == 0);
}

TEST_CASE("a circle resting on a box touches the face under it", "[contact][circle][polygon]") {
  const Body slab = ground();
  const Body ball = circle(0.5, Vec2(0.3, 0.49));
  const Manifold manifold = collideOnce(slab, ball);
  REQUIRE(manifold.pointCount == 1);
  CHECK(near(manifold.normal, Vec2(0.0, 1.0)));
  CHECK(manifold.points[0].penetration == Approx(0.01).margin(kExact));
  CHECK(near(slab.toWorld(manifold.points[0].anchorA), Vec2(0.3, 0.0)));
  CHECK(near(ball.toWorld(manifold.points[0].anchorB), Vec2(0.3, -0.01)));
  checkAnchorsMapBack(slab, ball, manifold);
  SECTION("with the circle as A the normal points from the circle to the box") {
    const Manifold swapped = collideOnce(ball, slab);
    REQUIRE(swapped.pointCount == 1);
    CHECK(near(swapped.normal, Vec2(0.0, -1.0)));
    CHECK(swapped.points[0].penetration == Approx(0.01).margin(kExact));
    checkSwapSymmetry(slab, ball);
  }
}

TEST_CASE("a circle off a box's corner touches the corner", "[contact][circle][polygon]") {
  const Body square = box(1.0, 1.0, Vec2(0.0, 0.0));
  const Body ball = circle(0.55, Vec2(0.5 + 0.3, 0.5 + 0.4));  // 0.5 m from the corner
  const Manifold manifold = collideOnce(square, ball);
  REQUIRE(manifold.pointCount == 1);
  CHECK(near(manifold.normal, Vec2(0.6, 0.8)));
  CHECK(manifold.points[0].penetration == Approx(0.05).margin(kExact));
  CHECK(near(square.toWorld(manifold.points[0].anchorA), Vec2(0.5, 0.5)));
  checkAnchorsMapBack(square, ball, manifold);
  checkSwapSymmetry(square, ball);
  SECTION("the corner and the face are different features") {
    const Manifold onFace = collideOnce(square, circle(0.55, Vec2(0.2, 1.0)));
    REQUIRE(onFace.pointCount == 1);
    CHECK(onFace.points[0].id != manifold.points[0].id);
  }
}

TEST_CASE("a circle whose centre is inside a box is pushed out of the nearest face",
          "[contact][circle][polygon]") {
  const Body square = box(2.0, 2.0, Vec2(0.0, 0.0));
  const Body ball = circle(0.5, Vec2(0.1, 0.8));
  const Manifold manifold = collideOnce(square, ball);
  REQUIRE(manifold.pointCount == 1);
  CHECK(near(manifold.normal, Vec2(0.0, 1.0)));
  CHECK(manifold.points[0].penetration == Approx(0.5 + 0.2).margin(kExact));
  checkAnchorsMapBack(square, ball, manifold);
  checkSwapSymmetry(square, ball);
}

TEST_CASE("circle and box: a gap within the margin is speculative, beyond it none",
          "[contact][circle][polygon][margin]") {
  const Manifold within = collideOnce(ground(), circle(0.5, Vec2(0.0, 0.504)));
  REQUIRE(within.pointCount == 1);
  CHECK(within.points[0].penetration == Approx(-0.004).margin(kExact));
  CHECK(collideOnce(ground(), circle(0.5, Vec2(0.0, 0.506))).pointCount == 0);
  CHECK(collideOnce(circle(0.5, Vec2(0.0, 0.506)), ground()).pointCount == 0);
}

TEST_CASE("a box lying flat on the ground touches at both bottom corners",
          "[contact][polygon][resting]") {
  const Body slab = ground();
  const Body square = box(1.0, 1.0, Vec2(0.2, 0.5 - 0.01));
  const Manifold manifold = collideOnce(slab, square);
  REQUIRE(manifold.pointCount == 2);
  CHECK(near(manifold.normal, Vec2(0.0, 1.0)));
  std::vector<double> xs;
  for (int i = 0; i < 2; ++i) {
    CHECK(manifold.points[i].penetration == Approx(0.01).margin(kExact));
    CHECK(manifold.points[i].point.y() == Approx(-0.005).margin(kExact));
    xs.push_back(manifold.points[i].point.x());
  }
  std::sort(xs.begin(), xs.end());
  CHECK(xs[0] == Approx(-0.3).margin(kExact));
  CHECK(xs[1] == Approx(0.7).margin(kExact));
  CHECK(manifold.points[0].id != manifold.points[1].id);
  checkAnchorsMapBack(slab, square, manifold);
  checkSwapSymmetry(slab, square);
}

TEST_CASE("a rotated box touches the ground with one corner", "[contact][polygon]") {
  const double angle = kPi / 6.0;
  const double cornerDrop = 0.5 * (std::sin(angle) + std::cos(angle));  // centre to lowest corner
  const Body slab = ground();
  const Body square = box(1.0, 1.0, Vec2(1.0, cornerDrop - 0.02), angle);
  const Manifold manifold = collideOnce(slab, square);
  REQUIRE(manifold.pointCount == 1);
  CHECK(near(manifold.normal, Vec2(0.0, 1.0)));
  CHECK(manifold.points[0].penetration == Approx(0.02).margin(kExact));
  CHECK(near(manifold.points[0].anchorB, Vec2(-0.5, -0.5)));
  CHECK(near(square.toWorld(manifold.points[0].anchorB),
             Vec2(1.0 + 0.5 * (std::sin(angle) - std::cos(angle)), -0.02)));
  checkAnchorsMapBack(slab, square, manifold);
  checkSwapSymmetry(slab, square);
  SECTION("the mirror-image pose touches with a different corner, so a different id") {
    const Manifold mirrored =
        collideOnce(slab, box(1.0, 1.0, Vec2(1.0, cornerDrop - 0.02), -angle));
    REQUIRE(mirrored.pointCount == 1);
    CHECK(mirrored.points[0].id != manifold.points[0].id);
  }
}

TEST_CASE("a box beside another box touches across the nearer faces", "[contact][polygon]") {
  const Body left = box(1.0, 1.0, Vec2(0.0, 0.0));
  const Body right = box(1.0, 2.0, Vec2(1.0 - 0.03, 0.2));
  const Manifold manifold = collideOnce(left, right);
  REQUIRE(manifold.pointCount == 2);
  CHECK(near(manifold.normal, Vec2(1.0, 0.0)));
  for (int i = 0; i < 2; ++i) {
    CHECK(manifold.points[i].penetration == Approx(0.03).margin(kExact));
  }
  checkAnchorsMapBack(left, right, manifold);
  checkSwapSymmetry(left, right);
}

TEST_CASE("a triangle meets a box tip first or lying on an edge", "[contact][polygon]") {
  const Body slab = box(2.0, 1.0, Vec2(0.0, 0.0));  // top face y = 0.5
  SECTION("tip down: one point") {
    const Body wedge = polygon({Vec2(-0.5, 1.5), Vec2(0.0, 0.47), Vec2(0.5, 1.5)});
    const Manifold manifold = collideOnce(slab, wedge);
    REQUIRE(manifold.pointCount == 1);
    CHECK(near(manifold.normal, Vec2(0.0, 1.0)));
    CHECK(manifold.points[0].penetration == Approx(0.03).margin(kExact));
    CHECK(near(wedge.toWorld(manifold.points[0].anchorB), Vec2(0.0, 0.47)));
    checkAnchorsMapBack(slab, wedge, manifold);
    checkSwapSymmetry(slab, wedge);
  }
  SECTION("edge down: two points at the ends of the edge") {
    const Body wedge = polygon({Vec2(-0.4, 0.49), Vec2(0.6, 0.49), Vec2(0.1, 1.3)});
    const Manifold manifold = collideOnce(slab, wedge);
    REQUIRE(manifold.pointCount == 2);
    CHECK(near(manifold.normal, Vec2(0.0, 1.0)));
    for (int i = 0; i < 2; ++i) {
      CHECK(manifold.points[i].penetration == Approx(0.01).margin(kExact));
    }
    checkAnchorsMapBack(slab, wedge, manifold);
    checkSwapSymmetry(slab, wedge);
  }
}

TEST_CASE("boxes: a gap within the margin is speculative, beyond it none",
          "[contact][polygon][margin]") {
  const Manifold within = collideOnce(ground(), box(1.0, 1.0, Vec2(0.0, 0.5 + 0.003)));
  REQUIRE(within.pointCount == 2);
  for (int i = 0; i < 2; ++i) {
    CHECK(within.points[i].penetration == Approx(-0.003).margin(kExact));
  }
  CHECK(collideOnce(ground(), box(1.0, 1.0, Vec2(0.0, 0.5 + 0.006))).pointCount == 0);
  SECTION("a tilted box keeps only the corner inside the margin") {
    const double angle = 0.008;  // the far corner is 1 m × sin(angle) ≈ 8 mm higher: 6 mm gap
    const double lowCorner = 0.5 * (std::cos(angle) + std::sin(angle));
    const Manifold tilted =
        collideOnce(ground(), box(1.0, 1.0, Vec2(0.0, lowCorner - 0.002), angle));
    REQUIRE(tilted.pointCount == 1);
    CHECK(tilted.points[0].penetration == Approx(0.002).margin(kExact));
  }
}

TEST_CASE("feature ids stay the same while a resting box is nudged", "[contact][feature-id]") {
  std::mt19937 generator(2024);
  std::uniform_real_distribution<double> nudge(-1e-4, 1e-4);  // m and rad
  struct Pair {
    const char* name;
    Body lower;
    Body upper;
  };
  const std::vector<Pair> pairs = {
      {"box on the ground", ground(), box(1.0, 1.0, Vec2(0.3, 0.5 - 0.001))},
      {"box on an equal box", box(1.0, 1.0, Vec2(0.0, 0.5)),
       box(1.0, 1.0, Vec2(0.2, 1.5 - 0.001))}};
  for (const Pair& pair : pairs) {
    INFO(pair.name);
    const Manifold rest = collideOnce(pair.lower, pair.upper);
    REQUIRE(rest.pointCount == 2);
    for (int pose = 0; pose < 10; ++pose) {
      Body moved = pair.upper;
      moved.position += Vec2(nudge(generator), nudge(generator));
      moved.angle += nudge(generator);
      moved.updateCache();
      const Manifold manifold = collideOnce(pair.lower, moved);
      REQUIRE(manifold.pointCount == 2);
      CHECK(ids(manifold) == ids(rest));
      CHECK(near(manifold.normal, rest.normal, 1e-4));
    }
  }
}

TEST_CASE("a point keeps its feature id when the reference face passes to the other box",
          "[contact][feature-id]") {
  // An equal box on a box, both tilted by a few milliradians the opposite way: as the tilts
  // swap, the face with the least overlap passes from the lower box (A) to the upper one (B).
  // The left point and the right point must keep their ids throughout, or warm starting loses
  // their impulses every time the reference flips.
  int flips = 0;
  std::vector<FeatureId> leftIds;
  std::vector<FeatureId> rightIds;
  for (int pose = -10; pose <= 10; ++pose) {
    const double tilt = 0.001 * pose;  // rad
    const Body lower = box(1.0, 1.0, Vec2(0.0, 0.5), tilt);
    const Body upper = box(1.0, 1.0, Vec2(0.3, 1.5 - 0.002), -0.5 * tilt);
    const Manifold manifold = collideOnce(lower, upper);
    REQUIRE(manifold.pointCount == 2);
    const Vec2 lowerTopNormal = lower.rotation * Vec2(0.0, 1.0);
    if (!near(manifold.normal, lowerTopNormal, 1e-12)) ++flips;  // B's face is the reference
    const bool firstIsLeft = manifold.points[0].point.x() < manifold.points[1].point.x();
    leftIds.push_back(manifold.points[firstIsLeft ? 0 : 1].id);
    rightIds.push_back(manifold.points[firstIsLeft ? 1 : 0].id);
  }
  CHECK(flips > 0);   // some poses took B's face ...
  CHECK(flips < 21);  // ... and some A's
  CHECK(std::count(leftIds.begin(), leftIds.end(), leftIds.front()) == 21);
  CHECK(std::count(rightIds.begin(), rightIds.end(), rightIds.front()) == 21);
  CHECK(leftIds.front() != rightIds.front());
}

TEST_CASE("feature ids differ for different touching features", "[contact][feature-id]") {
  const Body slab = ground();
  const Manifold bottomFace = collideOnce(slab, box(1.0, 2.0, Vec2(0.0, 1.0 - 0.001)));
  const Manifold sideFace = collideOnce(slab, box(1.0, 2.0, Vec2(0.0, 0.5 - 0.001), kPi / 2.0));
  REQUIRE(bottomFace.pointCount == 2);
  REQUIRE(sideFace.pointCount == 2);
  const std::vector<FeatureId> bottomIds = ids(bottomFace);
  for (FeatureId id : ids(sideFace)) {
    CHECK(std::find(bottomIds.begin(), bottomIds.end(), id) == bottomIds.end());
  }
  SECTION("a point cut by a side plane of the reference face has its own id") {
    const Manifold overhang =
        collideOnce(box(1.0, 1.0, Vec2(0.0, 0.0)), box(1.0, 1.0, Vec2(0.7, 1.0 - 0.001)));
    REQUIRE(overhang.pointCount == 2);
    CHECK(overhang.points[0].id != overhang.points[1].id);
    checkAnchorsMapBack(box(1.0, 1.0, Vec2(0.0, 0.0)), box(1.0, 1.0, Vec2(0.7, 1.0 - 0.001)),
                        overhang);
  }
}
