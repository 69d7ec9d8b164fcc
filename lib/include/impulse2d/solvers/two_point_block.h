// The two-point block solve (Box2D 2.4's block solver): the two normal impulses of a flat contact
// found together, exactly, so neither corner is favoured. Sequential impulses use it on
// velocities, the position pass on penetrations.
#pragma once

#include <Eigen/LU>

#include "impulse2d/math.h"

namespace impulse2d {

/// Whether K may be solved as a block: k₀₀² < conditionLimit · det K (Box2D's test). Two points
/// that act almost alike (a narrow contact) make K nearly singular; they are then solved apart.
inline bool isWellConditioned(const Mat2& k, double conditionLimit) {
  return k(0, 0) * k(0, 0) < conditionLimit * k.determinant();
}

/// The 2×2 linear complementarity problem of a two-point manifold: x ≥ 0, w = K x + q ≥ 0 and
/// xᵢwᵢ = 0, solved exactly by trying its four cases in turn — both points push, only the first,
/// only the second, neither — as Box2D 2.4's block solver does. K must be well conditioned.
Vec2 solveTwoPointLcp(const Mat2& k, const Vec2& q);

/// The same with K⁻¹ (inverseOrZero(k, 0)) computed once by the caller, for a K that stays the
/// same over many solves (the velocity sweeps of one step).
/// Written on scalars: it runs once per flat contact per sweep, and vectors built and taken apart
/// here would go through memory.
inline Vec2 solveTwoPointLcp(const Mat2& k, const Mat2& kInverse, const Vec2& q) {
  const double q0 = q(0);
  const double q1 = q(1);
  const double both0 = -(kInverse(0, 0) * q0 + kInverse(0, 1) * q1);
  const double both1 = -(kInverse(1, 0) * q0 + kInverse(1, 1) * q1);
  if (both0 >= 0.0 && both1 >= 0.0) return Vec2(both0, both1);
  const double firstOnly = -q0 / k(0, 0);
  if (firstOnly >= 0.0 && k(1, 0) * firstOnly + q1 >= 0.0) return Vec2(firstOnly, 0.0);
  const double secondOnly = -q1 / k(1, 1);
  if (secondOnly >= 0.0 && k(0, 1) * secondOnly + q0 >= 0.0) return Vec2(0.0, secondOnly);
  return Vec2::Zero();  // the last case, q ≥ 0: neither point needs to push
}

}  // namespace impulse2d
