// Shape construction, validation and mass properties.
#include "impulse2d/shape.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace impulse2d {
namespace {

/// Relative size below which two vertices count as repeated, or three as collinear.
constexpr double kDegenerateTolerance = 1e-9;

std::string describeVertex(int index, const Vec2& v) {
  std::ostringstream out;
  out << "vertex " << index << " (" << v.x() << ", " << v.y() << ")";
  return out.str();
}

double signedArea(const std::vector<Vec2>& vertices) {
  double twiceArea = 0.0;
  for (size_t i = 0; i < vertices.size(); ++i) {
    twiceArea += cross(vertices[i], vertices[(i + 1) % vertices.size()]);
  }
  return 0.5 * twiceArea;
}

void checkVertexList(const std::vector<Vec2>& vertices) {
  if (vertices.size() < 3) {
    throw ShapeError("polygon has " + std::to_string(vertices.size()) +
                     " vertices; it needs at least 3");
  }
  for (size_t i = 0; i < vertices.size(); ++i) {
    if (!vertices[i].allFinite()) {
      throw ShapeError("polygon " + describeVertex(int(i), vertices[i]) + " is not finite");
    }
  }
}

/// Rejects repeated and collinear vertices and reflex corners of a counter-clockwise polygon.
void checkConvexCounterClockwise(const std::vector<Vec2>& vertices, double lengthScale) {
  const size_t n = vertices.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec2& previous = vertices[(i + n - 1) % n];
    const Vec2& current = vertices[i];
    const Vec2& next = vertices[(i + 1) % n];
    if ((next - current).norm() <= kDegenerateTolerance * lengthScale) {
      throw ShapeError("polygon " + describeVertex(int((i + 1) % n), next) + " repeats " +
                       describeVertex(int(i), current));
    }
    const double turn = cross(Vec2(current - previous), Vec2(next - current));
    if (std::abs(turn) <= kDegenerateTolerance * lengthScale * lengthScale) {
      throw ShapeError("polygon " + describeVertex(int(i), current) +
                       " is collinear with its neighbours");
    }
    if (turn < 0.0) {
      throw ShapeError("polygon is not convex at " + describeVertex(int(i), current));
    }
  }
}

Shape polygonShape(std::vector<Vec2> vertices) {
  Shape shape;
  shape.type = ShapeType::Polygon;
  shape.vertices = std::move(vertices);
  const size_t n = shape.vertices.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec2 edge = shape.vertices[(i + 1) % n] - shape.vertices[i];
    shape.normals.push_back(Vec2(edge.y(), -edge.x()).normalized());
  }
  return shape;
}

Vec2 polygonCentroid(const std::vector<Vec2>& vertices, double area) {
  Vec2 sum = Vec2::Zero();
  for (size_t i = 0; i < vertices.size(); ++i) {
    const Vec2& a = vertices[i];
    const Vec2& b = vertices[(i + 1) % vertices.size()];
    sum += cross(a, b) * (a + b);
  }
  return sum / (6.0 * area);
}

}  // namespace

Shape makeCircle(double radius) {
  if (!std::isfinite(radius) || radius <= 0.0) {
    throw ShapeError("circle radius must be finite and > 0, not " + std::to_string(radius));
  }
  Shape shape;
  shape.type = ShapeType::Circle;
  shape.radius = radius;
  return shape;
}

Shape makeBox(double width, double height) {
  if (!std::isfinite(width) || !std::isfinite(height) || width <= 0.0 || height <= 0.0) {
    throw ShapeError("box size must be finite and > 0, not " + std::to_string(width) + " x " +
                     std::to_string(height));
  }
  const double w = 0.5 * width;
  const double h = 0.5 * height;
  return polygonShape({Vec2(-w, -h), Vec2(w, -h), Vec2(w, h), Vec2(-w, h)});
}

CentredPolygon makePolygon(const std::vector<Vec2>& vertices) {
  checkVertexList(vertices);
  std::vector<Vec2> ordered = vertices;
  double area = signedArea(ordered);
  if (area < 0.0) {
    std::reverse(ordered.begin(), ordered.end());
    area = -area;
  }
  double lengthScale = 0.0;
  for (const Vec2& v : ordered) lengthScale = std::max(lengthScale, (v - ordered[0]).norm());
  if (!(area > kDegenerateTolerance * lengthScale * lengthScale)) {
    throw ShapeError("polygon has zero area");
  }
  checkConvexCounterClockwise(ordered, lengthScale);
  const Vec2 centroid = polygonCentroid(ordered, area);
  for (Vec2& v : ordered) v -= centroid;
  return {polygonShape(std::move(ordered)), centroid};
}

MassProperties computeMass(const Shape& shape, double density) {
  if (shape.type == ShapeType::Circle) {
    const double mass = density * kPi * shape.radius * shape.radius;
    return {mass, 0.5 * mass * shape.radius * shape.radius};
  }
  // Sum of the triangles (origin, a, b); the origin is the centroid.
  double area = 0.0;
  double secondMoment = 0.0;
  const auto& v = shape.vertices;
  for (size_t i = 0; i < v.size(); ++i) {
    const Vec2& a = v[i];
    const Vec2& b = v[(i + 1) % v.size()];
    const double twiceTriangle = cross(a, b);
    area += 0.5 * twiceTriangle;
    secondMoment += twiceTriangle * (a.squaredNorm() + a.dot(b) + b.squaredNorm()) / 12.0;
  }
  return {density * area, density * secondMoment};
}

double maxExtent(const Shape& shape) {
  if (shape.type == ShapeType::Circle) return shape.radius;
  double extent = 0.0;
  for (const Vec2& vertex : shape.vertices) extent = std::max(extent, vertex.norm());
  return extent;
}

Aabb computeBounds(const Shape& shape, const Vec2& position, const Mat2& rotation) {
  if (shape.type == ShapeType::Circle) {
    const Vec2 extent(shape.radius, shape.radius);
    return {position - extent, position + extent};
  }
  Aabb box{position + rotation * shape.vertices[0], position + rotation * shape.vertices[0]};
  for (const Vec2& local : shape.vertices) {
    const Vec2 p = position + rotation * local;
    box.lower = box.lower.cwiseMin(p);
    box.upper = box.upper.cwiseMax(p);
  }
  return box;
}

}  // namespace impulse2d
