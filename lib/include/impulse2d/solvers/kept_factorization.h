// The factors of the last system an island's active set factorized (active_set.h), kept to the
// next step's solve, where GMRES on them takes the place of a factorization.
#pragma once

#include <memory>
#include <string>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "impulse2d/solvers/reference_solver_settings.h"

namespace impulse2d {

/// The corrections that take the regularization out stop once the residual of the unregularized
/// system is below this fraction of |b| + |A||x|: a thousandth of the reference's residual
/// tolerance, and above the floor that a pile's redundant rows leave.
constexpr double kRefinementTolerance = 1e-12;

/// One guess's linear system A x = b as the active set poses it, A = A₀ + S with S the
/// regularization on the diagonal: its products A x (taken through the bodies, at the cost of the
/// points' Jacobian rows), and its matrix only when it is factorized.
class PosedSystem {
 public:
  virtual ~PosedSystem() = default;
  /// unknowns
  virtual Eigen::Index size() const = 0;
  /// A x
  virtual Eigen::VectorXd times(const Eigen::VectorXd& x) const = 0;
  /// A
  virtual Eigen::SparseMatrix<double> matrix() const = 0;
  /// S's diagonal.
  virtual const Eigen::VectorXd& shift() const = 0;
  /// |A|, the largest sum of a row's magnitudes (or a bound on it): the scale of residuals.
  virtual double rowSum() const = 0;
};

/// The factors of the last system an island's active set factorized, kept to the next solve.
///
/// A resting pile poses next step the system of last step's states again, its values moved by
/// the bodies' small motion, or with the rows of a few points changed (a point on the friction
/// cone's edge whose sliding direction flipped). Each of its solves A x = b is then done by
/// GMRES preconditioned by the kept factors K: K⁻¹b is already close, and the Krylov space of
/// A K⁻¹ holds the rest in about one round per changed row, each round two triangular solves
/// and a product through the bodies instead of an assembly and a factorization. A system not
/// solved to round-off within a few rounds (many states flipped, another island) is factorized
/// after all; the answer is the same either way. A settling pile drifts from its kept factors and
/// needs a round every step: once such extra solves reach refactorAfterSolves, about a
/// factorization's cost, the next system is factorized afresh.
class KeptFactorization {
 public:
  KeptFactorization();
  ~KeptFactorization();
  KeptFactorization(const KeptFactorization&) = delete;
  KeptFactorization& operator=(const KeptFactorization&) = delete;

  /// Makes `system` the one solve() answers; it must outlive the calls to solve(). Factorizes
  /// at once unless `reuse` and factors of a system of the same size are kept. False (with
  /// lastError()) if that factorization fails.
  bool prepare(const PosedSystem& system, bool reuse, const ActiveSetSettings& settings);
  /// x with A₀x = b: A x = b + S·centre, the regularization centred on `centre` (a guess of x),
  /// then corrections (proximal point steps) that take what is left of it out; NaN if a needed
  /// factorization fails. A centre within ε of the answer leaves r·ε to take out.
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs, const Eigen::VectorXd& centre);

  /// made so far
  int factorizations() const { return factorizations_; }
  /// why the last one failed
  const std::string& lastError() const { return lastError_; }

 private:
  struct Factors;
  bool factorize();
  bool solveOnKeptFactors(const Eigen::VectorXd& rhs, Eigen::VectorXd& x);
  bool solveProximal(const Eigen::VectorXd& rhs, const Eigen::VectorXd& centre, Eigen::VectorXd& x);
  double residualScale(const Eigen::VectorXd& rhs, const Eigen::VectorXd& x) const;

  std::unique_ptr<Factors> factors_;
  const PosedSystem* system_ = nullptr;  ///< A, the system solve() answers
  ActiveSetSettings settings_;
  Eigen::Index factoredSize_ = 0;  ///< the size of the system the factors are of
  bool factorsValid_ = false;      ///< the factors hold a successful factorization
  bool fresh_ = false;             ///< the factors are system_'s own
  int factorizations_ = 0;
  int extraSolves_ = 0;  ///< kept factors' solves beyond a system's first two, since made
  std::string lastError_;
};

}  // namespace impulse2d
