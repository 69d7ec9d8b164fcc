// The active-set method that solves the global reference's large islands (reference_solver.h).
//
// Every contact point is in one of four states. For a guess of the states the contact
// conditions are LINEAR, and one sparse system gives the impulses:
//   separated   λn = 0, λt = 0                   (and then vn ≥ target must come out)
//   sticking    vn = target, vt = 0              (and then λn ≥ 0, |λt| ≤ μλn)
//   sliding +   vn = target, λt = −μλn           (and then λn ≥ 0, vt ≥ 0)
//   sliding −   vn = target, λt = +μλn           (and then λn ≥ 0, vt ≤ 0)
// The bodies' velocities are eliminated (u = u₀ + M⁻¹Jᵀλ), so the system is in the impulses the
// states leave unknown (λn of a touching point, λt of a sticking one), one row per condition
// above: W restricted to those rows and columns, a sliding point's λt = ∓μλn folded into its λn
// column. It is symmetric but for those columns, and factorized by LU in a symmetric
// fill-reducing order (AMD) with its own diagonal as pivots: its cost follows the contact graph,
// not (points)³.
// Points whose answer breaks the "and then" of their state change state: all at once while that
// lowers the number of violated points (block pivoting, Júdice–Pires), then one at a time, the
// worst first, until it falls again. The first guess comes from last step's impulses (kept by
// feature id) refined by a few projected Gauss–Seidel sweeps, so a resting pile needs one or two
// factorizations; with the factors of last step's last system kept (KeptFactorization), a pile
// whose states did not change needs none. The caller checks the answer against the physical
// conditions.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "impulse2d/contact.h"
#include "impulse2d/settings.h"
#include "impulse2d/solvers/kept_factorization.h"

namespace impulse2d {

/// The state the global reference solved a contact point in: no impulse, held by static
/// friction, or sliding with friction on its limit, the tangent velocity positive or negative.
/// Unknown: the reference did not solve the point last step.
enum class ContactState { Unknown, Separated, Sticking, SlidingPositive, SlidingNegative };

/// One contact point of an island. Axis 0 is the normal, 1 the tangent; side 0 is body A, 1 B.
struct IslandPoint {
  /// The island's number of each body (−1: a static body, which takes no impulse).
  std::array<int, 2> body{{-1, -1}};
  /// jacobian[axis][side]: how the relative velocity along the axis depends on that body's
  /// velocity (x, y, ω): −(d, r×d) for A, +(d, r×d) for B.
  std::array<std::array<Eigen::Vector3d, 2>, 2> jacobian{};
  /// The part of the relative velocities that comes from static bodies (normal, tangent).
  std::array<double, 2> staticVelocity{{0.0, 0.0}};
  /// m/s, what the normal velocity must reach
  double targetNormalVelocity = 0.0;
  /// mixed coefficient of friction
  double friction = 0.0;
  /// The guess at this point is last step's answer there (kept by feature id), not a zero.
  bool carried = false;
  /// The state last step's answer left the point in (ContactPoint::exactState), if known.
  ContactState lastState = ContactState::Unknown;
};

// The Jacobian arithmetic of one contact point, shared by the active set (IslandPoint) and the
// reference's own rows: any point type with `body` (−1 for a static body) and
// `jacobian[axis][side]`, on vectors of 3 per body (vx, vy, ω).

/// J u along `axis`: the relative velocity that body velocities (or changes) u give the point,
/// added to `start` (the part of it from static bodies, if any).
template <typename Point>
double jacobianTimes(const Point& point, int axis, const Eigen::VectorXd& u, double start = 0.0) {
  double v = start;
  for (int side = 0; side < 2; ++side) {
    const int body = point.body[side];
    if (body >= 0) v += point.jacobian[axis][side].dot(u.segment<3>(3 * body));
  }
  return v;
}

/// change += M⁻¹Jᵀ times an impulse along `axis`: the bodies' velocity change from it.
template <typename Point>
void addBodyVelocityChange(const Point& point, int axis, double impulse,
                           const Eigen::VectorXd& inverseMass, Eigen::VectorXd& change) {
  for (int side = 0; side < 2; ++side) {
    const int body = point.body[side];
    if (body < 0) continue;
    change.segment<3>(3 * body) +=
        impulse * inverseMass.segment<3>(3 * body).cwiseProduct(point.jacobian[axis][side]);
  }
}

/// J M⁻¹ Jᵀ along `axis`: the point's inverse effective mass there (W's diagonal entry).
template <typename Point>
double inverseEffectiveMass(const Point& point, int axis, const Eigen::VectorXd& inverseMass) {
  double w = 0.0;
  for (int side = 0; side < 2; ++side) {
    const int body = point.body[side];
    if (body < 0) continue;
    const Eigen::Vector3d& row = point.jacobian[axis][side];
    w += row.cwiseProduct(row).dot(inverseMass.segment<3>(3 * body));
  }
  return w;
}

/// One island's problem: its points and its bodies. The solve takes W λ (W = J M⁻¹ Jᵀ, the
/// Delassus matrix) through the bodies, J (M⁻¹ (Jᵀ λ)) (delassusTimes), at the cost of the
/// points' Jacobian rows rather than of W's entries (about 20 coupled points a point in a pile of
/// boxes); W's rows of the touching points are assembled only to be factorized. W itself is
/// needed only by the projected Gauss–Seidel sweeps that guess the states of
/// new points (needsGuessSweeps): on a degenerate pile their rounding decides the path of the
/// first step's flips, and the same sweeps done through the bodies round differently and can
/// send a large pile's first step on a far longer path of factorizations
/// (docs/design/reference-active-set.md).
struct IslandProblem {
  /// the island's contact points
  std::vector<IslandPoint> points;
  Eigen::VectorXd inverseMass;           ///< 3 per body: 1/m, 1/m, 1/I
  Eigen::VectorXd velocity;              ///< 3 per body: (vx, vy, ω) before the solve
  Eigen::SparseMatrix<double> delassus;  ///< W, 2 per point; only if needsGuessSweeps
  Eigen::VectorXd guess;                 ///< 2 per point: the impulses to start from
};

/// Whether the solve will guess some point's state by Gauss–Seidel sweeps (a point not solved
/// last step, or warm states off), which need the problem's W.
bool needsGuessSweeps(const IslandProblem& problem, const ActiveSetSettings& settings);

/// W λ: the relative velocity change (normal, tangent) at every point from impulses λ (2 per
/// point).
Eigen::VectorXd delassusTimes(const IslandProblem& problem, const Eigen::VectorXd& impulses);
/// W's diagonal: each point's inverse effective mass along its normal and its tangent.
Eigen::VectorXd delassusDiagonal(const IslandProblem& problem);

/// The active set method's answer for one island.
struct ActiveSetAnswer {
  /// an answer within tolerance was found
  bool solved = false;
  /// factorizations it took
  int factorizations = 0;
  Eigen::VectorXd impulses;          ///< (λn, λt) per point
  std::vector<ContactState> states;  ///< each point's state in the answer
  /// why not, when not solved
  std::string failure;
};

/// Solves one island; `solved` false (with `failure` saying why) at the factorization limit or
/// on a singular system. `kept` carries the factors from one call to the next (the caller keeps
/// one per island); it may be fresh.
ActiveSetAnswer solveActiveSet(const IslandProblem& problem, const ActiveSetSettings& settings,
                               KeptFactorization& kept);

/// The state a point's impulses put it in: no push, friction on either limit, or inside it.
ContactState stateOfImpulses(double normalImpulse, double tangentImpulse, double friction);

}  // namespace impulse2d
