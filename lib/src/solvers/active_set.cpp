// The active-set method: guess the states, solve the KKT system, flip what it violates.
#include "impulse2d/solvers/active_set.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "compressed_columns.h"

namespace impulse2d {
namespace {

using Sparse = Eigen::SparseMatrix<double>;

/// A set of states solved this often again means the flips cycle: the flip rule's counters may
/// send a second visit elsewhere, a third no more.
constexpr int kVisitsBeforeCycling = 2;

/// A point whose answer breaks its state, the state it should take and by how much (N s).
struct Violation {
  int point = 0;
  ContactState next = ContactState::Separated;
  double amount = 0.0;
};

/// The velocities (normal minus target, tangent) the points would have without impulses.
Eigen::VectorXd freeVelocity(const IslandProblem& problem) {
  const int count = static_cast<int>(problem.points.size());
  Eigen::VectorXd free(2 * count);
  for (int i = 0; i < count; ++i) {
    const IslandPoint& point = problem.points[static_cast<size_t>(i)];
    for (int axis = 0; axis < 2; ++axis) {
      double v = point.staticVelocity[static_cast<size_t>(axis)];
      for (int side = 0; side < 2; ++side) {
        const int body = point.body[static_cast<size_t>(side)];
        if (body < 0) continue;
        v += point.jacobian[static_cast<size_t>(axis)][static_cast<size_t>(side)].dot(
            problem.velocity.segment<3>(3 * body));
      }
      free(2 * i + axis) = v;
    }
    free(2 * i) -= point.targetNormalVelocity;
  }
  return free;
}

/// The point of impulse k (2 per point: λn, λt).
const IslandPoint& pointOf(const IslandProblem& problem, int k) {
  return problem.points[static_cast<size_t>(k / 2)];
}

/// The bodies' velocity change M⁻¹Jᵀλ from the points' impulses λ (2 per point).
Eigen::VectorXd bodyChange(const IslandProblem& problem, const Eigen::VectorXd& impulses) {
  Eigen::VectorXd change = Eigen::VectorXd::Zero(problem.velocity.size());
  for (int k = 0; k < impulses.size(); ++k) {
    if (impulses(k) == 0.0) continue;
    addBodyVelocityChange(pointOf(problem, k), k % 2, impulses(k), problem.inverseMass, change);
  }
  return change;
}

}  // namespace

Eigen::VectorXd delassusTimes(const IslandProblem& problem, const Eigen::VectorXd& impulses) {
  const Eigen::VectorXd change = bodyChange(problem, impulses);
  Eigen::VectorXd velocity(impulses.size());
  for (int k = 0; k < impulses.size(); ++k) {
    velocity(k) = jacobianTimes(pointOf(problem, k), k % 2, change);
  }
  return velocity;
}

namespace {

/// Whether the point starts the solve from last step's state and impulses (it was solved then,
/// matched by feature id, and warm states are on).
bool startsFromLastStep(const IslandPoint& point, const ActiveSetSettings& settings) {
  return settings.warmStates && point.carried;
}

}  // namespace

bool needsGuessSweeps(const IslandProblem& problem, const ActiveSetSettings& settings) {
  return std::any_of(problem.points.begin(), problem.points.end(), [&](const IslandPoint& point) {
    return !startsFromLastStep(point, settings);
  });
}

Eigen::VectorXd delassusDiagonal(const IslandProblem& problem) {
  Eigen::VectorXd diagonal(2 * static_cast<int>(problem.points.size()));
  for (int k = 0; k < diagonal.size(); ++k) {
    diagonal(k) = inverseEffectiveMass(pointOf(problem, k), k % 2, problem.inverseMass);
  }
  return diagonal;
}

namespace {

/// The guess put inside the cone: normal impulse ≥ 0, friction within μ of it.
Eigen::VectorXd projectedGuess(const IslandProblem& problem) {
  Eigen::VectorXd impulses = problem.guess;
  for (int i = 0; i < static_cast<int>(problem.points.size()); ++i) {
    const double limit =
        problem.points[static_cast<size_t>(i)].friction * std::max(impulses(2 * i), 0.0);
    impulses(2 * i) = std::max(impulses(2 * i), 0.0);
    impulses(2 * i + 1) = std::clamp(impulses(2 * i + 1), -limit, limit);
  }
  return impulses;
}

/// v += column k of the Delassus matrix times delta (it is symmetric: the column is the row).
void addColumn(const Sparse& delassus, int k, double delta, Eigen::VectorXd& velocity) {
  for (Sparse::InnerIterator it(delassus, k); it; ++it) velocity(it.row()) += it.value() * delta;
}

/// One projected Gauss–Seidel sweep; whether it changed some point's state.
bool gaussSeidelSweep(const IslandProblem& problem, const Eigen::VectorXd& diagonal,
                      Eigen::VectorXd& impulses, Eigen::VectorXd& velocity) {
  bool changed = false;
  for (int i = 0; i < static_cast<int>(problem.points.size()); ++i) {
    const double friction = problem.points[static_cast<size_t>(i)].friction;
    const ContactState before = stateOfImpulses(impulses(2 * i), impulses(2 * i + 1), friction);
    for (int axis = 0; axis < 2; ++axis) {
      const int k = 2 * i + axis;
      double next = impulses(k) - velocity(k) / diagonal(k);
      const double limit = friction * impulses(2 * i);
      next = axis == 0 ? std::max(next, 0.0) : std::clamp(next, -limit, limit);
      addColumn(problem.delassus, k, next - impulses(k), velocity);
      impulses(k) = next;
    }
    changed = changed || before != stateOfImpulses(impulses(2 * i), impulses(2 * i + 1), friction);
  }
  return changed;
}

/// Projected Gauss–Seidel sweeps from the guess: at least guessSweeps, then on while a sweep
/// still changes some point's state, up to maxGuessSweeps. From zero impulses (a pile's first
/// step) the weight reaches the bottom of a pile about one row a sweep, and the states settle
/// only after that.
Eigen::VectorXd gaussSeidelGuess(const IslandProblem& problem, const Eigen::VectorXd& free,
                                 const Eigen::VectorXd& diagonal,
                                 const ActiveSetSettings& settings) {
  Eigen::VectorXd impulses = projectedGuess(problem);
  Eigen::VectorXd velocity = free + problem.delassus * impulses;
  int sweep = 0;
  bool changed = true;
  while (sweep < settings.maxGuessSweeps && (changed || sweep < settings.guessSweeps)) {
    changed = gaussSeidelSweep(problem, diagonal, impulses, velocity);
    ++sweep;
  }
  return impulses;
}

/// The KKT system of one guess of the states, assembled column by column in Eigen's compressed
/// form (each column's rows in increasing order, as setFromTriplets would leave them, without
/// its sort). Unknowns: 3 per body (vx, vy, ω), then 2 per point (λn, λt). Rows:
///   body rows       u − M⁻¹Jᵀλ = u₀, the same whatever the states;
///   point rows      separated: λn = 0, λt = 0; otherwise J u + r λ = target along the normal,
///                   and along the tangent J u + r λ = 0 (sticking) or λt ∓ μλn = 0 (sliding);
/// r, the regularization, is kept in `shift` so solveProximal can take it out again.
class SystemAssembly {
 public:
  explicit SystemAssembly(const IslandProblem& problem)
      : problem_(problem),
        bodyUnknowns_(static_cast<int>(problem.velocity.size())),
        pointsOfBody_(static_cast<size_t>(bodyUnknowns_ / 3)) {
    for (int i = 0; i < pointCount(); ++i) {
      for (int side = 0; side < 2; ++side) {
        const int body = point(i).body[static_cast<size_t>(side)];
        if (body >= 0) pointsOfBody_[static_cast<size_t>(body)].push_back({i, side});
      }
    }
  }

  /// The system for `states`; rhs and shift are filled alongside.
  Sparse assemble(const std::vector<ContactState>& states, const Eigen::VectorXd& diagonal,
                  double regularization, Eigen::VectorXd& rhs, Eigen::VectorXd& shift) const {
    const int size = bodyUnknowns_ + 2 * pointCount();
    rhs = Eigen::VectorXd::Zero(size);
    rhs.head(bodyUnknowns_) = problem_.velocity;
    shift = Eigen::VectorXd::Zero(2 * pointCount());
    CompressedColumns columns(size, countEntries(states));
    for (int c = 0; c < bodyUnknowns_; ++c) addBodyColumn(c, states, columns);
    for (int i = 0; i < pointCount(); ++i) {
      addPointColumns(i, states, diagonal, regularization, rhs, shift, columns);
    }
    return columns.matrix();
  }

 private:
  struct Incidence {
    int point;
    int side;
  };
  const IslandPoint& point(int i) const { return problem_.points[static_cast<size_t>(i)]; }
  int pointCount() const { return static_cast<int>(problem_.points.size()); }
  static int velocityRows(ContactState state) {
    if (state == ContactState::Separated) return 0;
    return state == ContactState::Sticking ? 2 : 1;
  }

  size_t countEntries(const std::vector<ContactState>& states) const {
    size_t entries = static_cast<size_t>(bodyUnknowns_);
    for (int i = 0; i < pointCount(); ++i) {
      const ContactState state = states[static_cast<size_t>(i)];
      const int bodies = (point(i).body[0] >= 0) + (point(i).body[1] >= 0);
      entries += static_cast<size_t>(3 * bodies * (2 + velocityRows(state)));  // M⁻¹Jᵀ, J
      entries += state == ContactState::Separated || state == ContactState::Sticking ? 2 : 3;
    }
    return entries;
  }

  /// Column c of a body unknown: its identity entry, then J's entries of the velocity rows of
  /// the points it touches, in the points' order.
  void addBodyColumn(int c, const std::vector<ContactState>& states,
                     CompressedColumns& column) const {
    column.add(c, 1.0);
    for (const Incidence& incidence : pointsOfBody_[static_cast<size_t>(c / 3)]) {
      const int rows = velocityRows(states[static_cast<size_t>(incidence.point)]);
      for (int axis = 0; axis < rows; ++axis) {
        const Eigen::Vector3d& coefficients =
            point(incidence.point)
                .jacobian[static_cast<size_t>(axis)][static_cast<size_t>(incidence.side)];
        column.add(bodyUnknowns_ + 2 * incidence.point + axis, coefficients(c % 3));
      }
    }
    column.close();
  }

  /// The columns of a point's λn and λt: −M⁻¹Jᵀ in the rows of its bodies (in increasing
  /// order), then its own rows.
  void addPointColumns(int i, const std::vector<ContactState>& states,
                       const Eigen::VectorXd& diagonal, double regularization, Eigen::VectorXd& rhs,
                       Eigen::VectorXd& shift, CompressedColumns& column) const {
    const IslandPoint& p = point(i);
    const ContactState state = states[static_cast<size_t>(i)];
    const int normal = bodyUnknowns_ + 2 * i;
    const int tangent = normal + 1;
    const std::array<int, 2> sides = p.body[1] >= 0 && (p.body[0] < 0 || p.body[1] < p.body[0])
                                         ? std::array{1, 0}
                                         : std::array{0, 1};
    for (int axis = 0; axis < 2; ++axis) {
      for (const int side : sides) {
        const int body = p.body[static_cast<size_t>(side)];
        if (body < 0) continue;
        const Eigen::Vector3d& row =
            p.jacobian[static_cast<size_t>(axis)][static_cast<size_t>(side)];
        for (int c = 0; c < 3; ++c) {
          column.add(3 * body + c, -problem_.inverseMass(3 * body + c) * row(c));
        }
      }
      const int own = normal + axis;
      if (state == ContactState::Separated) {
        column.add(own, 1.0);
      } else if (axis == 0 || state == ContactState::Sticking) {
        const double r = regularization * diagonal(2 * i + axis);
        column.add(own, r);
        shift(2 * i + axis) = r;
      } else {
        column.add(own, 1.0);  // sliding: λt ∓ μλn = 0
      }
      if (axis == 0 &&
          (state == ContactState::SlidingPositive || state == ContactState::SlidingNegative)) {
        const double sign = state == ContactState::SlidingPositive ? 1.0 : -1.0;
        column.add(tangent, sign * p.friction);
      }
      column.close();
    }
    if (state == ContactState::Separated) return;
    rhs(normal) = p.targetNormalVelocity - p.staticVelocity[0];
    if (state == ContactState::Sticking) rhs(tangent) = -p.staticVelocity[1];
  }

  const IslandProblem& problem_;
  const int bodyUnknowns_;
  std::vector<std::vector<Incidence>> pointsOfBody_;  ///< by island body, in the points' order
};

/// What the answer breaks, point by point: a pull, a closing separated point, friction beyond
/// the cone while sticking, a slide against its friction. In N s (velocities times the point's
/// mass), so one tolerance serves all.
std::vector<Violation> violations(const IslandProblem& problem,
                                  const std::vector<ContactState>& states,
                                  const Eigen::VectorXd& impulses, const Eigen::VectorXd& velocity,
                                  const Eigen::VectorXd& diagonal, double tolerance) {
  std::vector<Violation> found;
  for (int i = 0; i < static_cast<int>(problem.points.size()); ++i) {
    const double mu = problem.points[static_cast<size_t>(i)].friction;
    const double normal = impulses(2 * i);
    const double tangent = impulses(2 * i + 1);
    const double slip = velocity(2 * i + 1) / diagonal(2 * i + 1);
    const ContactState state = states[static_cast<size_t>(i)];
    const ContactState touching = mu > 0.0 ? ContactState::Sticking : ContactState::SlidingPositive;
    if (state == ContactState::Separated) {
      const double closing = -velocity(2 * i) / diagonal(2 * i);
      if (closing > tolerance) found.push_back({i, touching, closing});
    } else if (-normal > tolerance) {
      found.push_back({i, ContactState::Separated, -normal});
    } else if (state == ContactState::Sticking && std::abs(tangent) - mu * normal > tolerance) {
      found.push_back(
          {i, tangent < 0.0 ? ContactState::SlidingPositive : ContactState::SlidingNegative,
           std::abs(tangent) - mu * normal});
    } else if (mu > 0.0 && state == ContactState::SlidingPositive && -slip > tolerance) {
      found.push_back({i, ContactState::Sticking, -slip});
    } else if (mu > 0.0 && state == ContactState::SlidingNegative && slip > tolerance) {
      found.push_back({i, ContactState::Sticking, slip});
    }
  }
  return found;
}

/// N s: the size of the island's impulses, for the flip tolerance.
double impulseScale(const Eigen::VectorXd& impulses, const Eigen::VectorXd& free,
                    const Eigen::VectorXd& diagonal) {
  double scale = impulses.size() > 0 ? impulses.cwiseAbs().maxCoeff() : 0.0;
  for (int k = 0; k < free.size(); ++k) scale = std::max(scale, std::abs(free(k)) / diagonal(k));
  return scale;
}

/// A separated point's impulses are zero by its state, but the solve leaves round-off there
/// (1e-16 N s on a 40-row pyramid): next step's warm states would read that as a touching
/// point, and about 50 such points a step would pull at the first factorization.
void zeroSeparated(const std::vector<ContactState>& states, Eigen::VectorXd& impulses) {
  for (size_t i = 0; i < states.size(); ++i) {
    if (states[i] == ContactState::Separated) impulses.segment<2>(2 * Eigen::Index(i)).setZero();
  }
}

/// Júdice–Pires: flip every violator while their number falls (or for a few tries after), else
/// only the worst, until the number falls below the best seen. With backtracking, a flip that
/// does not lower the number below the best goes back to the best states instead and flips
/// half as many of their violators, the worst first, then a quarter, … down to one; only then
/// one at a time from where it is.
class FlipRule {
 public:
  explicit FlipRule(const ActiveSetSettings& settings)
      : blockFailures_(settings.blockFailures), backtrack_(settings.backtrack) {}

  void apply(const std::vector<Violation>& found, std::vector<ContactState>& states) {
    const int count = static_cast<int>(found.size());
    if (count < best_) {
      best_ = count;
      failures_ = 0;
      bestStates_ = states;
      bestFound_ = found;
      std::sort(bestFound_.begin(), bestFound_.end(),
                [](const Violation& x, const Violation& y) { return x.amount > y.amount; });
      flip(found, found.size(), states);
      return;
    }
    ++failures_;
    if (backtrack_) {
      const bool halvings = failures_ < std::numeric_limits<size_t>::digits;
      const size_t share = halvings ? bestFound_.size() >> failures_ : 0;
      if (share > 0) {
        states = bestStates_;
        flip(bestFound_, share, states);
        return;
      }
    } else if (failures_ <= blockFailures_) {
      flip(found, found.size(), states);
      return;
    }
    flipWorst(found, states);
  }

 private:
  static void flip(const std::vector<Violation>& found, size_t count,
                   std::vector<ContactState>& states) {
    for (size_t k = 0; k < count; ++k) states[static_cast<size_t>(found[k].point)] = found[k].next;
  }

  /// One at a time, the worst first; with backtracking, not the point flipped just before (on a
  /// degenerate pile flipping it back returns to the states before: a cycle of two).
  void flipWorst(const std::vector<Violation>& found, std::vector<ContactState>& states) {
    const Violation* worst = nullptr;
    for (const Violation& v : found) {
      const bool tabu = backtrack_ && v.point == lastFlipped_ && found.size() > 1;
      if (!tabu && (worst == nullptr || v.amount > worst->amount)) worst = &v;
    }
    states[static_cast<size_t>(worst->point)] = worst->next;
    lastFlipped_ = worst->point;
  }

  int blockFailures_;
  bool backtrack_;
  int lastFlipped_ = -1;
  int best_ = std::numeric_limits<int>::max();
  int failures_ = 0;
  std::vector<ContactState> bestStates_;
  std::vector<Violation> bestFound_;  ///< the best states' violators, the worst first
};

/// Each point's first state: with warmStates, a point solved last step takes the state it was
/// solved in (or, solved by Lemke or another method, the state of its impulses); the others
/// (all of them without warmStates) the state the Gauss–Seidel sweeps from the guess give, and
/// the sweeps run only if some point needs them.
std::vector<ContactState> guessStates(const IslandProblem& problem, const Eigen::VectorXd& free,
                                      const Eigen::VectorXd& diagonal,
                                      const ActiveSetSettings& settings) {
  const Eigen::VectorXd swept = needsGuessSweeps(problem, settings)
                                    ? gaussSeidelGuess(problem, free, diagonal, settings)
                                    : Eigen::VectorXd();
  std::vector<ContactState> states(problem.points.size());
  for (int i = 0; i < static_cast<int>(problem.points.size()); ++i) {
    const IslandPoint& point = problem.points[static_cast<size_t>(i)];
    if (startsFromLastStep(point, settings) && point.lastState != ContactState::Unknown) {
      states[static_cast<size_t>(i)] = point.lastState;
      continue;
    }
    const Eigen::VectorXd& impulses = startsFromLastStep(point, settings) ? problem.guess : swept;
    states[static_cast<size_t>(i)] =
        stateOfImpulses(impulses(2 * i), impulses(2 * i + 1), point.friction);
  }
  return states;
}

}  // namespace

struct KeptFactorization::Factors {
  Eigen::SparseLU<Sparse, Eigen::COLAMDOrdering<int>> lu;
};

KeptFactorization::KeptFactorization() : factors_(std::make_unique<Factors>()) {}
KeptFactorization::~KeptFactorization() = default;

bool KeptFactorization::prepare(Sparse system, const Eigen::VectorXd& shift, bool reuse,
                                const ActiveSetSettings& settings) {
  const bool sameSize = factorsValid_ && system.rows() == system_.rows();
  system_ = std::move(system);
  shift_ = shift;
  settings_ = settings;
  fresh_ = false;
  Eigen::VectorXd sums = Eigen::VectorXd::Zero(system_.rows());
  for (int c = 0; c < system_.outerSize(); ++c) {
    for (Sparse::InnerIterator it(system_, c); it; ++it) sums(it.row()) += std::abs(it.value());
  }
  rowSum_ = sums.maxCoeff();
  if (!reuse || !sameSize) return factorize();
  return true;
}

/// The scale of a residual of A x = rhs: |rhs| + |A||x| (largest entries, largest row sum).
double KeptFactorization::residualScale(const Eigen::VectorXd& rhs,
                                        const Eigen::VectorXd& x) const {
  return rhs.cwiseAbs().maxCoeff() + rowSum_ * x.cwiseAbs().maxCoeff();
}

bool KeptFactorization::factorize() {
  factors_->lu.compute(system_);
  ++factorizations_;
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

}  // namespace

/// x with A x = rhs by GMRES preconditioned on the right by the kept factors K: from x = K⁻¹rhs,
/// the Krylov space of A K⁻¹ holds what K misses. A system whose values moved a little needs a
/// round or two, one with k rows changed (k states flipped since K) about k + 1. False if the
/// residual is not at round-off within keptRounds (K is too far from A).
bool KeptFactorization::solveOnKeptFactors(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) const {
  const int rounds = settings_.keptRounds;
  x = factors_->lu.solve(rhs);
  const double tolerance = settings_.keptTolerance * residualScale(rhs, x);
  const Eigen::VectorXd residual = rhs - system_ * x;
  const double beta = residual.norm();
  if (residual.cwiseAbs().maxCoeff() <= tolerance) return true;
  std::vector<Eigen::VectorXd> basis{residual / beta};
  std::vector<Eigen::VectorXd> preconditioned;
  Eigen::MatrixXd hessenberg = Eigen::MatrixXd::Zero(rounds + 1, rounds);
  std::vector<std::pair<double, double>> rotations;
  Eigen::VectorXd g = Eigen::VectorXd::Zero(rounds + 1);
  g(0) = beta;
  for (int j = 0; j < rounds; ++j) {
    preconditioned.push_back(factors_->lu.solve(basis[static_cast<size_t>(j)]));
    Eigen::VectorXd w = system_ * preconditioned.back();
    for (int i = 0; i <= j; ++i) {
      hessenberg(i, j) = w.dot(basis[static_cast<size_t>(i)]);
      w -= hessenberg(i, j) * basis[static_cast<size_t>(i)];
    }
    hessenberg(j + 1, j) = w.norm();
    basis.push_back(w / hessenberg(j + 1, j));
    for (int i = 0; i < j; ++i) {
      const auto [c, s] = rotations[static_cast<size_t>(i)];
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
    if (std::abs(g(j + 1)) > tolerance) continue;
    const Eigen::VectorXd y =
        hessenberg.topLeftCorner(j + 1, j + 1).triangularView<Eigen::Upper>().solve(g.head(j + 1));
    for (int i = 0; i <= j; ++i) x += y(i) * preconditioned[static_cast<size_t>(i)];
    return (rhs - system_ * x).cwiseAbs().maxCoeff() <= tolerance;
  }
  return false;
}

/// x with A₀x = rhs, A₀ the system without its regularization S (A = A₀ + S): one solve of
/// A x = rhs (on the fresh factors, or by GMRES on kept ones), then corrections
/// x += K⁻¹(rhs − A₀x) by the factors K until A₀'s residual is below refinementTolerance of its
/// scale: at most `refinements` on fresh factors, `keptRounds` on kept ones. On fresh factors
/// (K = A) each correction is a proximal point step, the solve of A x' = rhs + S x, so the
/// velocity rows end exact while redundant contacts keep the split the first solve chose. On kept
/// factors K only approximates A and each correction still shrinks the residual by about
/// |K⁻¹(A − K)| + |S|: one correction instead of a GMRES solve per proximal step. False if a
/// solve on kept factors does not reach its tolerance (the caller then factorizes).
bool KeptFactorization::solveProximal(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) const {
  if (fresh_) {
    x = factors_->lu.solve(rhs);
  } else if (!solveOnKeptFactors(rhs, x)) {
    return false;
  }
  const Eigen::Index impulses = shift_.size();
  const int corrections = fresh_ ? settings_.refinements : settings_.keptRounds;
  for (int k = 0;; ++k) {
    Eigen::VectorXd residual = rhs - system_ * x;
    residual.tail(impulses) += shift_.cwiseProduct(x.tail(impulses));
    if (residual.cwiseAbs().maxCoeff() <= settings_.refinementTolerance * residualScale(rhs, x)) {
      return true;
    }
    if (k == corrections) return fresh_;
    x += factors_->lu.solve(residual);
  }
}

Eigen::VectorXd KeptFactorization::solve(const Eigen::VectorXd& rhs) {
  Eigen::VectorXd x;
  if (!fresh_ && solveProximal(rhs, x)) return x.tail(shift_.size());
  if (!fresh_ && !factorize()) return Eigen::VectorXd::Constant(shift_.size(), std::nan(""));
  solveProximal(rhs, x);
  return x.tail(shift_.size());
}

ContactState stateOfImpulses(double normalImpulse, double tangentImpulse, double friction) {
  if (!(normalImpulse > 0.0)) return ContactState::Separated;
  const double limit = friction * normalImpulse * (1.0 - 1e-9);
  if (tangentImpulse <= -limit) return ContactState::SlidingPositive;
  if (tangentImpulse >= limit && friction > 0.0) return ContactState::SlidingNegative;
  return ContactState::Sticking;
}

ActiveSetAnswer solveActiveSet(const IslandProblem& problem, const ActiveSetSettings& settings,
                               KeptFactorization& kept) {
  const Eigen::VectorXd diagonal = delassusDiagonal(problem);
  const Eigen::VectorXd free = freeVelocity(problem);
  std::vector<ContactState> states = guessStates(problem, free, diagonal, settings);
  const SystemAssembly assembly(problem);
  FlipRule flips(settings);
  ActiveSetAnswer answer;
  const int factorizationsBefore = kept.factorizations();
  std::unordered_map<std::string, int> visits;  // how often each set of states was solved
  // Only the step's first system is solved on kept factors: after a flip, the flipped rows
  // differ from every earlier system (a block flip changes many), and the path of the flips
  // stays the one fresh factorizations take.
  bool firstSystem = true;
  while (answer.factorizations < settings.maxFactorizations) {
    std::string key(states.size(), '\0');
    for (size_t i = 0; i < states.size(); ++i) key[i] = static_cast<char>(states[i]);
    if (++visits[key] > kVisitsBeforeCycling) {
      answer.failure = "active set: cycling (the same states solved " +
                       std::to_string(kVisitsBeforeCycling + 1) + " times by factorization " +
                       std::to_string(answer.factorizations) + ")";
      return answer;
    }
    Eigen::VectorXd rhs;
    Eigen::VectorXd shift;
    Sparse system = assembly.assemble(states, diagonal, settings.regularization, rhs, shift);
    const bool prepared =
        kept.prepare(std::move(system), shift, firstSystem && settings.keepFactors, settings);
    firstSystem = false;
    if (prepared) answer.impulses = kept.solve(rhs);
    answer.factorizations = kept.factorizations() - factorizationsBefore;
    if (!prepared || !answer.impulses.allFinite()) {
      answer.failure = "active set: singular system at factorization " +
                       std::to_string(answer.factorizations) + " (" + kept.lastError() + ")";
      return answer;
    }
    zeroSeparated(states, answer.impulses);
    const Eigen::VectorXd velocity = free + delassusTimes(problem, answer.impulses);
    const double tolerance = settings.flipTolerance * impulseScale(answer.impulses, free, diagonal);
    const std::vector<Violation> found =
        violations(problem, states, answer.impulses, velocity, diagonal, tolerance);
    if (found.empty()) {
      answer.solved = true;
      answer.states = states;
      return answer;
    }
    flips.apply(found, states);
  }
  answer.failure = "active set: factorization limit of " +
                   std::to_string(settings.maxFactorizations) + " reached";
  return answer;
}

}  // namespace impulse2d
