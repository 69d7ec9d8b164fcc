// The linear complementarity problem (LCP) and Lemke's complementary pivoting method, on Eigen's
// dense matrices. The global reference solver states every contact of a step as one LCP.
//
// THE PROBLEM: given an n×n matrix M and a vector q, find z with
//   w = M z + q,   z ≥ 0,   w ≥ 0,   zᵢ wᵢ = 0 for every i.
// For contacts: z holds the impulses, w the velocities they leave; "no pull" is z ≥ 0, "no
// overlap velocity" is w ≥ 0, and complementarity says a contact either pushes or separates.
#pragma once

#include <string>

#include <Eigen/Dense>

#include "impulse2d/settings.h"

namespace impulse2d {

/// The answer of an LCP solver. `solved` is false on a secondary ray (no solution found this
/// way) or at the pivot limit; `failure` then says which, and z must not be used.
struct LcpSolution {
  Eigen::VectorXd z;
  Eigen::VectorXd w;
  int pivots = 0;
  bool solved = false;
  std::string failure;
};

/// Lemke's method with the covering vector of ones and the lexicographic ratio test (which
/// cannot cycle on degenerate problems such as a resting stack). It solves every LCP whose M is
/// positive semi-definite or copositive-plus and that has a solution; O(n³) work in all.
LcpSolution solveLemke(const Eigen::MatrixXd& m, const Eigen::VectorXd& q,
                       const LemkeSettings& options);

/// The natural residual ‖min(z, M z + q)‖∞: zero exactly at a solution; it measures violated
/// signs and complementarity together.
double naturalResidual(const Eigen::MatrixXd& m, const Eigen::VectorXd& q,
                       const Eigen::VectorXd& z);

}  // namespace impulse2d
