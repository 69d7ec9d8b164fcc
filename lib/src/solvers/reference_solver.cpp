// The global reference: Delassus matrix, the frictional LCP of all points, Lemke, a residual
// check of the answer, then the impulses.
#include "impulse2d/solvers/reference_solver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "impulse2d/solvers/contact_math.h"
#include "impulse2d/solvers/position_correction.h"

namespace impulse2d {
namespace {

/// The LCP variables of point i sit at 4i + these offsets.
enum LcpVariable {
  NormalImpulse = 0,
  PositiveFriction = 1,
  NegativeFriction = 2,
  SlidingSpeed = 3
};
constexpr int kVariablesPerPoint = 4;

const ContactPoint& pointOf(const StepContext& context, int manifold, int point) {
  return context.manifolds[static_cast<size_t>(manifold)].points[static_cast<size_t>(point)];
}

/// The worst violated condition of one point, in N s (velocities turned into impulses by the
/// point's masses): a pull, friction outside the cone, an overlap velocity, a push while the
/// point separates, and — while it slides — friction short of the limit or pushing along.
double pointViolation(double normalImpulse, double tangentImpulse, double normalError,
                      double tangentVelocity, double friction, double normalMass,
                      double tangentMass) {
  const double separation = normalMass * normalError;
  const double sliding = tangentMass * std::abs(tangentVelocity);
  const double frictionSlack = friction * normalImpulse - std::abs(tangentImpulse);
  const double alongSliding =
      tangentImpulse * tangentVelocity > 0.0 ? std::abs(tangentImpulse) : 0.0;
  return std::max({0.0, -normalImpulse, -frictionSlack, -separation,
                   std::min(std::max(normalImpulse, 0.0), std::max(separation, 0.0)),
                   std::min(sliding, std::max(frictionSlack, 0.0)),
                   std::min(sliding, alongSliding)});
}

/// N s. A body's momentum as seen from a point: m|v|, or I|ω| over the point's lever arm.
double momentumAt(const Body& body, const Vec2& point) {
  const double lever = (point - body.position).norm();
  const double angular = lever > 0.0 ? body.inertia * std::abs(body.angularVelocity) / lever : 0.0;
  return std::max(body.mass * body.velocity.norm(), angular);
}

}  // namespace

void ReferenceSolver::solveVelocities(const StepContext& context) {
  const Eigen::VectorXd impulses = exactImpulses(context);
  if (rows_.empty()) return;  // nothing touches: no system to solve
  applyImpulses(context, impulses);
}

Eigen::VectorXd ReferenceSolver::exactImpulses(const StepContext& context) {
  report_ = SolveReport{};
  collectPoints(context);
  if (rows_.empty()) return {};
  groupIslands(context);
  buildDelassus(context);
  buildFreeVelocity(context);
  formulateLcp();
  const LcpSolution solution = solveLcp();
  report_.iterations = solution.pivots;
  if (!solution.solved) fail(solution.failure);
  const Eigen::VectorXd impulses = contactImpulses(solution.z);
  report_.residual = residual(impulses);
  if (!(report_.residual <= settings_.residualTolerance)) {
    std::ostringstream reason;
    reason << "relative residual " << report_.residual << " exceeds the tolerance "
           << settings_.residualTolerance << " after " << solution.pivots
           << " pivots (LCP natural residual "
           << naturalResidual(lcpMatrix_, lcpVector_, solution.z) << ")";
    fail(reason.str());
  }
  return impulses;
}

// The targets use the closing velocity before the solve, with the same rules (bounce threshold,
// penetration bias, speculative gaps) as sequential impulses.
void ReferenceSolver::collectPoints(const StepContext& context) {
  rows_.clear();
  for (size_t m = 0; m < context.manifolds.size(); ++m) {
    const Manifold& manifold = context.manifolds[m];
    const Body& a = context.bodies[static_cast<size_t>(manifold.bodyA)];
    const Body& b = context.bodies[static_cast<size_t>(manifold.bodyB)];
    for (int i = 0; i < manifold.pointCount; ++i) {
      const ContactPoint& point = manifold.points[static_cast<size_t>(i)];
      const double normalVelocity = relativeVelocity(a, b, point.point, manifold.normal);
      rows_.push_back(
          PointRow{static_cast<int>(m), i, manifold.friction,
                   targetSeparatingVelocity(normalVelocity, point.penetration, manifold.restitution,
                                            context.dt, settings_.targets),
                   std::max(momentumAt(a, point.point), momentumAt(b, point.point))});
    }
  }
}

void ReferenceSolver::buildDelassus(const StepContext& context) {
  const int count = static_cast<int>(rows_.size());
  delassus_.setZero(2 * count, 2 * count);
  for (int i = 0; i < count; ++i) {
    const PointRow& rowI = rows_[static_cast<size_t>(i)];
    const Manifold& mi = context.manifolds[static_cast<size_t>(rowI.manifold)];
    for (int j = i; j < count; ++j) {
      const PointRow& rowJ = rows_[static_cast<size_t>(j)];
      const Manifold& mj = context.manifolds[static_cast<size_t>(rowJ.manifold)];
      const Mat2 block =
          couplingBlock(context.bodies, mi, pointOf(context, rowI.manifold, rowI.point).point, mj,
                        pointOf(context, rowJ.manifold, rowJ.point).point);
      delassus_.block<2, 2>(2 * i, 2 * j) = block;
      delassus_.block<2, 2>(2 * j, 2 * i) = block.transpose();
    }
  }
}

void ReferenceSolver::buildFreeVelocity(const StepContext& context) {
  freeVelocity_.resize(2 * static_cast<int>(rows_.size()));
  for (size_t i = 0; i < rows_.size(); ++i) {
    const Manifold& manifold = context.manifolds[static_cast<size_t>(rows_[i].manifold)];
    const Body& a = context.bodies[static_cast<size_t>(manifold.bodyA)];
    const Body& b = context.bodies[static_cast<size_t>(manifold.bodyB)];
    const Vec2& point = pointOf(context, rows_[i].manifold, rows_[i].point).point;
    freeVelocity_(2 * static_cast<int>(i)) = relativeVelocity(a, b, point, manifold.normal);
    freeVelocity_(2 * static_cast<int>(i) + 1) = relativeVelocity(a, b, point, manifold.tangent());
  }
}

// Rows per point i (λt = λt⁺ − λt⁻):
//   normal:   vn − target       = W_nn λn + W_nt λt + (vn₀ − target) ≥ 0  ⟂ λn
//   λt⁺:      vt + β            = W_tn λn + W_tt λt + β + vt₀        ≥ 0  ⟂ λt⁺
//   λt⁻:     −vt + β                                                 ≥ 0  ⟂ λt⁻
//   β:        μλn − λt⁺ − λt⁻                                        ≥ 0  ⟂ β
void ReferenceSolver::formulateLcp() {
  const int count = static_cast<int>(rows_.size());
  const int size = kVariablesPerPoint * count;
  lcpMatrix_.setZero(size, size);
  lcpVector_.setZero(size);
  for (int i = 0; i < count; ++i) {
    const int ri = kVariablesPerPoint * i;
    for (int j = 0; j < count; ++j) {
      const int cj = kVariablesPerPoint * j;
      const Mat2 w = delassus_.block<2, 2>(2 * i, 2 * j);
      for (int r = 0; r < 2; ++r) {
        lcpMatrix_(ri + r, cj + NormalImpulse) = w(r, 0);
        lcpMatrix_(ri + r, cj + PositiveFriction) = w(r, 1);
        lcpMatrix_(ri + r, cj + NegativeFriction) = -w(r, 1);
      }
      lcpMatrix_.block<1, 3>(ri + NegativeFriction, cj) = -lcpMatrix_.block<1, 3>(ri + 1, cj);
    }
    lcpMatrix_(ri + PositiveFriction, ri + SlidingSpeed) = 1.0;
    lcpMatrix_(ri + NegativeFriction, ri + SlidingSpeed) = 1.0;
    lcpMatrix_(ri + SlidingSpeed, ri + NormalImpulse) = rows_[static_cast<size_t>(i)].friction;
    lcpMatrix_(ri + SlidingSpeed, ri + PositiveFriction) = -1.0;
    lcpMatrix_(ri + SlidingSpeed, ri + NegativeFriction) = -1.0;
    lcpVector_(ri + NormalImpulse) =
        freeVelocity_(2 * i) - rows_[static_cast<size_t>(i)].targetNormalVelocity;
    lcpVector_(ri + PositiveFriction) = freeVelocity_(2 * i + 1);
    lcpVector_(ri + NegativeFriction) = -freeVelocity_(2 * i + 1);
  }
}

// Union-find over the dynamic bodies: two points share an island when a chain of contacts
// through dynamic bodies joins them. A static body joins nothing (it takes no impulse, so the
// points on it do not couple), which is what cuts a pile on the ground into islands.
void ReferenceSolver::groupIslands(const StepContext& context) {
  std::vector<int> parent(context.bodies.size());
  for (size_t b = 0; b < parent.size(); ++b) parent[b] = static_cast<int>(b);
  const auto root = [&parent](int body) {
    while (parent[static_cast<size_t>(body)] != body) {
      body = parent[static_cast<size_t>(body)] =
          parent[static_cast<size_t>(parent[static_cast<size_t>(body)])];
    }
    return body;
  };
  for (const PointRow& row : rows_) {
    const Manifold& manifold = context.manifolds[static_cast<size_t>(row.manifold)];
    if (context.bodies[static_cast<size_t>(manifold.bodyA)].isStatic() ||
        context.bodies[static_cast<size_t>(manifold.bodyB)].isStatic()) {
      continue;
    }
    parent[static_cast<size_t>(root(manifold.bodyA))] = root(manifold.bodyB);
  }
  std::vector<int> islandOfRoot(parent.size(), -1);
  islands_.clear();
  for (int i = 0; i < static_cast<int>(rows_.size()); ++i) {
    const Manifold& manifold =
        context.manifolds[static_cast<size_t>(rows_[static_cast<size_t>(i)].manifold)];
    const bool aStatic = context.bodies[static_cast<size_t>(manifold.bodyA)].isStatic();
    const int body = root(aStatic ? manifold.bodyB : manifold.bodyA);
    int& island = islandOfRoot[static_cast<size_t>(body)];
    if (island < 0) {
      island = static_cast<int>(islands_.size());
      islands_.emplace_back();
    }
    for (int v = 0; v < kVariablesPerPoint; ++v) {
      islands_[static_cast<size_t>(island)].push_back(kVariablesPerPoint * i + v);
    }
  }
}

// One LCP per island (the islands do not couple: the matrix is block diagonal in them).
LcpSolution ReferenceSolver::solveLcp() const {
  LcpSolution all;
  all.z = Eigen::VectorXd::Zero(lcpVector_.size());
  for (const std::vector<int>& island : islands_) {
    const LcpSolution part = solveIsland(lcpMatrix_(island, island), lcpVector_(island));
    all.pivots += part.pivots;
    if (!part.solved) {
      all.failure = part.failure;
      return all;
    }
    all.z(island) = part.z;
  }
  all.w = lcpMatrix_ * all.z + lcpVector_;
  all.solved = true;
  return all;
}

// Lemke on the problem as stated; on a ray (degeneracy defeating the floating-point
// lexicographic rule) once more on a slightly perturbed q.
LcpSolution ReferenceSolver::solveIsland(const Eigen::MatrixXd& matrix,
                                         const Eigen::VectorXd& vector) const {
  const LemkeSettings& options = settings_.lemke;
  const LcpSolution solution = solveLemke(matrix, vector, options);
  if (solution.solved || vector.size() == 0) return solution;
  const int size = static_cast<int>(vector.size());
  const Eigen::VectorXd growing = Eigen::VectorXd::LinSpaced(size, 1.0, 2.0);
  const double scale = settings_.degeneracyPerturbation * vector.cwiseAbs().maxCoeff();
  LcpSolution retry = solveLemke(matrix, vector + scale * growing, options);
  retry.pivots += solution.pivots;
  if (!retry.solved) retry.failure = solution.failure + "; perturbed retry: " + retry.failure;
  return retry;
}

/// (λn, λt) of every point, interleaved like the Delassus rows.
Eigen::VectorXd ReferenceSolver::contactImpulses(const Eigen::VectorXd& lcpSolution) const {
  const int count = static_cast<int>(rows_.size());
  Eigen::VectorXd impulses(2 * count);
  for (int i = 0; i < count; ++i) {
    const int ri = kVariablesPerPoint * i;
    impulses(2 * i) = lcpSolution(ri + NormalImpulse);
    impulses(2 * i + 1) = lcpSolution(ri + PositiveFriction) - lcpSolution(ri + NegativeFriction);
  }
  return impulses;
}

// The answer is checked against the physical conditions themselves, not the LCP's bookkeeping,
// so an error in the formulation would show here too.
double ReferenceSolver::residual(const Eigen::VectorXd& impulses) const {
  if (impulses.size() == 0) return 0.0;
  const Eigen::VectorXd velocity = freeVelocity_ + delassus_ * impulses;
  double worst = 0.0;
  for (int i = 0; i < static_cast<int>(rows_.size()); ++i) {
    const PointRow& row = rows_[static_cast<size_t>(i)];
    worst = std::max(worst,
                     pointViolation(impulses(2 * i), impulses(2 * i + 1),
                                    velocity(2 * i) - row.targetNormalVelocity, velocity(2 * i + 1),
                                    row.friction, 1.0 / delassus_(2 * i, 2 * i),
                                    1.0 / delassus_(2 * i + 1, 2 * i + 1)));
  }
  const double scale = impulseScale(impulses);
  return scale > 0.0 ? worst / scale : worst;
}

// N s. The size of the step's impulses, so that the residual is relative to something that
// cannot vanish when the answer does (a corner touching down, an elastic row that has already
// separated, where every impulse is 0 and rounding is all that is left): the largest impulse, each
// point's cancelling impulses (what stops its normal and tangent motion alone, velocity over
// effective mass) and the momenta of the bodies in contact (m|v|, and I|ω| over the point's lever
// arm).
double ReferenceSolver::impulseScale(const Eigen::VectorXd& impulses) const {
  double scale = impulses.cwiseAbs().maxCoeff();
  for (int i = 0; i < static_cast<int>(rows_.size()); ++i) {
    scale = std::max({scale, std::abs(lcpVector_(kVariablesPerPoint * i)) / delassus_(2 * i, 2 * i),
                      std::abs(freeVelocity_(2 * i + 1)) / delassus_(2 * i + 1, 2 * i + 1),
                      rows_[static_cast<size_t>(i)].momentum});
  }
  return scale;
}

void ReferenceSolver::applyImpulses(const StepContext& context,
                                    const Eigen::VectorXd& impulses) const {
  const double onLimit = settings_.residualTolerance * impulses.cwiseAbs().maxCoeff();
  for (int i = 0; i < static_cast<int>(rows_.size()); ++i) {
    const PointRow& row = rows_[static_cast<size_t>(i)];
    Manifold& manifold = context.manifolds[static_cast<size_t>(row.manifold)];
    ContactPoint& point = manifold.points[static_cast<size_t>(row.point)];
    point.normalImpulse = impulses(2 * i);
    point.tangentImpulse = impulses(2 * i + 1);
    point.friction =
        frictionStateOf(point.normalImpulse, point.tangentImpulse, row.friction, onLimit);
    applyContactImpulse(context.bodies, manifold, row.point, point.normalImpulse,
                        point.tangentImpulse);
    context.report({SolverEvent::Phase::Velocity, 0, row.manifold, row.point,
                    row.targetNormalVelocity - freeVelocity_(2 * i), point.normalImpulse,
                    point.tangentImpulse});
  }
}

void ReferenceSolver::fail(const std::string& reason) {
  report_.converged = false;
  throw std::runtime_error("reference solver: " + reason);
}

void ReferenceSolver::solvePositions(const StepContext& context) {
  correctPositions(context, settings_.positionPass, settings_.targets.allowedPenetration,
                   settings_.positionBlock);
}

}  // namespace impulse2d
