// The two-point block solve: Box2D's condition test and the four cases of a 2×2 LCP.
#include "impulse2d/solvers/two_point_block.h"

#include <Eigen/LU>

namespace impulse2d {

bool isWellConditioned(const Mat2& k, double conditionLimit) {
  return k(0, 0) * k(0, 0) < conditionLimit * k.determinant();
}

Vec2 solveTwoPointLcp(const Mat2& k, const Vec2& q) {
  return solveTwoPointLcp(k, inverseOrZero(k, 0.0), q);
}

Vec2 solveTwoPointLcp(const Mat2& k, const Mat2& kInverse, const Vec2& q) {
  const Vec2 both = -(kInverse * q);
  if (both.minCoeff() >= 0.0) return both;
  const Vec2 firstOnly(-q(0) / k(0, 0), 0.0);
  if (firstOnly(0) >= 0.0 && k(1, 0) * firstOnly(0) + q(1) >= 0.0) return firstOnly;
  const Vec2 secondOnly(0.0, -q(1) / k(1, 1));
  if (secondOnly(1) >= 0.0 && k(0, 1) * secondOnly(1) + q(0) >= 0.0) return secondOnly;
  return Vec2::Zero();  // the last case, q ≥ 0: neither point needs to push
}

}  // namespace impulse2d
