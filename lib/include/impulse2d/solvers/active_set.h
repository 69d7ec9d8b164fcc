// The active-set method that solves the global reference's large islands (reference_solver.h).
//
// Every contact point is in one of four states. For a guess of the states the contact
// conditions are LINEAR, and one sparse system gives the impulses:
//   separated   λn = 0, λt = 0                   (and then vn ≥ target must come out)
//   sticking    vn = target, vt = 0              (and then λn ≥ 0, |λt| ≤ μλn)
//   sliding +   vn = target, λt = −μλn           (and then λn ≥ 0, vt ≥ 0)
//   sliding −   vn = target, λt = +μλn           (and then λn ≥ 0, vt ≤ 0)
// The system is the KKT form in the bodies' velocities u and the impulses λ:
//   u − M⁻¹Jᵀλ = u₀ for every body, and one row per point condition above (Ju is the relative
//   velocity of a point), factorized by Eigen's SparseLU: its cost follows the contact graph,
//   not (points)³.
// Points whose answer breaks the "and then" of their state change state: all at once while that
// lowers the number of violated points (block pivoting, Júdice–Pires), then one at a time, the
// worst first, until it falls again. The first guess comes from last step's impulses (kept by
// feature id) refined by a few projected Gauss–Seidel sweeps, so a resting pile needs one or two
// factorizations. The caller checks the answer against the physical conditions.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "impulse2d/settings.h"

namespace impulse2d {

/// One contact point of an island. Axis 0 is the normal, 1 the tangent; side 0 is body A, 1 B.
struct IslandPoint {
  /// The island's number of each body (−1: a static body, which takes no impulse).
  std::array<int, 2> body{{-1, -1}};
  /// jacobian[axis][side]: how the relative velocity along the axis depends on that body's
  /// velocity (x, y, ω): −(d, r×d) for A, +(d, r×d) for B.
  std::array<std::array<Eigen::Vector3d, 2>, 2> jacobian{};
  /// The part of the relative velocities that comes from static bodies (normal, tangent).
  std::array<double, 2> staticVelocity{{0.0, 0.0}};
  double targetNormalVelocity = 0.0;
  double friction = 0.0;
  /// The guess at this point is last step's answer there (kept by feature id), not a zero.
  bool carried = false;
};

/// One island's problem: its points, its bodies and the Delassus matrix of its points.
struct IslandProblem {
  std::vector<IslandPoint> points;
  Eigen::VectorXd inverseMass;           ///< 3 per body: 1/m, 1/m, 1/I
  Eigen::VectorXd velocity;              ///< 3 per body: (vx, vy, ω) before the solve
  Eigen::SparseMatrix<double> delassus;  ///< 2 per point, rows (normal, tangent)
  Eigen::VectorXd guess;                 ///< 2 per point: the impulses to start from
};

enum class ContactState { Separated, Sticking, SlidingPositive, SlidingNegative };

struct ActiveSetAnswer {
  bool solved = false;
  int factorizations = 0;
  Eigen::VectorXd impulses;  ///< (λn, λt) per point
  std::string failure;
};

/// Solves one island; `solved` false (with `failure` saying why) at the factorization limit or
/// on a singular system.
ActiveSetAnswer solveActiveSet(const IslandProblem& problem, const ActiveSetSettings& settings);

/// The state a point's impulses put it in: no push, friction on either limit, or inside it.
ContactState stateOfImpulses(double normalImpulse, double tangentImpulse, double friction);

}  // namespace impulse2d
