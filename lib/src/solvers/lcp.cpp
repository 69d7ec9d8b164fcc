// Lemke's complementary pivoting method in revised form: the basis inverse is kept and updated by
// one rank-one change per pivot, so a pivot costs O(n²) and a solve O(n³).
//
// The system is  I·w − M·z − 1·z0 = q  with every variable ≥ 0. Variables are numbered w₀..wₙ₋₁,
// then z₀..zₙ₋₁, then the artificial z0. Starting from w = q, z0 enters to make every w ≥ 0;
// from then on the variable that enters is always the complement of the one that just left,
// until z0 itself leaves: then w and z are complementary and z0 = 0, a solution.
#include "impulse2d/solvers/lcp.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/LU>

namespace impulse2d {
namespace {

// Lemke's tolerances tell round-off from a pivot or a tie; they are not for tuning.

/// A column entry must exceed this times the column's largest entry (or 1) to be a pivot:
/// smaller entries are round-off of zeros, and pivoting on one wrecks the basis inverse.
constexpr double kPivotTolerance = 1e-9;
/// Ratios closer than this (relative) count as a tie, broken lexicographically: they differ by
/// round-off alone.
constexpr double kTieTolerance = 1e-12;
/// Harris's ratio test (RatioTest::Harris) may overshoot a basic variable by this much, relative
/// to the largest basic value, to take a larger pivot: round-off's size, so no variable leaves
/// its bound by more.
constexpr double kHarrisTolerance = 1e-11;

/// The revised tableau: B⁻¹, the values of the basic variables, and which variable each row holds.
struct LemkeTableau {
  Eigen::MatrixXd basisInverse;
  Eigen::VectorXd basicValues;
  std::vector<int> basicVariable;
};

/// The column of the constraint matrix [I, −M, −d] that belongs to a variable.
Eigen::VectorXd constraintColumn(const Eigen::MatrixXd& m, const Eigen::VectorXd& covering,
                                 int variable) {
  const int n = static_cast<int>(m.rows());
  if (variable < n) return Eigen::VectorXd::Unit(n, variable);
  if (variable < 2 * n) return -m.col(variable - n);
  return -covering;
}

/// w_i and z_i are complements: exactly one of them may be basic at a solution.
int complement(int variable, int n) {
  return variable < n ? variable + n : variable - n;
}

/// The entering variable replaces the basic variable of `row`; `direction` is B⁻¹ times the
/// entering variable's column.
void pivot(LemkeTableau& tableau, const Eigen::VectorXd& direction, int row, int entering) {
  const Eigen::RowVectorXd pivotRow = tableau.basisInverse.row(row) / direction(row);
  const double pivotValue = tableau.basicValues(row) / direction(row);
  tableau.basisInverse.noalias() -= direction * pivotRow;
  tableau.basicValues -= pivotValue * direction;
  tableau.basisInverse.row(row) = pivotRow;
  tableau.basicValues(row) = pivotValue;
  tableau.basicVariable[row] = entering;
}

/// A ratio test reads only finite numbers: an overflowed tableau (huge velocities against tiny
/// masses) would make every ratio NaN and leave no candidate to pivot on.
bool isFinite(const LemkeTableau& tableau, const Eigen::VectorXd& direction) {
  return direction.allFinite() && tableau.basicValues.allFinite() &&
         tableau.basisInverse.allFinite();
}

/// The candidates whose ratio is smallest, within the relative tie tolerance.
template <class Ratio>
std::vector<int> smallestRatios(const std::vector<int>& candidates, const Ratio& ratio,
                                double tieTolerance) {
  double smallest = ratio(candidates.front());
  for (int row : candidates) smallest = std::min(smallest, ratio(row));
  const double tie = tieTolerance * std::max(1.0, std::abs(smallest));
  std::vector<int> kept;
  for (int row : candidates) {
    if (ratio(row) <= smallest + tie) kept.push_back(row);
  }
  return kept;
}

/// The lexicographic minimum ratio test: the row minimising (x_B,i, row i of B⁻¹) / yᵢ over the
/// rows with yᵢ > 0, compared entry by entry. It keeps the basis lexicographically positive,
/// which rules out cycling. The artificial variable wins any tie of the first entry. −1: no
/// row limits the step (a ray).
int leavingRow(const LemkeTableau& tableau, const Eigen::VectorXd& direction, int artificial) {
  const double smallestPivot = kPivotTolerance * std::max(1.0, direction.cwiseAbs().maxCoeff());
  std::vector<int> candidates;
  for (int row = 0; row < direction.size(); ++row) {
    if (direction(row) > smallestPivot) candidates.push_back(row);
  }
  if (candidates.empty()) return -1;
  candidates = smallestRatios(
      candidates, [&](int row) { return tableau.basicValues(row) / direction(row); },
      kTieTolerance);
  for (int row : candidates) {
    if (tableau.basicVariable[row] == artificial) return row;
  }
  for (int column = 0; candidates.size() > 1 && column < direction.size(); ++column) {
    candidates = smallestRatios(
        candidates, [&](int row) { return tableau.basisInverse(row, column) / direction(row); },
        kTieTolerance);
  }
  return candidates.front();
}

/// Harris's ratio test: the step may overshoot a basic variable by kHarrisTolerance (relative to
/// the largest basic value), and among the rows it then allows the one with the largest pivot is
/// taken. It trades the lexicographic rule's guard against cycling (the pivot limit still ends a
/// cycle) for never pivoting on a small entry when a larger one is nearly as good: on a landing
/// pile the lexicographic rule can take an entry of 1e-8, and the path never recovers.
int harrisLeavingRow(const LemkeTableau& tableau, const Eigen::VectorXd& direction,
                     int artificial) {
  const double smallestPivot = kPivotTolerance * std::max(1.0, direction.cwiseAbs().maxCoeff());
  const double slack = kHarrisTolerance * std::max(1.0, tableau.basicValues.cwiseAbs().maxCoeff());
  double bound = std::numeric_limits<double>::infinity();
  for (int row = 0; row < direction.size(); ++row) {
    if (direction(row) > smallestPivot) {
      bound = std::min(bound, (tableau.basicValues(row) + slack) / direction(row));
    }
  }
  int chosen = -1;
  for (int row = 0; row < direction.size(); ++row) {
    if (!(direction(row) > smallestPivot) || tableau.basicValues(row) / direction(row) > bound) {
      continue;
    }
    if (tableau.basicVariable[row] == artificial) return row;
    if (chosen < 0 || direction(row) > direction(chosen)) chosen = row;
  }
  return chosen;
}

/// The first pivot brings z0 in at the most negative q/d; ties go to the last such row, which is
/// the lexicographic choice for the start from B = I.
int firstLeavingRow(const Eigen::VectorXd& q, const Eigen::VectorXd& covering) {
  int row = 0;
  for (int i = 1; i < q.size(); ++i) {
    if (q(i) / covering(i) <= q(row) / covering(row)) row = i;
  }
  return row;
}

/// The row whose variable leaves next, by the path's ratio test; −1 on a ray.
int nextLeavingRow(const LemkeTableau& tableau, const Eigen::VectorXd& direction,
                   const LemkePath& path, int artificial) {
  return path.ratioTest == RatioTest::Harris ? harrisLeavingRow(tableau, direction, artificial)
                                             : leavingRow(tableau, direction, artificial);
}

/// The start B = I: every w basic, at its value in q.
LemkeTableau startingTableau(const Eigen::VectorXd& q) {
  const int n = static_cast<int>(q.size());
  LemkeTableau tableau{Eigen::MatrixXd::Identity(n, n), q, std::vector<int>(n)};
  for (int i = 0; i < n; ++i) tableau.basicVariable[i] = i;
  return tableau;
}

/// The most pivots a path on n variables may take: maxPivotsPerVariable each, at most maxPivots.
int pivotLimitOf(const LemkeSettings& options, int n) {
  return static_cast<int>(
      std::min<long>(options.maxPivots, static_cast<long>(options.maxPivotsPerVariable) * n));
}

/// The answer z = 0, w = q of a problem with q ≥ 0: no pivot needed.
LcpSolution zeroSolution(const Eigen::VectorXd& q) {
  LcpSolution solution;
  solution.z = Eigen::VectorXd::Zero(q.size());
  solution.w = q;
  solution.solved = true;
  return solution;
}

LcpSolution failed(LcpSolution solution, const std::string& reason) {
  solution.solved = false;
  solution.failure = reason;
  return solution;
}

/// z from the basic values of a finished path.
Eigen::VectorXd impulsesOf(const LemkeTableau& tableau, const Eigen::VectorXd& values, int n) {
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  for (int row = 0; row < n; ++row) {
    const int variable = tableau.basicVariable[row];
    if (variable >= n && variable < 2 * n) z(variable - n) = std::max(values(row), 0.0);
  }
  return z;
}

/// A natural residual below this (relative to 1 + the largest z) needs no refinement.
constexpr double kExactResidual = 1e-13;

/// The answer of a finished path. Where its natural residual is above round-off, the basic
/// values are solved afresh from the final basis (one factorization and one step of iterative
/// refinement): a long path of rank-one updates leaves round-off in B⁻¹ that this removes. Kept
/// only where it makes the answer better.
LcpSolution extractSolution(const LemkeTableau& tableau, const Eigen::MatrixXd& m,
                            const Eigen::VectorXd& q, const Eigen::VectorXd& covering,
                            LcpSolution solution) {
  const int n = static_cast<int>(q.size());
  solution.z = impulsesOf(tableau, tableau.basicValues, n);
  solution.w = m * solution.z + q;
  if (!solution.z.allFinite() || !solution.w.allFinite()) {
    return failed(solution, "Lemke: the answer is not finite");
  }
  solution.solved = true;
  const double exact = kExactResidual * (1.0 + solution.z.cwiseAbs().maxCoeff());
  if (solution.z.cwiseMin(solution.w).cwiseAbs().maxCoeff() <= exact) return solution;
  Eigen::MatrixXd basis(n, n);
  for (int row = 0; row < n; ++row) {
    basis.col(row) = constraintColumn(m, covering, tableau.basicVariable[row]);
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(basis);
  Eigen::VectorXd values = lu.solve(q);
  values += lu.solve(q - basis * values);
  const Eigen::VectorXd refined = impulsesOf(tableau, values, n);
  if (refined.allFinite() && naturalResidual(m, q, refined) < naturalResidual(m, q, solution.z)) {
    solution.z = refined;
  }
  solution.w = m * solution.z + q;
  solution.solved = true;
  return solution;
}

}  // namespace

LcpSolution solveLemke(const Eigen::MatrixXd& m, const Eigen::VectorXd& q,
                       const LemkeSettings& options) {
  return solveLemke(m, q, LemkePath{Eigen::VectorXd::Ones(q.size()), RatioTest::Lexicographic},
                    options);
}

LcpSolution solveLemke(const Eigen::MatrixXd& m, const Eigen::VectorXd& q, const LemkePath& path,
                       const LemkeSettings& options) {
  const int n = static_cast<int>(q.size());
  LcpSolution solution;
  if (!m.allFinite() || !q.allFinite()) {
    return failed(solution, "Lemke: the problem is not finite (a velocity or mass overflowed)");
  }
  if (n == 0 || q.minCoeff() >= 0.0) return zeroSolution(q);
  LemkeTableau tableau = startingTableau(q);
  const int artificial = 2 * n;
  int entering = artificial;
  const int pivotLimit = pivotLimitOf(options, n);
  Eigen::VectorXd direction = -path.covering;
  int row = firstLeavingRow(q, path.covering);
  for (solution.pivots = 1;; ++solution.pivots) {
    const int leaving = tableau.basicVariable[row];
    pivot(tableau, direction, row, entering);
    if (path.ratioTest == RatioTest::Harris)
      tableau.basicValues = tableau.basicValues.cwiseMax(0.0);
    if (leaving == artificial) return extractSolution(tableau, m, q, path.covering, solution);
    if (solution.pivots >= pivotLimit) {
      return failed(solution, "Lemke: pivot limit of " + std::to_string(pivotLimit) +
                                  " reached without a solution");
    }
    entering = complement(leaving, n);
    direction.noalias() = tableau.basisInverse * constraintColumn(m, path.covering, entering);
    if (!isFinite(tableau, direction)) {
      return failed(solution, "Lemke: the tableau overflowed after " +
                                  std::to_string(solution.pivots) + " pivots");
    }
    row = nextLeavingRow(tableau, direction, path, artificial);
    if (row < 0) {
      return failed(solution, "Lemke: secondary ray after " + std::to_string(solution.pivots) +
                                  " pivots (no solution found from this start)");
    }
  }
}

double naturalResidual(const Eigen::MatrixXd& m, const Eigen::VectorXd& q,
                       const Eigen::VectorXd& z) {
  if (q.size() == 0) return 0.0;
  return z.cwiseMin(m * z + q).cwiseAbs().maxCoeff();
}

}  // namespace impulse2d
