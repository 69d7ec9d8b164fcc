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
  /// the unknowns
  Eigen::VectorXd z;
  /// w = M z + q
  Eigen::VectorXd w;
  /// pivots made
  int pivots = 0;
  /// z and w are a solution
  bool solved = false;
  /// why not, when not solved
  std::string failure;
};

/// How a Lemke path chooses the leaving variable among near-ties of the ratio test.
enum class RatioTest {
  Lexicographic,  ///< exact ties broken by B⁻¹'s rows: cannot cycle, may take a tiny pivot
  Harris          ///< overshoot by round-off allowed, then the largest pivot wins
};

/// One path of Lemke's method: the covering vector d > 0 of the artificial variable
/// (I·w − M·z − d·z0 = q) and the ratio test. Each gives its own path to the same solutions;
/// where round-off or a tiny pivot defeats one on a degenerate problem, another often succeeds.
struct LemkePath {
  /// d > 0
  Eigen::VectorXd covering;
  /// how near-ties are broken
  RatioTest ratioTest = RatioTest::Lexicographic;
};

/// Lemke's method with the covering vector of ones and the lexicographic ratio test (which
/// cannot cycle on degenerate problems such as a resting stack). It solves every LCP whose M is
/// positive semi-definite or copositive-plus and that has a solution; O(n³) work in all.
LcpSolution solveLemke(const Eigen::MatrixXd& m, const Eigen::VectorXd& q,
                       const LemkeSettings& options);

/// Lemke's method along the given path. Either way the basic values at the end are solved again
/// from the final basis, kept where that lowers the natural residual.
LcpSolution solveLemke(const Eigen::MatrixXd& m, const Eigen::VectorXd& q, const LemkePath& path,
                       const LemkeSettings& options);

/// The natural residual ‖min(z, M z + q)‖∞: zero exactly at a solution; it measures violated
/// signs and complementarity together.
double naturalResidual(const Eigen::MatrixXd& m, const Eigen::VectorXd& q,
                       const Eigen::VectorXd& z);

}  // namespace impulse2d
