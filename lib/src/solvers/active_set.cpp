// The active-set method: guess the states, solve the KKT system, flip what it violates.
#include "impulse2d/solvers/active_set.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

namespace impulse2d {
namespace {

using Sparse = Eigen::SparseMatrix<double>;
using Triplets = std::vector<Eigen::Triplet<double>>;

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

/// v += column k of the Delassus matrix times delta (it is symmetric: the column is the row).
void addColumn(const Sparse& delassus, int k, double delta, Eigen::VectorXd& velocity) {
  for (Sparse::InnerIterator it(delassus, k); it; ++it) velocity(it.row()) += it.value() * delta;
}

/// Projected Gauss–Seidel sweeps from the guess: normal impulse ≥ 0, friction in the cone.
Eigen::VectorXd gaussSeidelGuess(const IslandProblem& problem, const Eigen::VectorXd& free,
                                 const Eigen::VectorXd& diagonal, int sweeps) {
  const int count = static_cast<int>(problem.points.size());
  Eigen::VectorXd impulses = problem.guess;
  for (int i = 0; i < count; ++i) {
    const double limit =
        problem.points[static_cast<size_t>(i)].friction * std::max(impulses(2 * i), 0.0);
    impulses(2 * i) = std::max(impulses(2 * i), 0.0);
    impulses(2 * i + 1) = std::clamp(impulses(2 * i + 1), -limit, limit);
  }
  Eigen::VectorXd velocity = free + problem.delassus * impulses;
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    for (int i = 0; i < count; ++i) {
      for (int axis = 0; axis < 2; ++axis) {
        const int k = 2 * i + axis;
        double next = impulses(k) - velocity(k) / diagonal(k);
        const double limit = problem.points[static_cast<size_t>(i)].friction * impulses(2 * i);
        next = axis == 0 ? std::max(next, 0.0) : std::clamp(next, -limit, limit);
        addColumn(problem.delassus, k, next - impulses(k), velocity);
        impulses(k) = next;
      }
    }
  }
  return impulses;
}

/// The triplets of u − M⁻¹Jᵀλ = u₀: fixed for the island, whatever the states.
void addBodyRows(const IslandProblem& problem, Triplets& triplets) {
  const int bodyUnknowns = static_cast<int>(problem.velocity.size());
  for (int r = 0; r < bodyUnknowns; ++r) triplets.emplace_back(r, r, 1.0);
  for (int i = 0; i < static_cast<int>(problem.points.size()); ++i) {
    const IslandPoint& point = problem.points[static_cast<size_t>(i)];
    for (int axis = 0; axis < 2; ++axis) {
      for (int side = 0; side < 2; ++side) {
        const int body = point.body[static_cast<size_t>(side)];
        if (body < 0) continue;
        const Eigen::Vector3d& row =
            point.jacobian[static_cast<size_t>(axis)][static_cast<size_t>(side)];
        for (int c = 0; c < 3; ++c) {
          triplets.emplace_back(3 * body + c, bodyUnknowns + 2 * i + axis,
                                -problem.inverseMass(3 * body + c) * row(c));
        }
      }
    }
  }
}

/// The row of a point's velocity along an axis: J u + r λ (r, the regularization, is kept in
/// `shift` so solveProximal can take it out again).
void addVelocityRow(const IslandProblem& problem, int i, int axis, double regularization,
                    Triplets& triplets, Eigen::VectorXd& shift) {
  const IslandPoint& point = problem.points[static_cast<size_t>(i)];
  const int bodyUnknowns = static_cast<int>(problem.velocity.size());
  const int row = bodyUnknowns + 2 * i + axis;
  for (int side = 0; side < 2; ++side) {
    const int body = point.body[static_cast<size_t>(side)];
    if (body < 0) continue;
    const Eigen::Vector3d& coefficients =
        point.jacobian[static_cast<size_t>(axis)][static_cast<size_t>(side)];
    for (int c = 0; c < 3; ++c) triplets.emplace_back(row, 3 * body + c, coefficients(c));
  }
  triplets.emplace_back(row, row, regularization);
  shift(2 * i + axis) = regularization;
}

/// The point rows for the given states, their right-hand side and regularization.
void addPointRows(const IslandProblem& problem, const std::vector<ContactState>& states,
                  const Eigen::VectorXd& diagonal, double regularization, Triplets& triplets,
                  Eigen::VectorXd& rhs, Eigen::VectorXd& shift) {
  const int bodyUnknowns = static_cast<int>(problem.velocity.size());
  for (int i = 0; i < static_cast<int>(problem.points.size()); ++i) {
    const IslandPoint& point = problem.points[static_cast<size_t>(i)];
    const int normal = bodyUnknowns + 2 * i;
    const int tangent = normal + 1;
    const ContactState state = states[static_cast<size_t>(i)];
    if (state == ContactState::Separated) {
      triplets.emplace_back(normal, normal, 1.0);
      triplets.emplace_back(tangent, tangent, 1.0);
      continue;
    }
    addVelocityRow(problem, i, 0, regularization * diagonal(2 * i), triplets, shift);
    rhs(normal) = point.targetNormalVelocity - point.staticVelocity[0];
    if (state == ContactState::Sticking) {
      addVelocityRow(problem, i, 1, regularization * diagonal(2 * i + 1), triplets, shift);
      rhs(tangent) = -point.staticVelocity[1];
    } else {
      const double sign = state == ContactState::SlidingPositive ? 1.0 : -1.0;
      triplets.emplace_back(tangent, tangent, 1.0);
      triplets.emplace_back(tangent, normal, sign * point.friction);
    }
  }
}

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

/// Solves the factorized system, then takes the regularization out again: each further solve
/// centres it on the last impulses (J u + r(λ − λ_last) = target: a proximal point step, the
/// velocity change W + r stays positive definite), reusing the factorization, so
/// the velocity rows end exact while redundant contacts keep the split the first solve chose.
Eigen::VectorXd solveProximal(const Eigen::SparseLU<Sparse, Eigen::COLAMDOrdering<int>>& lu,
                              const Eigen::VectorXd& rhs, const Eigen::VectorXd& shift,
                              int refinements) {
  const int bodyUnknowns = static_cast<int>(rhs.size() - shift.size());
  Eigen::VectorXd x = lu.solve(rhs);
  for (int k = 0; k < refinements; ++k) {
    Eigen::VectorXd centred = rhs;
    centred.tail(shift.size()) += shift.cwiseProduct(x.tail(shift.size()));
    x = lu.solve(centred);
  }
  return x.tail(x.size() - bodyUnknowns);
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
/// only the worst, until the number falls below the best seen.
class FlipRule {
 public:
  explicit FlipRule(int blockFailures) : blockFailures_(blockFailures) {}

  void apply(const std::vector<Violation>& found, std::vector<ContactState>& states) {
    const int count = static_cast<int>(found.size());
    if (count < best_) {
      best_ = count;
      failures_ = 0;
    } else {
      ++failures_;
    }
    if (failures_ <= blockFailures_) {
      for (const Violation& v : found) states[static_cast<size_t>(v.point)] = v.next;
      return;
    }
    const auto worst = std::max_element(
        found.begin(), found.end(),
        [](const Violation& x, const Violation& y) { return x.amount < y.amount; });
    states[static_cast<size_t>(worst->point)] = worst->next;
  }

 private:
  int blockFailures_;
  int best_ = std::numeric_limits<int>::max();
  int failures_ = 0;
};

/// Each point's first state: with warmStates, a point solved last step takes the state of its
/// exact impulses; the others (all of them without warmStates) the state the Gauss–Seidel
/// sweeps from the guess give, and the sweeps run only if some point needs them.
std::vector<ContactState> guessStates(const IslandProblem& problem, const Eigen::VectorXd& free,
                                      const Eigen::VectorXd& diagonal,
                                      const ActiveSetSettings& settings) {
  const auto fromWarm = [&](const IslandPoint& point) {
    return settings.warmStates && point.carried;
  };
  const bool allWarm = std::all_of(problem.points.begin(), problem.points.end(), fromWarm);
  const Eigen::VectorXd swept =
      allWarm ? Eigen::VectorXd() : gaussSeidelGuess(problem, free, diagonal, settings.guessSweeps);
  std::vector<ContactState> states(problem.points.size());
  for (int i = 0; i < static_cast<int>(problem.points.size()); ++i) {
    const IslandPoint& point = problem.points[static_cast<size_t>(i)];
    const Eigen::VectorXd& impulses = fromWarm(point) ? problem.guess : swept;
    states[static_cast<size_t>(i)] =
        stateOfImpulses(impulses(2 * i), impulses(2 * i + 1), point.friction);
  }
  return states;
}

}  // namespace

ContactState stateOfImpulses(double normalImpulse, double tangentImpulse, double friction) {
  if (!(normalImpulse > 0.0)) return ContactState::Separated;
  const double limit = friction * normalImpulse * (1.0 - 1e-9);
  if (tangentImpulse <= -limit) return ContactState::SlidingPositive;
  if (tangentImpulse >= limit && friction > 0.0) return ContactState::SlidingNegative;
  return ContactState::Sticking;
}

ActiveSetAnswer solveActiveSet(const IslandProblem& problem, const ActiveSetSettings& settings) {
  const int count = static_cast<int>(problem.points.size());
  const int bodyUnknowns = static_cast<int>(problem.velocity.size());
  const Eigen::VectorXd diagonal = problem.delassus.diagonal();
  const Eigen::VectorXd free = freeVelocity(problem);
  std::vector<ContactState> states = guessStates(problem, free, diagonal, settings);
  Triplets bodyRows;
  addBodyRows(problem, bodyRows);
  const int size = bodyUnknowns + 2 * count;
  FlipRule flips(settings.blockFailures);
  ActiveSetAnswer answer;
  Eigen::SparseLU<Sparse, Eigen::COLAMDOrdering<int>> lu;
  std::unordered_map<std::string, int> visits;  // how often each set of states was solved
  while (answer.factorizations < settings.maxFactorizations) {
    std::string key(states.size(), '\0');
    for (size_t i = 0; i < states.size(); ++i) key[i] = static_cast<char>(states[i]);
    if (++visits[key] > kVisitsBeforeCycling) {
      answer.failure = "active set: cycling (the same states solved " +
                       std::to_string(kVisitsBeforeCycling + 1) + " times by factorization " +
                       std::to_string(answer.factorizations) + ")";
      return answer;
    }
    Triplets triplets = bodyRows;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
    rhs.head(bodyUnknowns) = problem.velocity;
    Eigen::VectorXd shift = Eigen::VectorXd::Zero(2 * count);
    addPointRows(problem, states, diagonal, settings.regularization, triplets, rhs, shift);
    Sparse system(size, size);
    system.setFromTriplets(triplets.begin(), triplets.end());
    lu.compute(system);
    ++answer.factorizations;
    if (lu.info() != Eigen::Success) {
      answer.failure = "active set: singular system at factorization " +
                       std::to_string(answer.factorizations) + " (" + lu.lastErrorMessage() + ")";
      return answer;
    }
    answer.impulses = solveProximal(lu, rhs, shift, settings.refinements);
    zeroSeparated(states, answer.impulses);
    const Eigen::VectorXd velocity = free + problem.delassus * answer.impulses;
    const double tolerance = settings.flipTolerance * impulseScale(answer.impulses, free, diagonal);
    const std::vector<Violation> found =
        violations(problem, states, answer.impulses, velocity, diagonal, tolerance);
    if (found.empty()) {
      answer.solved = true;
      return answer;
    }
    flips.apply(found, states);
  }
  answer.failure = "active set: factorization limit of " +
                   std::to_string(settings.maxFactorizations) + " reached";
  return answer;
}

}  // namespace impulse2d
