// The two-point block solve (Box2D 2.4's block solver): the two normal impulses of a flat contact
// found together, exactly, so neither corner is favoured. Sequential impulses use it on
// velocities, the position pass on penetrations.
#pragma once

#include "impulse2d/math.h"

namespace impulse2d {

/// Whether K may be solved as a block: k₀₀² < conditionLimit · det K (Box2D's test). Two points
/// that act almost alike (a narrow contact) make K nearly singular; they are then solved apart.
bool isWellConditioned(const Mat2& k, double conditionLimit);

/// The 2×2 linear complementarity problem of a two-point manifold: x ≥ 0, w = K x + q ≥ 0 and
/// xᵢwᵢ = 0, solved exactly by trying its four cases in turn — both points push, only the first,
/// only the second, neither — as Box2D 2.4's block solver does. K must be well conditioned.
Vec2 solveTwoPointLcp(const Mat2& k, const Vec2& q);

/// The same with K⁻¹ (inverseOrZero(k, 0)) computed once by the caller, for a K that stays the
/// same over many solves (the velocity sweeps of one step).
Vec2 solveTwoPointLcp(const Mat2& k, const Mat2& kInverse, const Vec2& q);

}  // namespace impulse2d
