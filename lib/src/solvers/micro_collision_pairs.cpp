// Pairs, a refinement of the lecture's resolver: a flat contact's two points resolved as one
// micro-collision (block impulses) and moved out as one (block moves). It fixes the rocking of
// one corner at a time, where each corner's impulse or move drives the other deeper.
#include "impulse2d/solvers/micro_collision.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "impulse2d/solvers/contact_math.h"
#include "impulse2d/solvers/two_point_block.h"

namespace impulse2d {

// With pair impulses, every two-point manifold is a pair; its contact matrix
// (invertPairContactMatrix) is inverted the first time the pair is tried in a step.
void MicroCollisionSolver::preparePairs() {
  pairs_.clear();
  if (settings_.impulses < MicroCollisionImpulses::Block) return;
  for (int first = 0; first + 1 < static_cast<int>(states_.size()); ++first) {
    if (otherPoint(first) != first + 1) continue;
    states_[first].pair = states_[first + 1].pair = static_cast<int>(pairs_.size());
    pairs_.push_back({first, PointPair::Status::NotInverted, Eigen::Matrix3d::Zero(),
                      Eigen::Matrix3d::Zero(), Eigen::Matrix2d::Zero()});
  }
}

// The lecture's contact matrix for the two points of a flat contact. Its rows and columns are
// the normal at the first point, the normal at the second, and the tangent: both points slip
// alike (they lie on one face, so a turn moves them alike along it) and a friction impulse turns
// the bodies alike wherever it acts along the face, so the two tangents are one direction.
// Entry (i, j) is the velocity change along i per unit impulse along j (velocityPerUnitImpulse of
// contact_math.h summed over both bodies, written on the solver's copies of them). Its inverse
// turns the wanted velocity changes into impulses; its two normal rows and columns alone, those of
// a frictionless pair. A nearly singular matrix (the points almost at one place) leaves the pair
// to single points.
void MicroCollisionSolver::invertPairContactMatrix(PointPair& pair) const {
  const PointState& p0 = states_[pair.first];
  const PointState& p1 = states_[pair.first + 1];
  const SolverBody& a = solverBodies_[p0.bodyA];
  const SolverBody& b = solverBodies_[p0.bodyB];
  const Vec2 tangent = leftPerpendicular(p0.normal);
  const std::array<Vec2, 3> direction = {p0.normal, p0.normal, tangent};
  const std::array<Vec2, 3> armA = {p0.armA, p1.armA, 0.5 * (p0.armA + p1.armA)};
  const std::array<Vec2, 3> armB = {p0.armB, p1.armB, 0.5 * (p0.armB + p1.armB)};
  Eigen::Matrix3d k;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      k(i, j) = couplingPerUnitImpulse(a, b, armA[i], armB[i], direction[i], armA[j], armB[j],
                                       direction[j]);
    }
  }
  // Hadamard's ratio: det K against the product of its diagonal (1 for a diagonal K).
  const double diagonal = k(0, 0) * k(1, 1) * k(2, 2);
  if (!(diagonal > 0.0) || k.determinant() < diagonal / settings_.blockConditionLimit) {
    pair.status = PointPair::Status::Singular;
    return;
  }
  pair.contactMatrix = k;
  pair.inverseContactMatrix = k.inverse();
  pair.inverseNormalMatrix = k.topLeftCorner<2, 2>().inverse();
  pair.status = PointPair::Status::Inverted;
}

// The pair's totals when static friction cannot hold it: dynamic friction, the tangent total
// `slide` = σμ times the normal total, σ the sign of the total static friction would have needed
// (as newTotalImpulse does for one point), and the two normal totals that still give both points
// their wanted normal change: Σⱼ K(i, j)(afterⱼ − beforeⱼ) = changeᵢ for the two normal rows,
// with after₂ = σμ (after₀ + after₁). False when that 2×2 system is as ill-conditioned as a pair
// matrix may not be (blockConditionLimit, Hadamard's ratio as in invertPairContactMatrix).
bool MicroCollisionSolver::slidingPairTotals(const PointPair& pair, const Eigen::Vector3d& before,
                                             const Eigen::Vector3d& change, double slide,
                                             Eigen::Vector3d& after) const {
  const Eigen::Matrix3d& k = pair.contactMatrix;
  Eigen::Matrix2d system;
  Eigen::Vector2d right;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) system(i, j) = k(i, j) + slide * k(i, 2);
    right(i) = change(i) + k.row(i) * before;
  }
  const double diagonal = std::abs(system(0, 0) * system(1, 1));
  if (!(std::abs(system.determinant()) > diagonal / settings_.blockConditionLimit)) return false;
  const Eigen::Vector2d normals = system.inverse() * right;
  after << normals(0), normals(1), slide * (normals(0) + normals(1));
  return true;
}

// Both points of the worst point's manifold in one micro-collision: the impulses that give both
// points their wanted normal change and stop the face slipping, through the pair's contact
// matrix. The friction total is shared between the points in proportion to their normal totals,
// so each stays in its cone when the total does. Taken only when both points are engaged and
// need resolving (a pair impulse where one corner is already resolved costs a settling pile more
// than it saves, docs/design/micro-collision-cost.md), both are to bounce or
// neither (with MicroCollisionImpulses::BlockWithBounces; without it a bounce passes point by
// point, as in the cradle), and the new totals push at both points, with static friction or, where
// static friction cannot hold the pair, dynamic friction (slidingPairTotals); otherwise false, and
// the worst point is resolved alone. A frictionless pair (friction off, or μ = 0) takes only the
// normal changes, through the normal rows of the contact matrix. A pair that bounces takes each
// point to its bounce on its closing velocity now, and both count as bounced.
bool MicroCollisionSolver::applyPairChange(const StepContext& context, const PointState& worst,
                                           int iteration) {
  PointPair& pair = pairs_[worst.pair];
  const PointsOfPair points = {&states_[pair.first], &states_[pair.first + 1]};
  Manifold& manifold = context.manifolds[worst.manifold];
  const bool frictionless = !settings_.friction || manifold.friction <= 0.0;
  const bool bounce = toBounce(*points[0]);
  std::array<Vec2, 2> desired;
  if (!pairNeedsChange(points, bounce, desired)) return false;
  if (pair.status == PointPair::Status::NotInverted) invertPairContactMatrix(pair);
  if (pair.status == PointPair::Status::Singular) return false;
  Eigen::Vector3d after;
  bool sliding = false;
  if (!newPairTotals(pair, points, desired, frictionless ? 0.0 : manifold.friction, after,
                     sliding)) {
    return false;
  }
  const FrictionState friction = frictionless ? FrictionState::None
                                 : sliding    ? FrictionState::Dynamic
                                              : FrictionState::Static;
  const std::array<Vec2, 2> impulses = applyPairTotals(manifold, points, after, friction, bounce);
  afterImpulse(context, worst);
  for (int i = 0; i < 2; ++i) {
    context.report({SolverEvent::Phase::Velocity, iteration, points[i]->manifold, points[i]->point,
                    normalPart(desired[i]), normalPart(impulses[i]), tangentPart(impulses[i])});
  }
  return true;
}

// Whether both points may take a pair impulse (applyPairChange), and the velocity change each
// wants.
bool MicroCollisionSolver::pairNeedsChange(const PointsOfPair& points, bool bounce,
                                           std::array<Vec2, 2>& desired) const {
  if (bounce && settings_.impulses != MicroCollisionImpulses::BlockWithBounces) return false;
  for (int i = 0; i < 2; ++i) {
    const PointState& point = *points[i];
    if (!engaged(point) || point.bounced) return false;
    if (toBounce(point) != bounce) return false;                     // both bounce, or neither
    if (severity(point) <= settings_.velocityEpsilon) return false;  // both must need it
    desired[i] = desiredVelocityChange(point);
  }
  return true;
}

// The pair's new totals (normal at each point, friction of both) that give the desired changes,
// through the inverse contact matrix (its normal rows when frictionless, `friction` = 0), or on
// the friction cone's edge when static friction cannot hold (`sliding`). False unless both
// normal totals push.
bool MicroCollisionSolver::newPairTotals(const PointPair& pair, const PointsOfPair& points,
                                         const std::array<Vec2, 2>& desired, double friction,
                                         Eigen::Vector3d& after, bool& sliding) const {
  const bool frictionless = friction <= 0.0;
  const Eigen::Vector3d before(
      normalPart(points[0]->totalImpulse), normalPart(points[1]->totalImpulse),
      tangentPart(points[0]->totalImpulse) + tangentPart(points[1]->totalImpulse));
  const Eigen::Vector3d change(normalPart(desired[0]), normalPart(desired[1]),
                               0.5 * (tangentPart(desired[0]) + tangentPart(desired[1])));
  if (frictionless) {
    after << before.head<2>() + pair.inverseNormalMatrix * change.head<2>(), 0.0;
  } else {
    after = before + pair.inverseContactMatrix * change;
  }
  sliding = !frictionless && std::abs(after(2)) > friction * (after(0) + after(1));
  const double slide = (after(2) > 0.0 ? 1.0 : -1.0) * friction;
  if (sliding && !slidingPairTotals(pair, before, change, slide, after)) return false;
  return !(after(0) <= 0.0 || after(1) <= 0.0);
}

// Gives both points their new totals, the friction total shared in proportion to the normal
// totals, records them on the manifold and applies the changes; the impulses applied.
std::array<Vec2, 2> MicroCollisionSolver::applyPairTotals(Manifold& manifold,
                                                          const PointsOfPair& points,
                                                          const Eigen::Vector3d& after,
                                                          FrictionState friction, bool bounce) {
  const double normalTotal = after(0) + after(1);
  std::array<Vec2, 2> impulses;
  for (int i = 0; i < 2; ++i) {
    PointState& point = *points[i];
    const Vec2 total(after(i), after(2) * after(i) / normalTotal);
    impulses[i] = total - point.totalImpulse;
    point.totalImpulse = total;
    point.friction = friction;
    point.bounced = point.bounced || bounce;
    ContactPoint& record = manifold.points[point.point];
    record.normalImpulse = normalPart(total);
    record.tangentImpulse = tangentPart(total);
    record.friction = point.friction;
    applyImpulse(point, impulses[i]);
  }
  return impulses;
}

// The other point of the manifold of states_[index], or −1 for a one-point manifold. prepare
// lists a manifold's points one after the other.
int MicroCollisionSolver::otherPoint(int index) const {
  const int manifold = states_[index].manifold;
  for (const int other : {index - 1, index + 1}) {
    if (other >= 0 && other < static_cast<int>(states_.size()) &&
        states_[other].manifold == manifold) {
      return other;
    }
  }
  return -1;
}

// Both points of a two-point manifold in one move. Moving the bodies by position impulses x
// (x along +n to B, −n to A, each body shifted by x/m and turned by x(r × n)/I, as a single
// point's move splits itself) changes the penetrations by −K x, K the pair's coupling matrix at
// the poses now; x ≥ 0 leaves neither point penetrating and pushes only where one touches (the
// 2×2 complementarity problem of two_point_block.h). False, moving nothing, when K is too
// ill-conditioned or a turn would pass the angular move limit: the point is then resolved alone.
bool MicroCollisionSolver::resolvePair(const StepContext& context, int index, int partner,
                                       int iteration) {
  const std::array<const MovePoint*, 2> points = {&movePoints_[index], &movePoints_[partner]};
  Pose& a = poses_[points[0]->bodyA];
  Pose& b = poses_[points[0]->bodyB];
  const Vec2 normal = points[0]->normal;
  std::array<Vec2, 2> armA;
  std::array<Vec2, 2> armB;
  std::array<double, 2> torqueArmA{};
  std::array<double, 2> torqueArmB{};
  for (int i = 0; i < 2; ++i) {
    const Vec2 point = contactPointNow(*points[i], normal);
    armA[i] = point - a.position;
    armB[i] = point - b.position;
    torqueArmA[i] = cross(armA[i], normal);
    torqueArmB[i] = cross(armB[i], normal);
  }
  const Mat2 k = normalCouplingMatrix(a, b, normal, armA, armB);
  if (!isWellConditioned(k, settings_.blockConditionLimit)) return false;
  const Vec2 x = solveTwoPointLcp(k, Vec2(-points[0]->penetration, -points[1]->penetration));
  const double turnA = -a.inverseInertia * (torqueArmA[0] * x(0) + torqueArmA[1] * x(1));
  const double turnB = b.inverseInertia * (torqueArmB[0] * x(0) + torqueArmB[1] * x(1));
  if (std::max(std::abs(turnA), std::abs(turnB)) > settings_.angularMoveLimit) return false;
  const std::array<double, 2> removed = {points[0]->penetration, points[1]->penetration};
  for (auto [pose, sign, turn] : {std::tuple{&a, -1.0, turnA}, std::tuple{&b, 1.0, turnB}}) {
    if (!pose->movable) continue;
    pose->position += sign * pose->inverseMass * (x(0) + x(1)) * normal;
    pose->turnBy(turn);
    pose->moved = true;
  }
  afterMove(context, *points[0]);
  const std::array<int, 2> indices = {index, partner};
  for (int i = 0; i < 2; ++i) {
    const PointState& state = states_[indices[i]];
    context.report({SolverEvent::Phase::Position, iteration, state.manifold, state.point,
                    removed[i], 0.0, 0.0});
  }
  return true;
}

}  // namespace impulse2d
