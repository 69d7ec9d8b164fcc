// The two-point block solve with K⁻¹ computed here (the inline forms are in the header).
#include "impulse2d/solvers/two_point_block.h"

namespace impulse2d {

Vec2 solveTwoPointLcp(const Mat2& k, const Vec2& q) {
  return solveTwoPointLcp(k, inverseOrZero(k, 0.0), q);
}

}  // namespace impulse2d
