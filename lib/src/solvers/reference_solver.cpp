// The global reference: the sparse Delassus matrix, islands, each solved by Lemke (small) or the
// active set (large), a residual check of the answer, then the impulses.
#include "impulse2d/solvers/reference_solver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "impulse2d/solvers/contact_math.h"
#include "impulse2d/solvers/position_correction.h"
#include "impulse2d/union_find.h"

#include "compressed_columns.h"

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

// Lemke's retries on a degenerate island: the textbook remedies, each answer checked against the
// unperturbed problem, so none can pass unnoticed; they are not for tuning.

/// A resting pile is massively degenerate (many zero velocities); in floating point the
/// lexicographic rule can then still end on a ray. Lemke is retried once with q moved by this
/// much, relative to its largest entry and growing along the rows: round-off's size, far below
/// the residual the answer is checked to.
constexpr double kDegeneracyPerturbation = 1e-10;
/// Then Lemke is tried with Harris's ratio test, and then along this many other covering vectors
/// (entries drawn in [0.5, 2) from a fixed seed), each with both ratio tests: every path ends at a
/// solution in exact arithmetic, but on a landing pile round-off and tiny pivots end some of them
/// on a ray or an answer the residual check rejects.
constexpr int kCoveringRetries = 3;

const ContactPoint& pointOf(const StepContext& context, int manifold, int point) {
  return context.manifolds[manifold].points[point];
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

/// N s. A body's momentum as seen from a point: m|v|, or I|ω| over the point's lever arm, or the
/// impulse the step's forces gave it, m|a|dt — which is what is left of the body's motion at the
/// top of its flight, where its velocity passes through 0 (a box thrown up along a wall).
double momentumAt(const Body& body, const Vec2& point, double dt) {
  const double lever = (point - body.position).norm();
  const double angular = lever > 0.0 ? body.inertia * std::abs(body.angularVelocity) / lever : 0.0;
  return std::max(
      {body.mass * body.velocity.norm(), angular, body.mass * body.lastAcceleration.norm() * dt});
}

/// The dense LCP of one island, variables (λn, λt⁺, λt⁻, β) per point, from the island's
/// Delassus matrix, friction coefficients and free velocities (normal minus target, tangent).
/// Rows per point i (λt = λt⁺ − λt⁻):
///   normal:   vn − target       = W_nn λn + W_nt λt + (vn₀ − target) ≥ 0  ⟂ λn
///   λt⁺:      vt + β            = W_tn λn + W_tt λt + β + vt₀        ≥ 0  ⟂ λt⁺
///   λt⁻:     −vt + β                                                 ≥ 0  ⟂ λt⁻
///   β:        μλn − λt⁺ − λt⁻                                        ≥ 0  ⟂ β
void formulateLcp(const Eigen::MatrixXd& delassus, const Eigen::VectorXd& friction,
                  const Eigen::VectorXd& free, Eigen::MatrixXd& matrix, Eigen::VectorXd& vector) {
  const int count = static_cast<int>(friction.size());
  const int size = kVariablesPerPoint * count;
  matrix.setZero(size, size);
  vector.setZero(size);
  for (int i = 0; i < count; ++i) {
    const int ri = kVariablesPerPoint * i;
    for (int j = 0; j < count; ++j) {
      const int cj = kVariablesPerPoint * j;
      const Mat2 w = delassus.block<2, 2>(2 * i, 2 * j);
      for (int r = 0; r < 2; ++r) {
        matrix(ri + r, cj + NormalImpulse) = w(r, 0);
        matrix(ri + r, cj + PositiveFriction) = w(r, 1);
        matrix(ri + r, cj + NegativeFriction) = -w(r, 1);
      }
      matrix.block<1, 3>(ri + NegativeFriction, cj) = -matrix.block<1, 3>(ri + 1, cj);
    }
    matrix(ri + PositiveFriction, ri + SlidingSpeed) = 1.0;
    matrix(ri + NegativeFriction, ri + SlidingSpeed) = 1.0;
    matrix(ri + SlidingSpeed, ri + NormalImpulse) = friction(i);
    matrix(ri + SlidingSpeed, ri + PositiveFriction) = -1.0;
    matrix(ri + SlidingSpeed, ri + NegativeFriction) = -1.0;
    vector(ri + NormalImpulse) = free(2 * i);
    vector(ri + PositiveFriction) = free(2 * i + 1);
    vector(ri + NegativeFriction) = -free(2 * i + 1);
  }
}

/// Covering vector number k ≥ 1 of the retries: entries in [0.5, 2), the same on every machine.
Eigen::VectorXd retryCovering(int size, int k) {
  std::mt19937 bits(static_cast<std::mt19937::result_type>(k));
  Eigen::VectorXd covering(size);
  for (int i = 0; i < size; ++i) covering(i) = 0.5 + 1.5 * (bits() / 4294967296.0);
  return covering;
}

/// One Lemke attempt on an island: a path, and whether q is perturbed.
struct LemkeAttempt {
  LemkePath path;
  bool perturbed = false;
  std::string name;
};

/// Attempt number k (0 ≤ k < 3 + 2·kCoveringRetries) in the order they are tried: the
/// lexicographic path, the same on a slightly perturbed q (the textbook remedy for degeneracy),
/// Harris's ratio test, then both ratio tests along kCoveringRetries other covering vectors.
/// Each answer is checked against the physical conditions of the unperturbed problem; the first
/// that passes is used, so the later ones are built only when needed.
LemkeAttempt lemkeAttempt(int size, int k) {
  LemkeAttempt attempt;
  attempt.path.ratioTest =
      k == 2 || (k > 2 && k % 2 == 0) ? RatioTest::Harris : RatioTest::Lexicographic;
  attempt.perturbed = k == 1;
  if (k < 3) {
    attempt.path.covering = Eigen::VectorXd::Ones(size);
    attempt.name = k == 0 ? "" : k == 1 ? "perturbed retry" : "Harris's ratio test";
    return attempt;
  }
  const int vector = (k - 1) / 2;
  attempt.path.covering = retryCovering(size, vector);
  attempt.name = "covering vector " + std::to_string(vector) +
                 (attempt.path.ratioTest == RatioTest::Harris ? " with Harris's test" : "");
  return attempt;
}

/// The Jacobian row of a relative velocity along `direction` at `point` on one body:
/// (d, r×d), with the sign of the side (−1 for A, +1 for B).
Eigen::Vector3d jacobianRow(const Body& body, const Vec2& point, const Vec2& direction,
                            double sign) {
  return sign *
         Eigen::Vector3d(direction.x(), direction.y(), cross(point - body.position, direction));
}

Eigen::Vector3d velocityOf(const Body& body) {
  return {body.velocity.x(), body.velocity.y(), body.angularVelocity};
}

/// The island's bodies (the step's numbers, in the island's order) into its problem: 3 inverse
/// masses and 3 velocities per body.
void setIslandBodies(const StepContext& context, const std::vector<int>& bodies,
                     IslandProblem& problem) {
  problem.inverseMass.resize(3 * static_cast<int>(bodies.size()));
  problem.velocity.resize(3 * static_cast<int>(bodies.size()));
  for (int k = 0; k < static_cast<int>(bodies.size()); ++k) {
    const Body& body = context.bodies[bodies[k]];
    problem.inverseMass.segment<3>(3 * k) << body.inverseMass, body.inverseMass,
        body.inverseInertia;
    problem.velocity.segment<3>(3 * k) = velocityOf(body);
  }
}

/// A point's Jacobian rows, jacobian[axis][side] (axis 0 normal, 1 tangent; side 0 A, 1 B).
using PointJacobian = std::array<std::array<Eigen::Vector3d, 2>, 2>;

/// Adds the term of a body b that points i and j share, J_ib M_b⁻¹ J_jbᵀ, to W's 2×2 block of
/// point i's rows and point j's columns.
void addSharedBody(const PointJacobian& row, int sideI, const PointJacobian& column, int sideJ,
                   const Eigen::Vector3d& inverseMass, Eigen::Matrix2d& block) {
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) {
      block(a, b) += row[a][sideI].cwiseProduct(column[b][sideJ]).dot(inverseMass);
    }
  }
}

/// W's 2×2 blocks in one column pair (point j's two columns) while they are summed body by body:
/// the listed points coupled to j so far and their blocks. Its storage serves every column pair.
class ColumnPairBlocks {
 public:
  /// Blocks for `count` listed points.
  explicit ColumnPairBlocks(int count) : blocks_(count), lastColumn_(count, -1) {}

  /// Point i's block in column pair j, zeroed (and i counted as coupled) when j first asks.
  Eigen::Matrix2d& of(int i, int j) {
    Eigen::Matrix2d& block = blocks_[i];
    if (lastColumn_[i] != j) {
      lastColumn_[i] = j;
      block.setZero();
      coupled_.push_back(i);
    }
    return block;
  }

  /// Writes the column pair's two columns, rows in increasing order, and starts the next pair.
  void write(CompressedColumns& columns) {
    std::sort(coupled_.begin(), coupled_.end());
    for (int b = 0; b < 2; ++b) {
      for (const int i : coupled_) {
        columns.add(2 * i, blocks_[i](0, b));
        columns.add(2 * i + 1, blocks_[i](1, b));
      }
      columns.close();
    }
    coupled_.clear();
  }

 private:
  std::vector<int> coupled_;  ///< the points coupled to this column pair, in the order found
  std::vector<Eigen::Matrix2d> blocks_;
  std::vector<int> lastColumn_;  ///< the column pair each point's block was last zeroed for
};

}  // namespace

// The step of sequential impulses, with the exact impulses in place of the sweeps.
void ReferenceSolver::step(StepStages& stages) {
  stepVelocitiesThenPositions(stages, *this);
}

void ReferenceSolver::solveVelocities(const StepContext& context) {
  const Eigen::VectorXd impulses = exactImpulses(context);
  if (!rows_.empty()) applyImpulses(context, impulses);  // else nothing touches: nothing to solve
  lastStates_.remember(context.manifolds, context.bodies);
}

Eigen::VectorXd ReferenceSolver::exactImpulses(const StepContext& context) {
  report_ = SolveReport{};
  report_.iterations = 0;
  collectPoints(context);
  if (rows_.empty()) return {};
  groupIslands(context);
  buildEffectiveMasses(context);
  buildFreeVelocity(context);
  if (!freeVelocity_.allFinite()) fail("the velocities before the solve are not finite");
  Eigen::VectorXd impulses = Eigen::VectorXd::Zero(2 * static_cast<int>(rows_.size()));
  pushed_ = Eigen::VectorXd::Zero(impulses.size());
  int largeIslands = 0;
  for (const std::vector<int>& island : islands_) {
    solveIsland(context, island, largeIslands, impulses);
  }
  report_.residual = residual(impulses);
  if (!(report_.residual <= settings_.residualTolerance)) {
    std::ostringstream reason;
    reason << "relative residual " << report_.residual << " exceeds the tolerance "
           << settings_.residualTolerance << " after " << report_.iterations
           << " pivots and factorizations";
    fail(reason.str());
  }
  return impulses + pushed_;
}

// The targets use the closing velocity before the solve, with the same rules (bounce threshold,
// penetration bias, speculative gaps) as sequential impulses.
void ReferenceSolver::collectPoints(const StepContext& context) {
  rows_.clear();
  lastStates_.recall(context.manifolds);
  for (int m = 0; m < static_cast<int>(context.manifolds.size()); ++m) {
    const Manifold& manifold = context.manifolds[m];
    const Body& a = context.bodies[manifold.bodyA];
    const Body& b = context.bodies[manifold.bodyB];
    for (int i = 0; i < manifold.pointCount; ++i) {
      const ContactPoint& point = manifold.points[i];
      const double normalVelocity = relativeVelocity(a, b, point.point, manifold.normal);
      PointRow row{
          m,
          i,
          manifold.friction,
          targetSeparatingVelocity(normalVelocity, point.penetration, manifold.restitution,
                                   context.dt, settings_.targets),
          targetSeparatingVelocity(normalVelocity, point.penetration, 0.0, context.dt,
                                   settings_.targets),
          manifold.restitution,
          std::max(momentumAt(a, point.point, context.dt), momentumAt(b, point.point, context.dt))};
      row.body = {a.isStatic() ? -1 : manifold.bodyA, b.isStatic() ? -1 : manifold.bodyB};
      const std::array<Vec2, 2> axes{{manifold.normal, manifold.tangent()}};
      for (int axis = 0; axis < 2; ++axis) {
        row.jacobian[axis] = {jacobianRow(a, point.point, axes[axis], -1.0),
                              jacobianRow(b, point.point, axes[axis], 1.0)};
      }
      row.lastImpulse = {point.normalImpulse, point.tangentImpulse};
      row.carried = point.carried;
      row.lastState = lastStates_.recalled(m, i);
      rows_.push_back(row);
    }
  }
}

// The bodies' inverse masses (3 per body, 0 for static ones) and the diagonal of the Delassus
// matrix W = J M⁻¹ Jᵀ: what every island needs. W itself is formed only for an island Lemke
// solves (islandDelassus) and on request (delassusMatrix); elsewhere W λ is taken through the
// bodies (velocityChange).
void ReferenceSolver::buildEffectiveMasses(const StepContext& context) {
  inverseMass_.resize(3 * static_cast<int>(context.bodies.size()));
  for (int b = 0; b < static_cast<int>(context.bodies.size()); ++b) {
    const Body& body = context.bodies[b];
    inverseMass_.segment<3>(3 * b) << body.inverseMass, body.inverseMass, body.inverseInertia;
  }
  diagonal_.resize(2 * static_cast<int>(rows_.size()));
  for (int k = 0; k < diagonal_.size(); ++k) {
    diagonal_(k) = inverseEffectiveMass(rows_[k / 2], k % 2, inverseMass_);
  }
}

// W's rows and columns of the listed points (an island, or all points: islands do not couple),
// in their order (local point k is points[k]). Built
// column pair by column pair: for point j, the 2×2 block of every listed point i sharing a body b
// with it, Σ_b J_ib M_b⁻¹ J_jbᵀ, each product formed as (J_ib J_jb) M_b⁻¹ so that W is exactly
// symmetric. Only points that share a dynamic body couple.
Eigen::SparseMatrix<double> ReferenceSolver::islandDelassus(const std::vector<int>& points) const {
  const int count = static_cast<int>(points.size());
  const std::vector<std::vector<std::pair<int, int>>> pointsOfBody = pointsOfBodies(points);
  Eigen::Index entries = 0;  // at most 4 per pair of points sharing a body
  for (const auto& incident : pointsOfBody) {
    const Eigen::Index shared = static_cast<int>(incident.size());
    entries += 4 * shared * shared;
  }
  CompressedColumns columns(2 * count, entries);
  ColumnPairBlocks blocks(count);
  for (int j = 0; j < count; ++j) {
    const PointRow& column = rows_[points[j]];
    for (int sideJ = 0; sideJ < 2; ++sideJ) {
      const int body = column.body[sideJ];
      if (body < 0) continue;
      const Eigen::Vector3d inverseMass = inverseMass_.segment<3>(3 * body);
      for (const auto& [i, sideI] : pointsOfBody[body]) {
        addSharedBody(rows_[points[i]].jacobian, sideI, column.jacobian, sideJ, inverseMass,
                      blocks.of(i, j));
      }
    }
    blocks.write(columns);
  }
  return columns.take();
}

// Each body's points among the listed ones, as (local point, side of the contact: 0 A, 1 B), in
// the order of the list.
std::vector<std::vector<std::pair<int, int>>> ReferenceSolver::pointsOfBodies(
    const std::vector<int>& points) const {
  std::vector<std::vector<std::pair<int, int>>> pointsOfBody(inverseMass_.size() / 3);
  for (int k = 0; k < static_cast<int>(points.size()); ++k) {
    for (int side = 0; side < 2; ++side) {
      const int body = rows_[points[k]].body[side];
      if (body >= 0) pointsOfBody[body].push_back({k, side});
    }
  }
  return pointsOfBody;
}

Eigen::SparseMatrix<double> ReferenceSolver::delassusMatrix() const {
  std::vector<int> all(rows_.size());
  for (int i = 0; i < static_cast<int>(all.size()); ++i) all[i] = i;
  return islandDelassus(all);
}

// W λ on the rows of the listed points, from their impulses (in the layout of all points): the
// bodies' velocity changes M⁻¹Jᵀλ, then J of them. The listed points must be whole islands (or
// all points), which share no dynamic body with the others. Entries of other points are 0.
Eigen::VectorXd ReferenceSolver::velocityChange(const std::vector<int>& points,
                                                const Eigen::VectorXd& impulses) const {
  Eigen::VectorXd bodies = Eigen::VectorXd::Zero(inverseMass_.size());
  for (const int i : points) {
    for (int axis = 0; axis < 2; ++axis) {
      addBodyVelocityChange(rows_[i], axis, impulses(2 * i + axis), inverseMass_, bodies);
    }
  }
  Eigen::VectorXd change = Eigen::VectorXd::Zero(impulses.size());
  for (const int i : points) {
    for (int axis = 0; axis < 2; ++axis) {
      change(2 * i + axis) = jacobianTimes(rows_[i], axis, bodies);
    }
  }
  return change;
}

void ReferenceSolver::buildFreeVelocity(const StepContext& context) {
  freeVelocity_.resize(2 * static_cast<int>(rows_.size()));
  for (int i = 0; i < static_cast<int>(rows_.size()); ++i) {
    const Manifold& manifold = context.manifolds[rows_[i].manifold];
    const Body& a = context.bodies[manifold.bodyA];
    const Body& b = context.bodies[manifold.bodyB];
    const Vec2& point = pointOf(context, rows_[i].manifold, rows_[i].point).point;
    freeVelocity_(2 * i) = relativeVelocity(a, b, point, manifold.normal);
    freeVelocity_(2 * i + 1) = relativeVelocity(a, b, point, manifold.tangent());
  }
}

// Union-find over the dynamic bodies: two points share an island when a chain of contacts
// through dynamic bodies joins them. A static body joins nothing (it takes no impulse, so the
// points on it do not couple), which is what cuts a pile on the ground into islands.
void ReferenceSolver::groupIslands(const StepContext& context) {
  UnionFind bodies;
  bodies.reset(static_cast<int>(context.bodies.size()));
  for (const PointRow& row : rows_) {
    if (row.body[0] >= 0 && row.body[1] >= 0) bodies.join(row.body[0], row.body[1]);
  }
  std::vector<int> islandOfRoot(context.bodies.size(), -1);
  islands_.clear();
  for (int i = 0; i < static_cast<int>(rows_.size()); ++i) {
    const PointRow& row = rows_[i];
    const int body = bodies.root(row.body[0] >= 0 ? row.body[0] : row.body[1]);
    int& island = islandOfRoot[body];
    if (island < 0) {
      island = static_cast<int>(islands_.size());
      islands_.emplace_back();
    }
    islands_[island].push_back(i);
  }
}

// The island's points with each manifold's two in the order of their feature ids: the clipping
// may list a face's two points either way round from step to step (boxes side by side), and a
// fixed order keeps the system a resting pile poses the same from step to step, as its kept
// factors need (KeptFactorization). A manifold's points are next to each other in an island.
std::vector<int> ReferenceSolver::inFeatureIdOrder(const StepContext& context,
                                                   const std::vector<int>& island) const {
  std::vector<int> ordered = island;
  for (int k = 0; k + 1 < static_cast<int>(ordered.size()); ++k) {
    const PointRow& first = rows_[ordered[k]];
    const PointRow& second = rows_[ordered[k + 1]];
    if (first.manifold != second.manifold) continue;
    const Manifold& manifold = context.manifolds[first.manifold];
    const auto id = [&](const PointRow& row) { return manifold.points[row.point].id; };
    if (id(second) < id(first)) std::swap(ordered[k], ordered[k + 1]);
    ++k;
  }
  return ordered;
}

// Small islands by Lemke, with the active set as the fallback; large ones by the active set,
// with Lemke as the fallback while the island is not too large for it. An island whose bounces
// have no answer together bounces in two solves (restitutionInTwoSolves); any other failure ends
// the solve with its reason.
void ReferenceSolver::solveIsland(const StepContext& context, const std::vector<int>& island,
                                  int& largeIslands, Eigen::VectorXd& impulses) {
  std::string failure;
  if (solveIslandOnce(context, island, largeIslands, impulses, failure)) return;
  const bool bounces =
      std::any_of(island.begin(), island.end(), [this](int i) { return rows_[i].bounces(); });
  if (!settings_.restitutionInTwoSolves || !bounces) fail(failure);
  bounceInTwoSolves(context, island, largeIslands, impulses, failure);
}

bool ReferenceSolver::solveIslandOnce(const StepContext& context, const std::vector<int>& island,
                                      int& largeIslands, Eigen::VectorXd& impulses,
                                      std::string& failure) {
  const int points = static_cast<int>(island.size());
  const bool large = points > settings_.lemkeIslandPoints;
  failure.clear();
  if (large) {
    if (solveIslandByActiveSet(context, island, keptFactorization(largeIslands++), impulses,
                               failure)) {
      return true;
    }
    if (points > settings_.lemkeFallbackPoints) return false;
    failure += "; ";
  }
  const LcpSolution solution = solveByLemke(island);
  report_.iterations += solution.pivots;
  if (solution.solved) {
    const Eigen::VectorXd answer = islandImpulses(island, solution.z);
    for (const int point : island) {
      impulses.segment<2>(2 * point) = answer.segment<2>(2 * point);
      PointRow& row = rows_[point];
      row.state = stateOfImpulses(answer(2 * point), answer(2 * point + 1), row.friction);
    }
    return true;
  }
  failure += solution.failure;
  if (large) return false;
  // Lemke's paths can all end a little short of the tolerance on a small, degenerate island (a
  // row of ten 0.1 m balls on a frictionless floor at 240 Hz: 1.2e-9 to 3.7e-9 on every path);
  // the active set, which factorizes the island afresh, answers it.
  failure += "; ";
  KeptFactorization scratch;
  return solveIslandByActiveSet(context, island, scratch, impulses, failure);
}

bool ReferenceSolver::solveIslandByActiveSet(const StepContext& context,
                                             const std::vector<int>& island,
                                             KeptFactorization& kept, Eigen::VectorXd& impulses,
                                             std::string& failure) {
  const std::vector<int> ordered = inFeatureIdOrder(context, island);
  const ActiveSetAnswer answer = solveByActiveSet(context, ordered, kept);
  report_.iterations += answer.factorizations;
  if (!answer.solved) {
    failure += answer.failure;
    return false;
  }
  for (int k = 0; k < static_cast<int>(ordered.size()); ++k) {
    const int i = ordered[k];
    impulses.segment<2>(2 * i) = answer.impulses.segment<2>(2 * k);
    rows_[i].state = answer.states[k];
  }
  const double violation = residualOver(island, impulses);
  if (violation <= settings_.residualTolerance) return true;
  std::ostringstream reason;
  reason << "active set: relative residual " << violation << " exceeds the tolerance "
         << settings_.residualTolerance;
  failure += reason.str();
  return false;
}

// Poisson's law of restitution in two solves. Compression: the island with its bounce targets
// taken out, which has an answer λc like any problem whose targets are 0 or below. Restitution:
// every point pushed by λc, and each point that was to bounce also along its normal by e·λc,n
// (a point closing too slowly to bounce gets none, as under Newton's law), the free velocities
// moved by what both do (W times them), and the island solved again with no bounce, so nothing
// ends closing. What is checked from then on is that second problem; pushed_ keeps λc and the
// push, and the step applies them with the second answer.
void ReferenceSolver::bounceInTwoSolves(const StepContext& context, const std::vector<int>& island,
                                        int& largeIslands, Eigen::VectorXd& impulses,
                                        const std::string& newtonFailure) {
  std::vector<double> restitution(island.size(), 0.0);  // of the points that were to bounce
  for (int k = 0; k < static_cast<int>(island.size()); ++k) {
    PointRow& row = rows_[island[k]];
    if (row.bounces()) restitution[k] = row.restitution;
    row.targetNormalVelocity = row.inelasticTarget;
  }
  std::string failure;
  if (!solveIslandOnce(context, island, largeIslands, impulses, failure)) {
    fail(newtonFailure + "; in two solves, compression: " + failure);
  }
  Eigen::VectorXd push = Eigen::VectorXd::Zero(impulses.size());
  for (int k = 0; k < static_cast<int>(island.size()); ++k) {
    const int i = island[k];
    push.segment<2>(2 * i) = impulses.segment<2>(2 * i);
    push(2 * i) *= 1.0 + restitution[k];
  }
  freeVelocity_ += velocityChange(island, push);
  pushed_ += push;
  if (!solveIslandOnce(context, island, largeIslands, impulses, failure)) {
    fail(newtonFailure + "; in two solves, restitution: " + failure);
  }
}

// The island's dense LCP (formulateLcp) from its block of W, its friction coefficients and its
// free velocities, the normal ones less their targets.
void ReferenceSolver::islandLcp(const std::vector<int>& island, Eigen::MatrixXd& matrix,
                                Eigen::VectorXd& vector) const {
  const int count = static_cast<int>(island.size());
  Eigen::VectorXd friction(count);
  Eigen::VectorXd free(2 * count);
  for (int k = 0; k < count; ++k) {
    const int i = island[k];
    friction(k) = rows_[i].friction;
    free(2 * k) = freeVelocity_(2 * i) - rows_[i].targetNormalVelocity;
    free(2 * k + 1) = freeVelocity_(2 * i + 1);
  }
  formulateLcp(Eigen::MatrixXd(islandDelassus(island)), friction, free, matrix, vector);
}

LcpSolution ReferenceSolver::solveByLemke(const std::vector<int>& island) const {
  Eigen::MatrixXd matrix;
  Eigen::VectorXd vector;
  islandLcp(island, matrix, vector);
  const int size = static_cast<int>(vector.size());
  const Eigen::VectorXd growing = Eigen::VectorXd::LinSpaced(size, 1.0, 2.0);
  const double perturbation =
      size > 0 ? kDegeneracyPerturbation * vector.cwiseAbs().maxCoeff() : 0.0;
  std::string failures;
  int pivots = 0;
  for (int k = 0; k < 3 + 2 * kCoveringRetries; ++k) {
    const LemkeAttempt attempt = lemkeAttempt(size, k);
    LcpSolution solution = solveLemke(
        matrix, attempt.perturbed ? Eigen::VectorXd(vector + perturbation * growing) : vector,
        attempt.path, settings_.lemke);
    pivots += solution.pivots;
    if (solution.solved) {
      const double violation = residualOver(island, islandImpulses(island, solution.z));
      if (violation <= settings_.residualTolerance) {
        solution.pivots = pivots;
        return solution;
      }
      std::ostringstream reason;
      reason << "Lemke: relative residual " << violation << " exceeds the tolerance "
             << settings_.residualTolerance << " after " << solution.pivots << " pivots";
      solution.failure = reason.str();
    }
    failures +=
        attempt.name.empty() ? solution.failure : "; " + attempt.name + ": " + solution.failure;
  }
  LcpSolution failed;
  failed.pivots = pivots;
  failed.failure = failures;
  return failed;
}

// The island's (λn, λt) from the LCP's z, placed in the layout of all points.
Eigen::VectorXd ReferenceSolver::islandImpulses(const std::vector<int>& island,
                                                const Eigen::VectorXd& z) const {
  Eigen::VectorXd impulses = Eigen::VectorXd::Zero(2 * static_cast<int>(rows_.size()));
  for (int k = 0; k < static_cast<int>(island.size()); ++k) {
    const int ri = kVariablesPerPoint * k;
    impulses.segment<2>(2 * island[k]) << z(ri + NormalImpulse),
        z(ri + PositiveFriction) - z(ri + NegativeFriction);
  }
  return impulses;
}

KeptFactorization& ReferenceSolver::keptFactorization(int ordinal) {
  while (static_cast<int>(keptFactors_.size()) <= ordinal) {
    keptFactors_.push_back(std::make_unique<KeptFactorization>());
  }
  return *keptFactors_[ordinal];
}

ActiveSetAnswer ReferenceSolver::solveByActiveSet(const StepContext& context,
                                                  const std::vector<int>& island,
                                                  KeptFactorization& kept) {
  IslandProblem problem;
  std::vector<int> localBody(context.bodies.size(), -1);
  std::vector<int> bodies;
  problem.guess.resize(2 * static_cast<int>(island.size()));
  for (int k = 0; k < static_cast<int>(island.size()); ++k) {
    const PointRow& row = rows_[island[k]];
    problem.points.push_back(islandPoint(context, row, localBody, bodies));
    problem.guess.segment<2>(2 * k) = row.lastImpulse;
  }
  setIslandBodies(context, bodies, problem);
  if (needsGuessSweeps(problem, settings_.activeSet)) problem.delassus = islandDelassus(island);
  return solveActiveSet(problem, settings_.activeSet, kept);
}

// A point as the active set sees it: a static body's part of its velocities folded into
// staticVelocity, its dynamic bodies numbered in the island as they are first met (localBody:
// each body's number in the island, −1 before; bodies: the step's number of each).
IslandPoint ReferenceSolver::islandPoint(const StepContext& context, const PointRow& row,
                                         std::vector<int>& localBody, std::vector<int>& bodies) {
  IslandPoint point;
  point.carried = row.carried;
  point.lastState = row.lastState;
  point.targetNormalVelocity = row.targetNormalVelocity;
  point.friction = row.friction;
  point.jacobian = row.jacobian;
  const Manifold& manifold = context.manifolds[row.manifold];
  const std::array<int, 2> pair{{manifold.bodyA, manifold.bodyB}};
  for (int side = 0; side < 2; ++side) {
    const Body& body = context.bodies[pair[side]];
    if (row.body[side] < 0) {
      for (int axis = 0; axis < 2; ++axis) {
        point.staticVelocity[axis] += row.jacobian[axis][side].dot(velocityOf(body));
      }
      continue;
    }
    int& local = localBody[pair[side]];
    if (local < 0) {
      local = static_cast<int>(bodies.size());
      bodies.push_back(pair[side]);
    }
    point.body[side] = local;
  }
  return point;
}

// The answer is checked against the physical conditions themselves, not the LCP's bookkeeping,
// so an error in the formulation would show here too.
double ReferenceSolver::residual(const Eigen::VectorXd& impulses) const {
  if (impulses.size() == 0) return 0.0;
  std::vector<int> all(rows_.size());
  for (int i = 0; i < static_cast<int>(all.size()); ++i) all[i] = i;
  return residualOver(all, impulses);
}

// The worst violated condition of the listed points (impulses in the layout of all points),
// relative to their impulse scale.
double ReferenceSolver::residualOver(const std::vector<int>& points,
                                     const Eigen::VectorXd& impulses) const {
  const Eigen::VectorXd velocity = freeVelocity_ + velocityChange(points, impulses);
  double worst = 0.0;
  for (const int i : points) {
    const PointRow& row = rows_[i];
    worst = std::max(
        worst, pointViolation(impulses(2 * i), impulses(2 * i + 1),
                              velocity(2 * i) - row.targetNormalVelocity, velocity(2 * i + 1),
                              row.friction, 1.0 / diagonal_(2 * i), 1.0 / diagonal_(2 * i + 1)));
  }
  const double scale = impulseScale(points, impulses);
  return scale > 0.0 ? worst / scale : worst;
}

// N s. The size of the step's impulses, so that the residual is relative to something that
// cannot vanish when the answer does (a corner touching down, an elastic row that has already
// separated, where every impulse is 0 and rounding is all that is left): the largest impulse, each
// point's cancelling impulses (what stops its normal and tangent motion alone, velocity over
// effective mass) and the momenta of the bodies in contact (m|v|, I|ω| over the point's lever
// arm, and the impulse of the step's forces m|a|dt, for a body whose velocity passes through 0).
double ReferenceSolver::impulseScale(const std::vector<int>& points,
                                     const Eigen::VectorXd& impulses) const {
  double scale = 0.0;
  for (const int i : points) {
    const PointRow& row = rows_[i];
    scale = std::max({scale, std::abs(impulses(2 * i)), std::abs(impulses(2 * i + 1)),
                      std::abs(freeVelocity_(2 * i) - row.targetNormalVelocity) / diagonal_(2 * i),
                      std::abs(freeVelocity_(2 * i + 1)) / diagonal_(2 * i + 1), row.momentum});
  }
  return scale;
}

void ReferenceSolver::applyImpulses(const StepContext& context, const Eigen::VectorXd& impulses) {
  const double onLimit = settings_.residualTolerance * impulses.cwiseAbs().maxCoeff();
  for (int i = 0; i < static_cast<int>(rows_.size()); ++i) {
    const PointRow& row = rows_[i];
    Manifold& manifold = context.manifolds[row.manifold];
    ContactPoint& point = manifold.points[row.point];
    point.normalImpulse = impulses(2 * i);
    point.tangentImpulse = impulses(2 * i + 1);
    point.friction =
        frictionStateOf(point.normalImpulse, point.tangentImpulse, row.friction, onLimit);
    lastStates_.store(row.manifold, row.point, row.state);
    applyContactImpulse(context.bodies, manifold, row.point, point.normalImpulse,
                        point.tangentImpulse);
    context.report({SolverEvent::Phase::Velocity, 0, row.manifold, row.point,
                    row.targetNormalVelocity - freeVelocity_(2 * i), point.normalImpulse,
                    point.tangentImpulse});
  }
}

void ReferenceSolver::fail(const std::string& reason) {
  report_.converged = false;
  throw ReferenceSolveFailure(reason);
}

void ReferenceSolver::solvePositions(const StepContext& context) {
  correctPositions(context, settings_.positionPass, settings_.targets.allowedPenetration,
                   settings_.blockConditionLimit);
}

}  // namespace impulse2d
