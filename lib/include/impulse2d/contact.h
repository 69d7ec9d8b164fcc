// Contact manifolds: where two bodies touch, and the impulses a solver applied there.
//
// THE SIGN CONVENTION (stated here once, used everywhere):
// - A manifold joins body A and body B. Its normal n is a unit vector pointing from A to B.
// - penetration d > 0 means the surfaces overlap by d along n; d < 0 is a gap of −d.
// - An impulse λ along n is applied as +λn to B and −λn to A: λ > 0 pushes them apart.
// - The relative velocity at a contact is v = (vB + ωB × rB) − (vA + ωA × rA), r being the arm
//   from each centre of mass to the contact point; its normal part vn = v·n is the separating
//   velocity: vn < 0 closing (approaching), vn > 0 separating.
// - The tangent is t = leftPerpendicular(n) (n turned +90°); a friction impulse λt acts as +λt t
//   on B and −λt t on A, like the normal impulse.
#pragma once

#include <array>
#include <cstdint>

#include "impulse2d/math.h"

namespace impulse2d {

/// Which features (edges, vertices) of the two shapes make a contact point. It stays the same
/// from step to step while the same features touch, so impulses can be carried over by it.
using FeatureId = std::uint32_t;

/// Builds a feature id from a feature of A and a feature of B (vertex indices for two polygons,
/// collide.cpp), so it does not depend on which of the two gave the reference face.
inline FeatureId makeFeatureId(int featureOfA, int featureOfB) {
  return static_cast<FeatureId>((featureOfA & 0xffff) | (featureOfB & 0xffff) << 16);
}

/// Friction state of a contact point in the last solve, for frames and tests.
enum class FrictionState { None, Static, Dynamic };

/// Where a contact's impulses act, from the points on A's and B's surfaces: midway between them,
/// so one point carries both impulses and the pair's angular momentum is kept.
inline Vec2 contactPointBetween(const Vec2& onA, const Vec2& onB) {
  return 0.5 * (onA + onB);
}

/// One point of a contact manifold: where it is, how deep, and the impulses applied there.
struct ContactPoint {
  Vec2 point = Vec2::Zero();    ///< world point where impulses act (contactPointBetween)
  Vec2 anchorA = Vec2::Zero();  ///< the point on A's surface, in A's body frame
  Vec2 anchorB = Vec2::Zero();  ///< the point on B's surface, in B's body frame
  double penetration = 0.0;     ///< m, along the normal; negative is a gap
  /// the features that made it, to carry impulses between steps
  FeatureId id = 0;

  /// N s. Total normal impulse the solver applied this step (the accumulated impulse, which a
  /// method may warm start the next step from).
  double normalImpulse = 0.0;
  /// N s. Total friction impulse along the tangent this step.
  double tangentImpulse = 0.0;
  /// static, dynamic or none this step
  FrictionState friction = FrictionState::None;
  /// Its impulses were carried over from last step's point with the same feature id: the solver
  /// solved this point last step (a new point starts at zero impulse and false).
  bool carried = false;
};

/// Coefficients of a contact from the two materials. The mixing rule is Box2D's, so both engines
/// see the same numbers: friction √(μA·μB), restitution max(eA, eB).
double mixFriction(double frictionA, double frictionB);
double mixRestitution(double restitutionA, double restitutionB);

/// A contact between two bodies: one normal and up to two points (the sign convention above).
struct Manifold {
  int bodyA = -1;  ///< index into the world's bodies
  /// index into the world's bodies
  int bodyB = -1;
  Vec2 normal = Vec2(0.0, 1.0);  ///< unit, from A to B
  double friction = 0.0;         ///< mixed coefficient of friction
  double restitution = 0.0;      ///< mixed coefficient of restitution
  int pointCount = 0;            ///< 0, 1 or 2
  /// the first pointCount are used
  std::array<ContactPoint, 2> points;

  /// The friction direction: the normal turned a quarter turn counter-clockwise.
  Vec2 tangent() const { return leftPerpendicular(normal); }

  /// The index of the point the features `id` made, or -1: how a point is matched to the same
  /// point a step earlier, to carry its impulses or its solver's state over.
  int pointMadeBy(FeatureId id) const {
    for (int i = 0; i < pointCount; ++i) {
      if (points[i].id == id) return i;
    }
    return -1;
  }
};

}  // namespace impulse2d
