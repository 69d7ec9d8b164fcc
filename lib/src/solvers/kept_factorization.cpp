// The factors the active set keeps from one step's last system to the next, and the GMRES that
// solves a system whose values moved a little on them.
#include "impulse2d/solvers/kept_factorization.h"

#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/SparseLU>

namespace impulse2d {
namespace {

// How far GMRES on kept factors goes before a factorization, and the factorization's pivot rule:
// they change what a solve costs, not its answer, and are not for tuning.

/// GMRES rounds on kept factors before the system is factorized after all, and then at most as
/// many corrections that take the regularization out: a system whose rows barely moved needs a
/// round or two, and each round costs a small share of a factorization.
constexpr int kKeptRounds = 8;
/// A solve on kept factors is done once the residual of A x = b is below this fraction of
/// |b| + |A||x| (largest entries, largest row sum): the round-off of a solve on fresh factors.
constexpr double kKeptTolerance = 1e-14;
/// The factorization takes a row's own diagonal entry as its pivot when that entry is at least
/// this fraction of the largest in its column, so the symmetric fill-reducing order holds;
/// below, it pivots on the largest. The regularized pivots of a redundant pile are about
/// `regularization` of their column and must pass; 1 would be partial pivoting.
constexpr double kDiagonalPivotThreshold = 1e-12;

}  // namespace

/// LU factors of P A Pᵀ, P a symmetric fill-reducing order (AMD on A's pattern, which is
/// symmetric: two points couple when they share a body) and the pivots A's own diagonal wherever
/// it is at least kDiagonalPivotThreshold of its column. A column order alone (COLAMD) with
/// partial pivoting, as for an unsymmetric matrix, fills far more entries on a large pile's
/// system (docs/design/reference-active-set.md), and the regularized pivots of a redundant pile
/// (about r) would be passed over for off-diagonal ones, breaking the symmetric order's fill.
struct KeptFactorization::Factors {
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;  ///< P⁻¹
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::NaturalOrdering<int>> lu;

  void compute(const Eigen::SparseMatrix<double>& system, double pivotThreshold) {
    Eigen::AMDOrdering<int>()(system, order);
    const Eigen::SparseMatrix<double> rows = order.inverse() * system;
    lu.setPivotThreshold(pivotThreshold);
    lu.compute(rows * order);
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const {
    return order * lu.solve(order.inverse() * rhs).eval();
  }
};

KeptFactorization::KeptFactorization() : factors_(std::make_unique<Factors>()) {}
KeptFactorization::~KeptFactorization() = default;

bool KeptFactorization::prepare(const PosedSystem& system, bool reuse,
                                const ActiveSetSettings& settings) {
  const bool sameSize = factorsValid_ && system.size() == factoredSize_;
  system_ = &system;
  settings_ = settings;
  fresh_ = false;
  if (!reuse || !sameSize || extraSolves_ >= settings.refactorAfterSolves) return factorize();
  return true;
}

/// The scale of a residual of A x = rhs: |rhs| + |A||x| (largest entries, largest row sum).
double KeptFactorization::residualScale(const Eigen::VectorXd& rhs,
                                        const Eigen::VectorXd& x) const {
  return rhs.cwiseAbs().maxCoeff() + system_->rowSum() * x.cwiseAbs().maxCoeff();
}

bool KeptFactorization::factorize() {
  factors_->compute(system_->matrix(), kDiagonalPivotThreshold);
  factoredSize_ = system_->size();
  ++factorizations_;
  extraSolves_ = 0;
  fresh_ = factorsValid_ = factors_->lu.info() == Eigen::Success;
  if (!fresh_) lastError_ = factors_->lu.lastErrorMessage();
  return fresh_;
}

namespace {

/// The Givens rotation (c, s) that turns (a, b) into (r, 0).
std::pair<double, double> givens(double a, double b) {
  const double r = std::hypot(a, b);
  return r > 0.0 ? std::pair{a / r, b / r} : std::pair{1.0, 0.0};
}

/// GMRES's small least-squares problem min |β e₁ − H y|, H the Hessenberg matrix the Arnoldi
/// process builds a column per round, kept upper triangular by Givens rotations; g is β e₁
/// rotated alike, so |g(j + 1)| is the residual's norm after round j.
struct GivensLeastSquares {
  GivensLeastSquares(int rounds, double beta)
      : hessenberg(Eigen::MatrixXd::Zero(rounds + 1, rounds)),
        g(Eigen::VectorXd::Zero(rounds + 1)) {
    g(0) = beta;
  }

  /// Turns column j of H upper triangular: the earlier rotations, then a new one that zeroes its
  /// entry below the diagonal, applied to g too.
  void rotateColumn(int j) {
    for (int i = 0; i < j; ++i) {
      const auto [c, s] = rotations[i];
      const double top = hessenberg(i, j);
      hessenberg(i, j) = c * top + s * hessenberg(i + 1, j);
      hessenberg(i + 1, j) = -s * top + c * hessenberg(i + 1, j);
    }
    rotations.push_back(givens(hessenberg(j, j), hessenberg(j + 1, j)));
    const auto [c, s] = rotations.back();
    hessenberg(j, j) = c * hessenberg(j, j) + s * hessenberg(j + 1, j);
    hessenberg(j + 1, j) = 0.0;
    g(j + 1) = -s * g(j);
    g(j) = c * g(j);
  }

  /// The residual's norm after round j.
  double residualNorm(int j) const { return std::abs(g(j + 1)); }

  /// y of rounds 0..j: the rotated problem's triangular solve.
  Eigen::VectorXd solution(int j) const {
    return hessenberg.topLeftCorner(j + 1, j + 1)
        .triangularView<Eigen::Upper>()
        .solve(g.head(j + 1));
  }

  Eigen::MatrixXd hessenberg;                        ///< H, its columns rotated so far
  std::vector<std::pair<double, double>> rotations;  ///< (c, s) of each column's rotation
  Eigen::VectorXd g;                                 ///< β e₁, rotated alike
};

}  // namespace

/// x with A x = rhs by GMRES preconditioned on the right by the kept factors K: from x = K⁻¹rhs,
/// the Krylov space of A K⁻¹ holds what K misses. A system whose values moved a little needs a
/// round or two, one with k rows changed (k states flipped since K) about k + 1. False if the
/// residual is not at round-off within kKeptRounds (K is too far from A).
bool KeptFactorization::solveOnKeptFactors(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) {
  const int rounds = kKeptRounds;
  x = factors_->solve(rhs);
  const double tolerance = kKeptTolerance * residualScale(rhs, x);
  const Eigen::VectorXd residual = rhs - system_->times(x);
  const double beta = residual.norm();
  if (residual.cwiseAbs().maxCoeff() <= tolerance) return true;
  std::vector<Eigen::VectorXd> basis{residual / beta};
  std::vector<Eigen::VectorXd> preconditioned;
  GivensLeastSquares leastSquares(rounds, beta);
  Eigen::MatrixXd& hessenberg = leastSquares.hessenberg;
  for (int j = 0; j < rounds; ++j) {
    ++extraSolves_;
    preconditioned.push_back(factors_->solve(basis[j]));
    Eigen::VectorXd w = system_->times(preconditioned.back());
    for (int i = 0; i <= j; ++i) {
      hessenberg(i, j) = w.dot(basis[i]);
      w -= hessenberg(i, j) * basis[i];
    }
    hessenberg(j + 1, j) = w.norm();
    basis.push_back(w / hessenberg(j + 1, j));
    leastSquares.rotateColumn(j);
    if (leastSquares.residualNorm(j) > tolerance) continue;
    const Eigen::VectorXd y = leastSquares.solution(j);
    for (int i = 0; i <= j; ++i) x += y(i) * preconditioned[i];
    return (rhs - system_->times(x)).cwiseAbs().maxCoeff() <= tolerance;
  }
  return false;
}

/// x with A₀x = rhs, A₀ the system without its regularization S (A = A₀ + S): one solve of
/// A x = rhs + S·centre (on the fresh factors, or by GMRES on kept ones), then corrections
/// x += K⁻¹(rhs − A₀x) by the factors K until A₀'s residual is below kRefinementTolerance of its
/// scale: at most `refinements` on fresh factors, kKeptRounds on kept ones. On fresh factors
/// (K = A) each correction is a proximal point step, the solve of A x' = rhs + S x, so the
/// velocity rows end exact while redundant contacts keep the split the first solve chose, near
/// the centre's. A centre within ε of the answer leaves about r·ε, often none to correct. On kept
/// factors K only approximates A and each correction still shrinks the residual by about
/// |K⁻¹(A − K)| + |S|: one correction instead of a GMRES solve per proximal step. False if a
/// solve on kept factors does not reach its tolerance (the caller then factorizes).
bool KeptFactorization::solveProximal(const Eigen::VectorXd& rhs, const Eigen::VectorXd& centre,
                                      Eigen::VectorXd& x) {
  const Eigen::VectorXd centred = rhs + system_->shift().cwiseProduct(centre);
  if (fresh_) {
    x = factors_->solve(centred);
  } else if (!solveOnKeptFactors(centred, x)) {
    return false;
  }
  const int corrections = fresh_ ? settings_.refinements : kKeptRounds;
  for (int k = 0;; ++k) {
    Eigen::VectorXd residual = rhs - system_->times(x);
    residual += system_->shift().cwiseProduct(x);
    if (residual.cwiseAbs().maxCoeff() <= kRefinementTolerance * residualScale(rhs, x)) {
      return true;
    }
    if (k == corrections) return fresh_;
    if (!fresh_ && k > 0) ++extraSolves_;
    x += factors_->solve(residual);
  }
}

Eigen::VectorXd KeptFactorization::solve(const Eigen::VectorXd& rhs,
                                         const Eigen::VectorXd& centre) {
  Eigen::VectorXd x;
  if (!fresh_ && solveProximal(rhs, centre, x)) return x;
  if (!fresh_ && !factorize()) return Eigen::VectorXd::Constant(rhs.size(), std::nan(""));
  solveProximal(rhs, centre, x);
  return x;
}

}  // namespace impulse2d
