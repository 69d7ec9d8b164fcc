// The active-set method: guess the states, solve for the impulses they leave unknown, flip what
// the answer violates.
#include "impulse2d/solvers/active_set.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <optional>
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
/// After guessSweeps, the guess's sweeps go on while one still changes a point's state, up to
/// this many: a pile's first step starts from zero impulses, and its states settle only once the
/// weight has reached the bottom, about one row a sweep. The sweeps only guess: the answer does
/// not depend on where they stop.
constexpr int kMaxGuessSweeps = 400;
/// A condition counts as violated beyond this fraction of the island's impulse scale: far below
/// the residual tolerance the answer is checked to, and above round-off, so round-off flips
/// nothing.
constexpr double kFlipTolerance = 1e-12;
/// Under Júdice–Pires: block flips in a row that do not lower the number of violated points
/// before the method flips one point at a time (their method's p).
constexpr int kJudicePiresBlockFailures = 3;

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
    const IslandPoint& point = problem.points[i];
    for (int axis = 0; axis < 2; ++axis) {
      free(2 * i + axis) = jacobianTimes(point, axis, problem.velocity, point.staticVelocity[axis]);
    }
    free(2 * i) -= point.targetNormalVelocity;
  }
  return free;
}

/// The point of impulse k (2 per point: λn, λt).
const IslandPoint& pointOf(const IslandProblem& problem, int k) {
  return problem.points[k / 2];
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
    const double limit = problem.points[i].friction * std::max(impulses(2 * i), 0.0);
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
    const double friction = problem.points[i].friction;
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
/// still changes some point's state, up to kMaxGuessSweeps.
Eigen::VectorXd gaussSeidelGuess(const IslandProblem& problem, const Eigen::VectorXd& free,
                                 const Eigen::VectorXd& diagonal,
                                 const ActiveSetSettings& settings) {
  Eigen::VectorXd impulses = projectedGuess(problem);
  Eigen::VectorXd velocity = free + problem.delassus * impulses;
  int sweep = 0;
  bool changed = true;
  const int most = std::max(kMaxGuessSweeps, settings.guessSweeps);
  while (sweep < most && (changed || sweep < settings.guessSweeps)) {
    changed = gaussSeidelSweep(problem, diagonal, impulses, velocity);
    ++sweep;
  }
  return impulses;
}

/// Which points couple in W (they share a body) and through which sides, point by point in
/// increasing order: the pattern of every guess's matrix, built once per solve, on its first
/// factorization (a resting pile's step on kept factors needs none).
class Neighbours {
 public:
  /// Point j next to point i: the bodies they share, as (j's side, i's side).
  struct Coupling {
    int point = 0;
    int shared = 0;
    std::array<std::array<int, 2>, 2> sides{};
  };
  struct Range {
    const Coupling* first;
    const Coupling* last;
    const Coupling* begin() const { return first; }
    const Coupling* end() const { return last; }
  };

  explicit Neighbours(const IslandProblem& problem) {
    const int count = static_cast<int>(problem.points.size());
    std::vector<std::vector<int>> pointsOfBody(problem.velocity.size() / 3);
    for (int i = 0; i < count; ++i) {
      for (const int body : problem.points[i].body) {
        if (body >= 0) pointsOfBody[body].push_back(i);
      }
    }
    first_.reserve(count + 1);
    first_.push_back(0);
    const std::vector<int> none;
    for (int i = 0; i < count; ++i) {
      const std::array<int, 2>& bodies = problem.points[i].body;
      const std::vector<int>& a = bodies[0] >= 0 ? pointsOfBody[bodies[0]] : none;
      const std::vector<int>& b = bodies[1] >= 0 ? pointsOfBody[bodies[1]] : none;
      mergeNext(problem, i, a, b);
      first_.push_back(static_cast<int>(couplings_.size()));
    }
  }

  Range of(int i) const {
    const Coupling* all = couplings_.data();
    return {all + first_[i], all + first_[i + 1]};
  }

 private:
  /// Appends point i's neighbours: the points of its body on side 0 (list a) and on side 1
  /// (list b), both in increasing order, merged; a point in both shares both bodies.
  void mergeNext(const IslandProblem& problem, int i, const std::vector<int>& a,
                 const std::vector<int>& b) {
    const std::array<int, 2>& bodies = problem.points[i].body;
    const int countA = static_cast<int>(a.size());
    const int countB = static_cast<int>(b.size());
    int ia = 0;
    int ib = 0;
    while (ia < countA || ib < countB) {
      const int j = std::min(ia < countA ? a[ia] : INT_MAX, ib < countB ? b[ib] : INT_MAX);
      Coupling c;
      c.point = j;
      const std::array<int, 2>& other = problem.points[j].body;
      for (int side = 0; side < 2; ++side) {
        int& cursor = side == 0 ? ia : ib;
        const std::vector<int>& list = side == 0 ? a : b;
        if (cursor >= static_cast<int>(list.size()) || list[cursor] != j) continue;
        ++cursor;
        const int rowSide = other[0] == bodies[side] ? 0 : 1;
        c.sides[c.shared++] = {rowSide, side};
      }
      couplings_.push_back(c);
    }
  }

  std::vector<Coupling> couplings_;
  std::vector<int> first_;  ///< where each point's neighbours start in couplings_
};

/// The linear system of one guess of the states, in the impulses the states leave unknown. The
/// bodies' velocities are eliminated (u = u₀ + M⁻¹Jᵀλ), so the rows are the points' velocity
/// conditions in their impulses: W λ + r λ = −(J u₀ − target), one row for each normal of a
/// touching point and each tangent of a sticking one. A separated point has no unknown (λ = 0); a
/// sliding point only λn, its friction λt = ∓μλn folded into λn's column. The matrix is W
/// restricted to those rows (symmetric but for the sliding columns) and is assembled only to be
/// factorized, column by column in Eigen's compressed form; products A x are taken through the
/// bodies. r, the regularization, is kept in `shift` so the solve can take it out again.
class GuessSystem final : public PosedSystem {
 public:
  GuessSystem(const IslandProblem& problem, const std::vector<ContactState>& states,
              const Eigen::VectorXd& diagonal, const Eigen::VectorXd& free, double regularization,
              std::optional<Neighbours>& neighbours)
      : problem_(problem), states_(states), neighbours_(neighbours) {
    firstRow_.assign(states.size(), -1);
    int rows = 0;
    for (int i = 0; i < pointCount(); ++i) {
      if (rowsOf(i) == 0) continue;
      firstRow_[i] = rows;
      rows += rowsOf(i);
    }
    rhs_.resize(rows);
    shift_.resize(rows);
    for (int i = 0; i < pointCount(); ++i) {
      for (int axis = 0; axis < rowsOf(i); ++axis) {
        rhs_(row(i, axis)) = -free(2 * i + axis);
        shift_(row(i, axis)) = regularization * diagonal(2 * i + axis);
      }
    }
    rowSum_ = boundRowSum();
  }

  Eigen::Index size() const override { return rhs_.size(); }
  const Eigen::VectorXd& shift() const override { return shift_; }
  double rowSum() const override { return rowSum_; }
  const Eigen::VectorXd& rhs() const { return rhs_; }

  Eigen::VectorXd times(const Eigen::VectorXd& x) const override {
    const Eigen::VectorXd velocity = delassusTimes(problem_, impulses(x));
    Eigen::VectorXd product(x.size());
    for (int i = 0; i < pointCount(); ++i) {
      for (int axis = 0; axis < rowsOf(i); ++axis) {
        const int k = row(i, axis);
        product(k) = velocity(2 * i + axis) + shift_(k) * x(k);
      }
    }
    return product;
  }

  Sparse matrix() const override {
    if (!neighbours_) neighbours_.emplace(problem_);
    Eigen::Index entries = 0;
    for (int i = 0; i < pointCount(); ++i) {
      Eigen::Index column = 0;
      for (const Neighbours::Coupling& c : neighbours_->of(i)) column += rowsOf(c.point);
      entries += rowsOf(i) * column;
    }
    CompressedColumns columns(static_cast<int>(size()), entries);
    for (int i = 0; i < pointCount(); ++i) {
      for (int axis = 0; axis < rowsOf(i); ++axis) addColumn(i, axis, columns);
    }
    return columns.take();
  }

  /// The unknowns x that hold these impulses (λn, and λt of a sticking point).
  Eigen::VectorXd unknownsOf(const Eigen::VectorXd& impulses) const {
    Eigen::VectorXd x(size());
    for (int i = 0; i < pointCount(); ++i) {
      for (int axis = 0; axis < rowsOf(i); ++axis) x(row(i, axis)) = impulses(2 * i + axis);
    }
    return x;
  }

  /// The impulses (λn, λt per point) of the system's answer x.
  Eigen::VectorXd impulses(const Eigen::VectorXd& x) const {
    Eigen::VectorXd all = Eigen::VectorXd::Zero(2 * pointCount());
    for (int i = 0; i < pointCount(); ++i) {
      const ContactState state = states_[i];
      if (state == ContactState::Separated) continue;
      all(2 * i) = x(row(i, 0));
      all(2 * i + 1) = state == ContactState::Sticking
                           ? x(row(i, 1))
                           : -slidingSign(state) * point(i).friction * x(row(i, 0));
    }
    return all;
  }

 private:
  const IslandPoint& point(int i) const { return problem_.points[i]; }
  int pointCount() const { return static_cast<int>(problem_.points.size()); }
  int row(int i, int axis) const { return firstRow_[i] + axis; }
  /// The unknowns (and rows) of point i: none if separated, λn if sliding, λn and λt if sticking.
  int rowsOf(int i) const {
    const ContactState state = states_[i];
    if (state == ContactState::Separated) return 0;
    return state == ContactState::Sticking ? 2 : 1;
  }
  /// +1 sliding +, −1 sliding −: the friction of a sliding point is λt = −sign·μλn.
  static double slidingSign(ContactState state) {
    return state == ContactState::SlidingPositive ? 1.0 : -1.0;
  }

  /// The bodies' velocity change per unit of the unknown (point i, axis): M⁻¹ times its impulse
  /// direction, Jᵀ along the axis, or Jnᵀ ∓ μJtᵀ for a sliding point's λn; one per side.
  std::array<Eigen::Vector3d, 2> unitChange(int i, int axis) const {
    const IslandPoint& p = point(i);
    const ContactState state = states_[i];
    std::array<Eigen::Vector3d, 2> change{};
    for (int side = 0; side < 2; ++side) {
      if (p.body[side] < 0) continue;
      Eigen::Vector3d direction = p.jacobian[axis][side];
      if (state != ContactState::Sticking) {
        direction -= slidingSign(state) * p.friction * p.jacobian[1][side];
      }
      change[side] = problem_.inverseMass.segment<3>(3 * p.body[side]).cwiseProduct(direction);
    }
    return change;
  }

  /// The column of unknown (point i, axis): the velocity every row's point gets from it, in
  /// the rows' order (neighbours are in increasing order, rows are numbered point by point).
  void addColumn(int i, int axis, CompressedColumns& column) const {
    const std::array<Eigen::Vector3d, 2> change = unitChange(i, axis);
    for (const Neighbours::Coupling& c : neighbours_->of(i)) {
      const IslandPoint& rowPoint = point(c.point);
      for (int r = 0; r < rowsOf(c.point); ++r) {
        double value = c.point == i && r == axis ? shift_(row(i, axis)) : 0.0;
        for (int k = 0; k < c.shared; ++k) {
          const auto [rowSide, side] = c.sides[k];
          value += rowPoint.jacobian[r][rowSide].dot(change[side]);
        }
        column.add(row(c.point, r), value);
      }
    }
    column.close();
  }

  /// A bound on |A|, the largest sum of a row's magnitudes, from the entries' bounds
  /// |J_row| M⁻¹ |direction|: each body's sum of its unknowns' |M⁻¹ direction|, taken by each
  /// row's |J|. It is the scale the solve's residuals are measured against.
  double boundRowSum() const {
    Eigen::VectorXd reach = Eigen::VectorXd::Zero(problem_.velocity.size());
    for (int i = 0; i < pointCount(); ++i) {
      for (int axis = 0; axis < rowsOf(i); ++axis) {
        const std::array<Eigen::Vector3d, 2> change = unitChange(i, axis);
        for (int side = 0; side < 2; ++side) {
          const int body = point(i).body[side];
          if (body >= 0) reach.segment<3>(3 * body) += change[side].cwiseAbs();
        }
      }
    }
    double bound = 0.0;
    for (int i = 0; i < pointCount(); ++i) {
      for (int axis = 0; axis < rowsOf(i); ++axis) {
        double sum = shift_(row(i, axis));
        for (int side = 0; side < 2; ++side) {
          const int body = point(i).body[side];
          if (body < 0) continue;
          sum += point(i).jacobian[axis][side].cwiseAbs().dot(reach.segment<3>(3 * body));
        }
        bound = std::max(bound, sum);
      }
    }
    return bound;
  }

  const IslandProblem& problem_;
  const std::vector<ContactState>& states_;
  std::optional<Neighbours>& neighbours_;
  std::vector<int> firstRow_;  ///< each point's first row, −1 if separated
  Eigen::VectorXd rhs_;
  Eigen::VectorXd shift_;
  double rowSum_ = 0.0;
};

/// What the answer breaks, point by point: a pull, a closing separated point, friction beyond
/// the cone while sticking, a slide against its friction. In N s (velocities times the point's
/// mass), so one tolerance serves all. A closing point takes up sticking, or with enterSliding
/// and a slip, sliding against its slip.
std::vector<Violation> violations(const IslandProblem& problem,
                                  const std::vector<ContactState>& states,
                                  const Eigen::VectorXd& impulses, const Eigen::VectorXd& velocity,
                                  const Eigen::VectorXd& diagonal, double tolerance,
                                  bool enterSliding) {
  std::vector<Violation> found;
  for (int i = 0; i < static_cast<int>(problem.points.size()); ++i) {
    const double mu = problem.points[i].friction;
    const double normal = impulses(2 * i);
    const double tangent = impulses(2 * i + 1);
    const double slip = velocity(2 * i + 1) / diagonal(2 * i + 1);
    const ContactState state = states[i];
    const ContactState touching = mu > 0.0 ? ContactState::Sticking : ContactState::SlidingPositive;
    if (state == ContactState::Separated) {
      const double closing = -velocity(2 * i) / diagonal(2 * i);
      ContactState next = touching;
      if (enterSliding && mu > 0.0 && std::abs(slip) > tolerance) {
        next = slip > 0.0 ? ContactState::SlidingPositive : ContactState::SlidingNegative;
      }
      if (closing > tolerance) found.push_back({i, next, closing});
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

/// Júdice–Pires: flip every violator while their number falls (or for a few tries after), else
/// only the worst, until the number falls below the best seen. With backtracking, a flip that
/// does not lower the number below the best goes back to the best states instead and flips
/// half as many of their violators, the worst first, then a quarter, … down to one; only then
/// one at a time from where it is.
class FlipRule {
 public:
  explicit FlipRule(const ActiveSetSettings& settings)
      : backtrack_(settings.cyclingSafeguard == CyclingSafeguard::Backtrack) {}

  void apply(const std::vector<Violation>& found, std::vector<ContactState>& states) {
    const int count = static_cast<int>(found.size());
    if (count < best_) {
      best_ = count;
      failures_ = 0;
      bestStates_ = states;
      bestFound_ = found;
      std::sort(bestFound_.begin(), bestFound_.end(),
                [](const Violation& x, const Violation& y) { return x.amount > y.amount; });
      flip(found, count, states);
      return;
    }
    ++failures_;
    if (backtrack_) {
      const bool halvings = failures_ < std::numeric_limits<int>::digits;
      const int share = halvings ? static_cast<int>(bestFound_.size()) >> failures_ : 0;
      if (share > 0) {
        states = bestStates_;
        flip(bestFound_, share, states);
        return;
      }
    } else if (failures_ <= kJudicePiresBlockFailures) {
      flip(found, count, states);
      return;
    }
    flipWorst(found, states);
  }

 private:
  static void flip(const std::vector<Violation>& found, int count,
                   std::vector<ContactState>& states) {
    for (int k = 0; k < count; ++k) states[found[k].point] = found[k].next;
  }

  /// One at a time, the worst first; with backtracking, not the point flipped just before (on a
  /// degenerate pile flipping it back returns to the states before: a cycle of two).
  void flipWorst(const std::vector<Violation>& found, std::vector<ContactState>& states) {
    const Violation* worst = nullptr;
    for (const Violation& v : found) {
      const bool tabu = backtrack_ && v.point == lastFlipped_ && found.size() > 1;
      if (!tabu && (worst == nullptr || v.amount > worst->amount)) worst = &v;
    }
    states[worst->point] = worst->next;
    lastFlipped_ = worst->point;
  }

  bool backtrack_;
  int lastFlipped_ = -1;
  int best_ = std::numeric_limits<int>::max();
  int failures_ = 0;
  std::vector<ContactState> bestStates_;
  std::vector<Violation> bestFound_;  ///< the best states' violators, the worst first
};

/// The first guess: each point's state and the impulses the regularization is centred on.
struct Guess {
  std::vector<ContactState> states;
  Eigen::VectorXd impulses;  ///< (λn, λt) per point; zero unless centreOnGuess
};

/// Each point's first state: with warmStates, a point solved last step takes the state it was
/// solved in (or, solved by Lemke or another method, the state of its impulses); the others
/// (all of them without warmStates) the state the Gauss–Seidel sweeps from the guess give, and
/// the sweeps run only if some point needs them. The impulses are those the state came from.
Guess firstGuess(const IslandProblem& problem, const Eigen::VectorXd& free,
                 const Eigen::VectorXd& diagonal, const ActiveSetSettings& settings) {
  const Eigen::VectorXd swept = needsGuessSweeps(problem, settings)
                                    ? gaussSeidelGuess(problem, free, diagonal, settings)
                                    : Eigen::VectorXd();
  Guess guess{std::vector<ContactState>(problem.points.size()),
              Eigen::VectorXd::Zero(problem.guess.size())};
  for (int i = 0; i < static_cast<int>(problem.points.size()); ++i) {
    const IslandPoint& point = problem.points[i];
    const Eigen::VectorXd& impulses = startsFromLastStep(point, settings) ? problem.guess : swept;
    if (settings.centreOnGuess) guess.impulses.segment<2>(2 * i) = impulses.segment<2>(2 * i);
    const bool carried =
        startsFromLastStep(point, settings) && point.lastState != ContactState::Unknown;
    guess.states[i] = carried
                          ? point.lastState
                          : stateOfImpulses(impulses(2 * i), impulses(2 * i + 1), point.friction);
  }
  return guess;
}

}  // namespace

ContactState stateOfImpulses(double normalImpulse, double tangentImpulse, double friction) {
  if (!(normalImpulse > 0.0)) return ContactState::Separated;
  const double limit = friction * normalImpulse * (1.0 - 1e-9);
  if (tangentImpulse <= -limit) return ContactState::SlidingPositive;
  if (tangentImpulse >= limit && friction > 0.0) return ContactState::SlidingNegative;
  return ContactState::Sticking;
}

namespace {

/// How often each set of states was solved: one solved more than kVisitsBeforeCycling times
/// means the flips cycle.
class VisitedStates {
 public:
  /// Counts a solve of `states`; whether the flips now cycle.
  bool cycles(const std::vector<ContactState>& states) {
    std::string key(states.size(), '\0');
    for (int i = 0; i < static_cast<int>(states.size()); ++i) key[i] = static_cast<char>(states[i]);
    return ++visits_[key] > kVisitsBeforeCycling;
  }

 private:
  std::unordered_map<std::string, int> visits_;  ///< by the states, one character per point
};

/// The impulses of one guess's system solved on `kept` (on its kept factors if `reuse`), the
/// regularization centred on `centre`; none if it is singular (a factorization failed, or the
/// answer is not finite).
std::optional<Eigen::VectorXd> solveGuessSystem(const GuessSystem& system,
                                                const Eigen::VectorXd& centre, bool reuse,
                                                const ActiveSetSettings& settings,
                                                KeptFactorization& kept) {
  Eigen::VectorXd unknowns = Eigen::VectorXd::Zero(system.size());
  const bool prepared = system.size() == 0 || kept.prepare(system, reuse, settings);
  if (prepared && system.size() > 0) unknowns = kept.solve(system.rhs(), system.unknownsOf(centre));
  if (!prepared || !unknowns.allFinite()) return std::nullopt;
  return system.impulses(unknowns);
}

/// What the answer breaks (violations), measured against kFlipTolerance of its impulse scale.
std::vector<Violation> violationsOfAnswer(const IslandProblem& problem,
                                          const std::vector<ContactState>& states,
                                          const Eigen::VectorXd& impulses,
                                          const Eigen::VectorXd& free,
                                          const Eigen::VectorXd& diagonal,
                                          const ActiveSetSettings& settings) {
  const Eigen::VectorXd velocity = free + delassusTimes(problem, impulses);
  const double tolerance = kFlipTolerance * impulseScale(impulses, free, diagonal);
  return violations(problem, states, impulses, velocity, diagonal, tolerance,
                    settings.enterSliding);
}

/// The answer so far, failed for `reason`.
ActiveSetAnswer failedAnswer(ActiveSetAnswer answer, const std::string& reason) {
  answer.failure = reason;
  return answer;
}

/// The answer so far, solved in `states`.
ActiveSetAnswer solved(ActiveSetAnswer answer, const std::vector<ContactState>& states) {
  answer.solved = true;
  answer.states = states;
  return answer;
}

/// From the first guess, each guess of the states solved and its violators flipped, until an
/// answer breaks nothing; failed if the flips cycle, a system is singular or the factorization
/// limit is reached.
ActiveSetAnswer flipUntilSolved(const IslandProblem& problem, const Eigen::VectorXd& free,
                                const Eigen::VectorXd& diagonal, const Guess& guess,
                                const ActiveSetSettings& settings, KeptFactorization& kept) {
  ActiveSetAnswer answer;
  std::vector<ContactState> states = guess.states;
  std::optional<Neighbours> neighbours;  // W's pattern, built at the first factorization
  FlipRule flips(settings);
  const int factorizationsBefore = kept.factorizations();
  VisitedStates visited;
  // Only the step's first system is solved on kept factors: after a flip, the flipped rows
  // differ from every earlier system (a block flip changes many), and the path of the flips
  // stays the one fresh factorizations take.
  bool firstSystem = true;
  while (answer.factorizations < settings.maxFactorizations) {
    if (visited.cycles(states)) {
      return failedAnswer(answer, "active set: cycling (the same states solved " +
                                      std::to_string(kVisitsBeforeCycling + 1) +
                                      " times by factorization " +
                                      std::to_string(answer.factorizations) + ")");
    }
    const GuessSystem system(problem, states, diagonal, free, settings.regularization, neighbours);
    const std::optional<Eigen::VectorXd> impulses = solveGuessSystem(
        system, guess.impulses, firstSystem && settings.keepFactors, settings, kept);
    firstSystem = false;
    answer.factorizations = kept.factorizations() - factorizationsBefore;
    if (!impulses) {
      return failedAnswer(answer, "active set: singular system at factorization " +
                                      std::to_string(answer.factorizations) + " (" +
                                      kept.lastError() + ")");
    }
    answer.impulses = *impulses;
    const std::vector<Violation> found =
        violationsOfAnswer(problem, states, answer.impulses, free, diagonal, settings);
    if (found.empty()) return solved(answer, states);
    flips.apply(found, states);
  }
  return failedAnswer(answer, "active set: factorization limit of " +
                                  std::to_string(settings.maxFactorizations) + " reached");
}

}  // namespace

ActiveSetAnswer solveActiveSet(const IslandProblem& problem, const ActiveSetSettings& settings,
                               KeptFactorization& kept) {
  const Eigen::VectorXd diagonal = delassusDiagonal(problem);
  const Eigen::VectorXd free = freeVelocity(problem);
  if (!free.allFinite() || !diagonal.allFinite()) {
    return failedAnswer({},
                        "active set: the problem is not finite (a velocity or mass overflowed)");
  }
  return flipUntilSolved(problem, free, diagonal, firstGuess(problem, free, diagonal, settings),
                         settings, kept);
}

}  // namespace impulse2d
