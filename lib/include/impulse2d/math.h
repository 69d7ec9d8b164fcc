// Planar vector helpers on top of Eigen's fixed-size types. In 2D an angular velocity or a torque
// is a scalar (its z component), so the three cross products of 3D mechanics become the helpers
// below.
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace impulse2d {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

/// π, the one constant for it (kPi is not standard C++).
inline constexpr double kPi = 3.14159265358979323846;

/// z component of the 3D cross product (a, 0) × (b, 0): the torque of force b at arm a.
inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// (0, 0, w) × (r, 0): the velocity of a point at arm r on a body spinning at w.
inline Vec2 cross(double w, const Vec2& r) {
  return Vec2(-w * r.y(), w * r.x());
}

/// v turned +90° (counter-clockwise): the tangent of a contact whose normal is v.
inline Vec2 leftPerpendicular(const Vec2& v) {
  return Vec2(-v.y(), v.x());
}

/// r turned by the rotation whose cosine and sine are (c, s).
inline Vec2 rotate(double c, double s, const Vec2& r) {
  return Vec2(c * r.x() - s * r.y(), s * r.x() + c * r.y());
}

/// The rotation matrix of an angle in radians (counter-clockwise positive).
inline Mat2 rotation(double angle) {
  Mat2 r;
  r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return r;
}

/// Closed-form inverse of a 2×2 matrix; the zero matrix when it is singular (|det| ≤ tiny).
inline Mat2 inverseOrZero(const Mat2& m, double tiny) {
  const double det = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
  if (std::abs(det) <= tiny) return Mat2::Zero();
  Mat2 inverse;
  inverse << m(1, 1), -m(0, 1), -m(1, 0), m(0, 0);
  return inverse / det;
}

/// The direction from `from` to `to`, or `fallback` where the two coincide.
inline Vec2 directionOr(const Vec2& from, const Vec2& to, const Vec2& fallback) {
  const Vec2 d = to - from;
  const double length = d.norm();
  return length > 0.0 ? Vec2(d / length) : fallback;
}

/// An axis-aligned bounding box.
struct Aabb {
  /// m, the lower left corner
  Vec2 lower = Vec2::Zero();
  /// m, the upper right corner
  Vec2 upper = Vec2::Zero();

  /// True when the boxes overlap or touch.
  bool overlaps(const Aabb& other) const {
    return lower.x() <= other.upper.x() && other.lower.x() <= upper.x() &&
           lower.y() <= other.upper.y() && other.lower.y() <= upper.y();
  }
};

}  // namespace impulse2d
