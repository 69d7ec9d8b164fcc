// Collision shapes: circles and convex polygons, in the body frame with the centre of mass at the
// origin. A polygon that cannot be simulated is rejected here, with the reason, never later.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "impulse2d/math.h"

namespace impulse2d {

enum class ShapeType { Circle, Polygon };

/// Thrown for a shape that cannot be simulated (non-convex, degenerate, non-finite, ...).
class ShapeError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// A circle or a convex polygon, in the body frame with the centre of mass at the origin.
struct Shape {
  /// circle or polygon
  ShapeType type = ShapeType::Circle;
  double radius = 0.0;         ///< circle radius (m); 0 for polygons
  std::vector<Vec2> vertices;  ///< polygon vertices, counter-clockwise, centroid at the origin
  std::vector<Vec2> normals;   ///< outward unit normal of edge i (vertices[i] -> vertices[i+1])
};

/// Mass properties of a shape of uniform density.
struct MassProperties {
  double mass = 0.0;     ///< kg
  double inertia = 0.0;  ///< kg m^2, about the centre of mass
};

/// Where the centroid of a polygon given in some frame lies, and the polygon moved so it is at the
/// origin. Scene loading uses it so the body's position is its centre of mass.
struct CentredPolygon {
  /// the polygon, its centroid at the origin
  Shape shape;
  Vec2 centroid = Vec2::Zero();  ///< in the frame the vertices were given in
};

/// A circle of the given radius (> 0, finite).
Shape makeCircle(double radius);

/// A width × height box centred on the origin (both > 0, finite).
Shape makeBox(double width, double height);

/// A convex polygon from vertices in either winding order, moved so its centroid is the origin.
/// Throws ShapeError naming the problem: fewer than 3 vertices, a non-finite coordinate, a
/// repeated vertex, three collinear vertices, zero area, or a reflex (non-convex) corner.
CentredPolygon makePolygon(const std::vector<Vec2>& vertices);

/// Mass and moment of inertia of the shape at the given density (kg/m^2).
MassProperties computeMass(const Shape& shape, double density);

/// Whether the surface under a contact changes as the shape turns about its centre: not a
/// circle's, which is the same however it turns (a contact on it moves with its centre alone).
inline bool surfaceTurnsWithShape(const Shape& shape) {
  return shape.type != ShapeType::Circle;
}

/// m. The largest distance of a point of the shape from its centre of mass (its body origin).
double maxExtent(const Shape& shape);

/// The shape's bounding box when placed at position with the given rotation.
Aabb computeBounds(const Shape& shape, const Vec2& position, const Mat2& rotation);

}  // namespace impulse2d
