// Fuzz target for contact generation: the bytes choose two convex shapes (circles, boxes, convex
// polygons through makePolygon) and their poses, and collide() must keep the promises of
// contact.h and collide.h for them in both orders:
//   - at most 2 points, each finite, deeper than −margin, no deeper than the shapes are wide;
//   - a unit normal from A to B; swapping A and B negates it (exactly for pairs with a circle,
//     where no reference face is chosen, unless two circles share a centre; for two polygons, a
//     contact less deep than half the thinner shape's inradius must still face the other way);
//   - each point's anchors put A's surface point `penetration` past B's along the normal, and the
//     point midway between them; the two points of a manifold have different feature ids.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "impulse2d/body.h"
#include "impulse2d/collide.h"

using impulse2d::Body;
using impulse2d::Manifold;
using impulse2d::Vec2;

namespace {

/// m. The sizes and places the shapes are drawn from: those of lecture scenes.
constexpr double kSmallestSize = 0.01;
constexpr double kLargestSize = 10.0;
constexpr double kLargestOffset = 10.0;
constexpr double kLargestMargin = 0.1;
constexpr int kMostPolygonVertices = 8;

/// m. Round-off allowed in the relations checked, for coordinates up to about 20 m.
constexpr double kTolerance = 1e-8;

/// A broken promise; the fuzz entry point prints it with the two bodies, then aborts.
struct BrokenPromise {
  const char* what;
};

void require(bool condition, const char* what) {
  if (!condition) throw BrokenPromise{what};
}

void printBody(const char* label, const Body& body) {
  std::fprintf(stderr, "%s: at (%.17g, %.17g), angle %.17g, radius %.17g, vertices", label,
               body.position.x(), body.position.y(), body.angle, body.shape.radius);
  for (const Vec2& v : body.shape.vertices) std::fprintf(stderr, " (%.17g, %.17g)", v.x(), v.y());
  std::fprintf(stderr, "\n");
}

double size(FuzzedDataProvider& bytes) {
  return bytes.ConsumeFloatingPointInRange(kSmallestSize, kLargestSize);
}

/// Vertices on an ellipse at sorted angles: convex, though near-repeated or near-collinear ones
/// are rejected by makePolygon, and then the input is skipped.
std::vector<Vec2> ellipsePoints(FuzzedDataProvider& bytes) {
  const int count = bytes.ConsumeIntegralInRange(3, kMostPolygonVertices);
  const double width = size(bytes);
  const double height = size(bytes);
  double angle = 0.0;
  std::vector<Vec2> points;
  for (int i = 0; i < count; ++i) {
    points.emplace_back(width * std::cos(angle), height * std::sin(angle));
    angle += bytes.ConsumeFloatingPointInRange(0.0, 2.0 * impulse2d::kPi / (count - 1));
  }
  if (bytes.ConsumeBool()) std::reverse(points.begin(), points.end());
  return points;
}

impulse2d::Shape shape(FuzzedDataProvider& bytes) {
  switch (bytes.ConsumeIntegralInRange(0, 2)) {
    case 0:
      return impulse2d::makeCircle(size(bytes));
    case 1:
      return impulse2d::makeBox(size(bytes), size(bytes));
    default:
      return impulse2d::makePolygon(ellipsePoints(bytes)).shape;
  }
}

Body body(FuzzedDataProvider& bytes) {
  const impulse2d::Shape bodyShape = shape(bytes);
  const Vec2 position(bytes.ConsumeFloatingPointInRange(-kLargestOffset, kLargestOffset),
                      bytes.ConsumeFloatingPointInRange(-kLargestOffset, kLargestOffset));
  const double angle = bytes.ConsumeFloatingPointInRange(-impulse2d::kPi, impulse2d::kPi);
  return impulse2d::makeBody("fuzzed", impulse2d::BodyType::Dynamic, bodyShape, 1.0, position,
                             angle);
}

/// m. The radius of a circle about the centre of mass that holds the shape.
double boundingRadius(const impulse2d::Shape& shape) {
  double radius = shape.radius;
  for (const Vec2& vertex : shape.vertices) radius = std::max(radius, vertex.norm());
  return radius;
}

/// m. The distance from the centre of mass to the nearest face (a polygon's is its centroid).
double inradius(const impulse2d::Shape& shape) {
  if (shape.type == impulse2d::ShapeType::Circle) return shape.radius;
  double radius = INFINITY;
  for (size_t i = 0; i < shape.vertices.size(); ++i) {
    radius = std::min(radius, shape.normals[i].dot(shape.vertices[i]));
  }
  return radius;
}

void checkPoint(const Body& a, const Body& b, const Manifold& manifold,
                const impulse2d::ContactPoint& point, double margin) {
  require(point.point.allFinite() && point.anchorA.allFinite() && point.anchorB.allFinite() &&
              std::isfinite(point.penetration),
          "a contact point is not finite");
  require(point.penetration > -margin - kTolerance, "a point is further apart than the margin");
  require(point.penetration <= 2.0 * (boundingRadius(a.shape) + boundingRadius(b.shape)),
          "a point is deeper than the shapes are wide");
  const Vec2 onA = a.toWorld(point.anchorA);
  const Vec2 onB = b.toWorld(point.anchorB);
  require((onA - onB - point.penetration * manifold.normal).norm() <= kTolerance,
          "the anchors do not lie `penetration` apart along the normal");
  require((point.point - impulse2d::contactPointBetween(onA, onB)).norm() <= kTolerance,
          "the contact point is not where contactPointBetween puts it");
}

void checkManifold(const Body& a, const Body& b, const Manifold& manifold, int count,
                   double margin) {
  require(count == manifold.pointCount, "collide() returns a count other than pointCount");
  require(count >= 0 && count <= 2, "a manifold has more than 2 points");
  if (count == 0) return;
  require(manifold.normal.allFinite() && std::abs(manifold.normal.norm() - 1.0) <= kTolerance,
          "the normal is not a unit vector");
  for (int i = 0; i < count; ++i) checkPoint(a, b, manifold, manifold.points[i], margin);
  require(count < 2 || manifold.points[0].id != manifold.points[1].id,
          "two points of a manifold share a feature id");
}

double deepest(const Manifold& manifold) {
  double depth = -INFINITY;
  for (int i = 0; i < manifold.pointCount; ++i) {
    depth = std::max(depth, manifold.points[i].penetration);
  }
  return depth;
}

void checkSwapped(const Body& a, const Body& b, const Manifold& ab, const Manifold& ba) {
  if (ab.pointCount == 0 || ba.pointCount == 0) return;
  const bool withCircle =
      a.shape.type == impulse2d::ShapeType::Circle || b.shape.type == impulse2d::ShapeType::Circle;
  if (withCircle) {
    // Two circles on one centre have no direction between them; collide.h gives +y either way.
    if (a.shape.type == b.shape.type && (a.position - b.position).norm() <= 1e-12) return;
    require((ab.normal + ba.normal).norm() <= kTolerance, "swapping A and B does not negate n");
    return;
  }
  const double shallow = 0.5 * std::min(inradius(a.shape), inradius(b.shape));
  if (std::max(deepest(ab), deepest(ba)) > shallow) return;
  // Both orders take the reference face from one body (the same face finds the same deepest
  // point, a difference of 0), and then the normal turns round, unless that body's face separates
  // them by no more than kReferenceFaceTolerance beyond the other's: then each order keeps its
  // first body's face, and where two slivers cross, both normals may point the same way (each
  // sliver's tip pokes out of the other on the same side).
  const double difference = std::abs(deepest(ab) - deepest(ba));
  if (difference > 0.0 && difference <= impulse2d::kReferenceFaceTolerance) return;
  require(ab.normal.dot(ba.normal) < 0.0, "swapping A and B does not turn the normal round");
}

void checkPair(const Body& a, const Body& b, double margin) {
  Manifold ab;
  Manifold ba;
  checkManifold(a, b, ab, impulse2d::collide(a, b, margin, ab), margin);
  checkManifold(b, a, ba, impulse2d::collide(b, a, margin, ba), margin);
  checkSwapped(a, b, ab, ba);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider bytes(data, size);
  Body a;
  Body b;
  try {
    a = body(bytes);
    b = body(bytes);
  } catch (const impulse2d::ShapeError&) {
    return 0;  // a degenerate polygon, rejected by makePolygon: not a collision input
  }
  const double margin = bytes.ConsumeFloatingPointInRange(0.0, kLargestMargin);
  try {
    checkPair(a, b, margin);
  } catch (const BrokenPromise& broken) {
    std::fprintf(stderr, "collide_fuzzer: %s (margin %.17g)\n", broken.what, margin);
    printBody("A", a);
    printBody("B", b);
    std::abort();
  }
  return 0;
}
