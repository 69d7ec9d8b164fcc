// The micro-collision resolver of lecture 3.6. Velocity resolution: repeatedly take the contact
// whose desired velocity change is largest, apply the one impulse that achieves it (with static
// or dynamic friction), and update the contact velocities of every contact sharing a body.
// Penetration resolution: repeatedly take the deepest contact and move its two bodies apart,
// split between linear and angular motion in proportion to their inertia at the contact.
#include "impulse2d/solvers/micro_collision.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "impulse2d/solvers/contact_math.h"

namespace impulse2d {
namespace {

/// Rows and columns of the contact matrix (contact_math.h, contactMatrix).
enum ContactAxis : int { Normal = 0, Tangent = 1 };

}  // namespace
// ---- velocity resolution ----

// The lecture's update: the micro-collisions on the velocities the forces gave, then the
// remaining penetration resolved once the bodies have moved.
void MicroCollisionSolver::step(StepStages& stages) {
  stepVelocitiesThenPositions(stages, *this);
}

void MicroCollisionSolver::solveVelocities(const StepContext& context) {
  prepare(context);
  queueKeys_.clear();
  for (const PointState& state : states_) queueKeys_.push_back(severity(state));
  queue_.reset(queueKeys_, settings_.velocityEpsilon);
  const int points = static_cast<int>(states_.size());
  const int cap = settings_.velocityIterationsPerContact * points;
  const int limit = settings_.passCapWhileProgressing
                        ? std::max(cap, settings_.velocityIterationsPerContactLimit * points)
                        : cap;
  report_ = SolveReport{};
  waitingTotals_.clear();
  int roundEnd = points;
  while (report_.iterations < limit) {
    const int worst = worstVelocityPoint();
    if (worst < 0) break;
    applyVelocityChange(context, worst, report_.iterations);
    if (++report_.iterations == roundEnd) {
      recordRound();
      roundEnd += points;
    }
    if (report_.iterations >= cap && !stillProgressing()) break;
  }
  const int remaining = worstVelocityPoint();
  report_.residual = remaining < 0 ? 0.0 : severity(states_[remaining]);
  report_.converged = remaining < 0;
  storeVelocities(context);
  for (const PointState& state : states_)
    bounced_.store(state.manifold, state.point, state.bounced);
  bounced_.remember(context.manifolds, context.bodies);
}

// After every round of one impulse per point (with passCapWhileProgressing), the total desired
// velocity change of the points still waiting: the queue's keys.
void MicroCollisionSolver::recordRound() {
  if (settings_.passCapWhileProgressing) waitingTotals_.push_back(queue_.waitingTotal());
}

// Whether the impulses may go on past the cap: the waiting total fell by at least minimumProgress
// over the last progressRounds rounds. A pile passing its weight down from rest converges at a
// steady rate until it is resolved; a pile hit every step (rain landing) soon creeps along
// Gauss–Seidel's slow tail, where the impulses left would buy little. A span of no rounds never
// shows progress.
bool MicroCollisionSolver::stillProgressing() const {
  const int rounds = static_cast<int>(waitingTotals_.size());
  const int span = settings_.progressRounds;
  if (!settings_.passCapWhileProgressing || span < 1 || rounds <= span) return false;
  const double before = waitingTotals_[rounds - 1 - span];
  return waitingTotals_.back() <= (1.0 - settings_.minimumProgress) * before;
}

void MicroCollisionSolver::prepare(const StepContext& context) {
  dt_ = context.dt;
  loadSolverBodies(context);
  states_.clear();
  bounced_.recall(context.manifolds);
  for (int m = 0; m < static_cast<int>(context.manifolds.size()); ++m) {
    Manifold& manifold = context.manifolds[m];
    context.bodies[manifold.bodyA].wake();  // a contact's impulses wake its bodies
    context.bodies[manifold.bodyB].wake();
    for (int p = 0; p < manifold.pointCount; ++p) {
      states_.push_back(preparePoint(context, m, p));
    }
  }
  for (PointState& state : states_) {
    state.contactVelocity = contactVelocityNow(state);
    Manifold& manifold = context.manifolds[state.manifold];
    state.friction = carriedFriction(state, manifold.friction);
    manifold.points[state.point].friction = state.friction;  // reported even if nothing is resolved
  }
  preparePairs();
  indexContactsByBody(context);
}

// The velocity phase works on copies of what its impulses touch, one per body (static bodies
// have zero inverse mass and inertia); positions do not move until the penetration phase.
void MicroCollisionSolver::loadSolverBodies(const StepContext& context) {
  impulse2d::loadSolverBodies(context.bodies, solverBodies_);
}

void MicroCollisionSolver::storeVelocities(const StepContext& context) const {
  for (int i = 0; i < static_cast<int>(context.bodies.size()); ++i) storeVelocity(context, i);
}

void MicroCollisionSolver::storeVelocity(const StepContext& context, int body) const {
  Body& target = context.bodies[body];
  if (target.isStatic()) return;
  target.velocity = solverBodies_[body].velocity;
  target.angularVelocity = solverBodies_[body].angularVelocity;
}

// The (normal, tangent) relative velocity at the point, B's material minus A's.
Vec2 MicroCollisionSolver::contactVelocityNow(const PointState& state) const {
  const SolverBody& a = solverBodies_[state.bodyA];
  const SolverBody& b = solverBodies_[state.bodyB];
  const Vec2 relative = b.velocity + cross(b.angularVelocity, state.armB) - a.velocity -
                        cross(a.angularVelocity, state.armA);
  return Vec2(relative.dot(state.normal), relative.dot(leftPerpendicular(state.normal)));
}

// The (normal, tangent) impulse at the point: +P to B, −P to A.
void MicroCollisionSolver::applyImpulse(const PointState& state, const Vec2& impulse) {
  const Vec2 P =
      normalPart(impulse) * state.normal + tangentPart(impulse) * leftPerpendicular(state.normal);
  applyPairImpulse(solverBodies_[state.bodyA], solverBodies_[state.bodyB], state.armA, state.armB,
                   P);
}

// One point's state before the solve; with warm starting, its last totals are applied at once.
MicroCollisionSolver::PointState MicroCollisionSolver::preparePoint(const StepContext& context,
                                                                    int manifoldIndex,
                                                                    int pointIndex) {
  Manifold& manifold = context.manifolds[manifoldIndex];
  ContactPoint& point = manifold.points[pointIndex];
  PointState state;
  state.manifold = manifoldIndex;
  state.point = pointIndex;
  state.bodyA = manifold.bodyA;
  state.bodyB = manifold.bodyB;
  state.normal = manifold.normal;
  state.armA = point.point - context.bodies[manifold.bodyA].position;
  state.armB = point.point - context.bodies[manifold.bodyB].position;
  state.restitution = manifold.restitution;
  state.anchorA = point.anchorA;
  state.anchorB = point.anchorB;
  state.contactMatrix = contactMatrix(context.bodies[manifold.bodyA],
                                      context.bodies[manifold.bodyB], point.point, manifold.normal);
  state.inverseContactMatrix =
      inverseOrZero(state.contactMatrix, settings_.singularMatrixTolerance);
  state.penetration = point.penetration;
  state.accelerationVelocity = accelerationVelocity(context, manifold);
  state.totalImpulse =
      warmStartTotals(manifold, point, bounced_.recalled(manifoldIndex, pointIndex));
  point.normalImpulse = normalPart(state.totalImpulse);
  point.tangentImpulse = tangentPart(state.totalImpulse);
  point.friction = FrictionState::None;
  if (normalPart(state.totalImpulse) > 0.0) applyImpulse(state, state.totalImpulse);
  return state;
}

// Warm starting: the (normal, tangent) totals the point ended the last step with, matched by
// feature id, kept inside the friction cone. A bounce is not resting weight: a point that bounced
// starts from zero, as does every point with warm starting off.
Vec2 MicroCollisionSolver::warmStartTotals(const Manifold& manifold, const ContactPoint& point,
                                           bool bouncedLastStep) const {
  if (!settings_.warmStarting || bouncedLastStep || point.normalImpulse <= 0.0) return Vec2::Zero();
  const double frictionLimit = settings_.friction ? manifold.friction * point.normalImpulse : 0.0;
  return Vec2(point.normalImpulse, std::clamp(point.tangentImpulse, -frictionLimit, frictionLimit));
}

// The friction state a warm-started point starts the step in, from the totals it carries, so
// that worst first counts its slip (severity): inside the cone static friction holds and any slip
// needs resolving; on the cone, dynamic friction that opposes the slip is settled, and friction
// along the slip is not. Starting every point with no state left a disc that landed on a slope
// with its landing's friction total step after step, its normal need met by the carried total
// and its slip never looked at: it slipped ever faster (docs/friction.md).
FrictionState MicroCollisionSolver::carriedFriction(const PointState& state,
                                                    double friction) const {
  if (!settings_.friction || friction <= 0.0) return FrictionState::None;
  const FrictionState carried = frictionStateOf(normalPart(state.totalImpulse),
                                                tangentPart(state.totalImpulse), friction, 0.0);
  if (carried != FrictionState::Dynamic) return carried;
  const bool opposesSlip =
      tangentPart(state.totalImpulse) * tangentPart(state.contactVelocity) < 0.0;
  return opposesSlip ? FrictionState::Dynamic : FrictionState::Static;
}

// Lists, for every body, the contact points it takes part in (compressed rows), so an impulse
// updates only the contacts that share a body with it.
void MicroCollisionSolver::indexContactsByBody(const StepContext& context) {
  const int bodyCount = static_cast<int>(context.bodies.size());
  contactsOfBodyStart_.assign(bodyCount + 1, 0);
  for (const PointState& state : states_) {
    const Manifold& manifold = context.manifolds[state.manifold];
    ++contactsOfBodyStart_[manifold.bodyA + 1];
    ++contactsOfBodyStart_[manifold.bodyB + 1];
  }
  for (int i = 0; i < bodyCount; ++i) contactsOfBodyStart_[i + 1] += contactsOfBodyStart_[i];
  contactsOfBody_.resize(contactsOfBodyStart_[bodyCount]);
  std::vector<int>& next = contactsOfBodyStart_;
  for (int s = 0; s < static_cast<int>(states_.size()); ++s) {
    const Manifold& manifold = context.manifolds[states_[s].manifold];
    contactsOfBody_[next[manifold.bodyA]++] = s;
    contactsOfBody_[next[manifold.bodyB]++] = s;
  }
  for (int i = bodyCount; i > 0; --i) next[i] = next[i - 1];
  next[0] = 0;
}

// Lowering the restitution: a contact closing slower than the velocity limit does not bounce.
double MicroCollisionSolver::appliedRestitution(const PointState& state,
                                                double closingSpeed) const {
  if (settings_.lowerRestitutionAtLowSpeed && closingSpeed < settings_.restitutionThreshold) {
    return 0.0;
  }
  return state.restitution;
}

// Removing accelerative velocity: vacc, the separating velocity the last update's accelerations
// built up along the normal. Zero when the fix is switched off.
double MicroCollisionSolver::accelerationVelocity(const StepContext& context,
                                                  const Manifold& manifold) const {
  if (!settings_.removeAccelerationVelocity) return 0.0;
  const Vec2 relativeAcceleration = context.bodies[manifold.bodyB].lastAcceleration -
                                    context.bodies[manifold.bodyA].lastAcceleration;
  return context.dt * relativeAcceleration.dot(manifold.normal);
}

// The separating velocity a point wants: the bounce −c·(vs − vacc) on its closing velocity *now*,
// as in Millington's resolver, so an impulse at a neighbour that changes vs changes the bounce and
// a collision passes along a row of touching bodies. A point that has bounced bounces again only
// if a neighbour's impulse drives it closing once more (two balls striking a row send two out).
// Without a bounce, a contact with a speculative gap may close it within the step, and no more; a
// touching one should stop closing.
double MicroCollisionSolver::targetNormalVelocity(const PointState& state) const {
  const double separatingVelocity = normalPart(state.contactVelocity);
  if (!state.bounced || separatingVelocity < 0.0) {
    const double restitution = appliedRestitution(state, -separatingVelocity);
    const double bounce = -restitution * (separatingVelocity - state.accelerationVelocity);
    if (bounce > settings_.velocityEpsilon) return bounce;
  }
  return settings_.speculativeGaps ? std::min(0.0, state.penetration / dt_) : 0.0;
}

// A point whose target is a bounce: its first in this step, or another once closing again.
bool MicroCollisionSolver::toBounce(const PointState& state) const {
  return targetNormalVelocity(state) > 0.0;
}

// The velocity change a contact point wants. Along the normal, the lecture's
// Δv = −vs − c·(vs − vacc), i.e. the target minus the separating velocity, while the contact
// touches, or (speculative gaps) its gap would close within the step, or (impulse totals) this
// update already pushes it. Along the tangent, all the slip. A point that has bounced never has
// its bounce taken back by a later impulse at a neighbour: it only gains impulse.
Vec2 MicroCollisionSolver::desiredVelocityChange(const PointState& state) const {
  const double separatingVelocity = normalPart(state.contactVelocity);
  double normalChange = engaged(state) ? targetNormalVelocity(state) - separatingVelocity : 0.0;
  if (state.bounced) normalChange = std::max(0.0, normalChange);
  return Vec2(normalChange, -tangentPart(state.contactVelocity));
}

// A point the normal rule applies to: it touches, or (speculative gaps) its gap would close within
// the step, both to within touchingTolerance, or (impulse totals) this update already pushes it.
// The tolerance keeps round-off from parting the two corners of a face that falls flat onto
// another and just closes its gap in the step: one engaged alone, resolved alone, would spin it.
bool MicroCollisionSolver::engaged(const PointState& state) const {
  const double separatingVelocity = normalPart(state.contactVelocity);
  const bool gapCloses = settings_.speculativeGaps &&
                         separatingVelocity * dt_ < state.penetration + settings_.touchingTolerance;
  const bool pressed = pointTotals() && normalPart(state.totalImpulse) > 0.0;
  return state.penetration >= -settings_.touchingTolerance || gapCloses || pressed;
}

// How badly a point needs resolving. A point not yet pushed in this update counts only its
// normal need, as in the lecture; a point this update already pushes also counts being pushed
// too hard and, while its friction is static, the slip left by impulses at its neighbours — so
// the impulses of one update converge to resting contact instead of leaving a box rocking.
double MicroCollisionSolver::severity(const PointState& state) const {
  const Vec2 desired = desiredVelocityChange(state);
  if (!settings_.severityCountsPushedPoints || normalPart(state.totalImpulse) <= 0.0) {
    return normalPart(desired);
  }
  const double slip =
      state.friction == FrictionState::Static ? std::abs(tangentPart(desired)) : 0.0;
  return std::max(std::abs(normalPart(desired)), slip);
}

int MicroCollisionSolver::worstVelocityPoint() {
  return queue_.empty() ? -1 : queue_.worst();
}

// The total impulse (normal, tangent) at a point after this micro-collision, from the totals
// `before` it: the inverse contact matrix turns the desired velocity change into an impulse.
// Beyond the limit of static friction, dynamic friction: the tangent total is exactly μ times
// the normal total, in the direction of the trial tangent total (the impulse static friction
// would need), and the normal part is recomputed so the normal target still holds. Taking the
// direction from the slip left after earlier impulses instead turns friction the wrong way on a
// slope at rest, step after step. The totals can push but never pull. From zero totals this is
// the lecture's rule.
Vec2 MicroCollisionSolver::newTotalImpulse(const PointState& state, const Vec2& before,
                                           double friction, const Vec2& desiredChange,
                                           FrictionState& frictionState) const {
  if (separatesPastItsBounce(state)) {
    return frictionAlone(state, before, friction, desiredChange, frictionState);
  }
  const Mat2& matrix = state.contactMatrix;
  const double frictionlessNormal =
      std::max(0.0, normalPart(before) + normalPart(desiredChange) /
                                             matrix(ContactAxis::Normal, ContactAxis::Normal));
  frictionState = FrictionState::None;
  if (!settings_.friction || friction <= 0.0) return Vec2(frictionlessNormal, 0.0);

  const Vec2 trial = before + state.inverseContactMatrix * desiredChange;
  if (normalPart(trial) > 0.0 && std::abs(tangentPart(trial)) <= friction * normalPart(trial)) {
    frictionState = FrictionState::Static;
    return trial;
  }
  const double direction = std::copysign(1.0, tangentPart(trial));
  const double coupling = matrix(ContactAxis::Normal, ContactAxis::Normal) +
                          matrix(ContactAxis::Normal, ContactAxis::Tangent) * direction * friction;
  if (coupling <= settings_.singularMatrixTolerance) return Vec2(frictionlessNormal, 0.0);
  const double normalChange =
      (normalPart(desiredChange) -
       matrix(ContactAxis::Normal, ContactAxis::Tangent) *
           (direction * friction * normalPart(before) - tangentPart(before))) /
      coupling;
  const double normal = std::max(0.0, normalPart(before) + normalChange);
  frictionState = FrictionState::Dynamic;
  return Vec2(normal, direction * friction * normal);
}

// A point that has bounced and now separates faster than its bounce asks nothing along the normal,
// and its bounce is never taken back: friction acts there alone, its normal total left as it is.
// Holding its normal velocity instead (a normal change of 0) pushes it with whatever normal
// impulse stopping the slip takes, and two such points of one face, each stopping the slip the
// other's impulse left, pushed each other apart without end, gaining energy in an impact.
bool MicroCollisionSolver::separatesPastItsBounce(const PointState& state) const {
  return state.bounced && normalPart(state.contactVelocity) >
                              targetNormalVelocity(state) + settings_.velocityEpsilon;
}

// The friction total that stops the slip, within μ times the normal total `before`, the normal
// total unchanged.
Vec2 MicroCollisionSolver::frictionAlone(const PointState& state, const Vec2& before,
                                         double friction, const Vec2& desiredChange,
                                         FrictionState& frictionState) const {
  const double limit = settings_.friction ? friction * normalPart(before) : 0.0;
  const double wanted =
      tangentPart(before) +
      tangentPart(desiredChange) / state.contactMatrix(ContactAxis::Tangent, ContactAxis::Tangent);
  frictionState = std::abs(wanted) <= limit ? FrictionState::Static : FrictionState::Dynamic;
  if (limit <= 0.0) frictionState = FrictionState::None;
  return Vec2(normalPart(before), std::clamp(wanted, -limit, limit));
}

// One micro-collision: the impulse that takes the point from its totals to the new ones. Without
// impulse totals each impulse is computed alone, from zero, as the lecture does.
void MicroCollisionSolver::applyVelocityChange(const StepContext& context, int index,
                                               int iteration) {
  PointState& state = states_[index];
  if (state.pair >= 0 && applyPairChange(context, state, iteration)) return;
  Manifold& manifold = context.manifolds[state.manifold];
  ContactPoint& point = manifold.points[state.point];
  const Vec2 desired = desiredVelocityChange(state);
  const bool bounces = toBounce(state);
  const Vec2 before = pointTotals() ? state.totalImpulse : Vec2::Zero();
  const Vec2 impulse =
      newTotalImpulse(state, before, manifold.friction, desired, state.friction) - before;
  state.totalImpulse += impulse;
  state.bounced = state.bounced || bounces;
  point.normalImpulse = normalPart(state.totalImpulse);
  point.tangentImpulse = tangentPart(state.totalImpulse);
  point.friction = state.friction;
  applyImpulse(state, impulse);
  afterImpulse(context, state);
  context.report({SolverEvent::Phase::Velocity, iteration, state.manifold, state.point,
                  normalPart(desired), normalPart(impulse), tangentPart(impulse)});
}

// After an impulse at a point: the contact velocities of every point sharing one of its bodies
// (and their places in the queue), and in a traced step the bodies as the impulse left them.
void MicroCollisionSolver::afterImpulse(const StepContext& context, const PointState& state) {
  refreshContactVelocities(context, state.bodyA, -1);
  refreshContactVelocities(context, state.bodyB,
                           context.bodies[state.bodyA].isStatic() ? -1 : state.bodyA);
  if (context.observer) {
    storeVelocity(context, state.bodyA);
    storeVelocity(context, state.bodyB);
  }
}

// The points of one body, but for those it shares with `refreshedBody` (whose points were just
// refreshed, −1 for none): the point of an impulse is listed under both its bodies.
void MicroCollisionSolver::refreshContactVelocities(const StepContext& context, int bodyIndex,
                                                    int refreshedBody) {
  if (context.bodies[bodyIndex].isStatic()) return;
  for (int i = contactsOfBodyStart_[bodyIndex]; i < contactsOfBodyStart_[bodyIndex + 1]; ++i) {
    PointState& state = states_[contactsOfBody_[i]];
    if (state.bodyA == refreshedBody || state.bodyB == refreshedBody) continue;
    state.contactVelocity = contactVelocityNow(state);
    queue_.update(contactsOfBody_[i], severity(state));
  }
}

// ---- penetration resolution ----

void MicroCollisionSolver::solvePositions(const StepContext& context) {
  loadPoses(context);
  movePoints_.clear();
  queueKeys_.clear();
  for (const PointState& state : states_) {
    MovePoint point{state.bodyA, state.bodyB, 0.0, state.normal, state.anchorA, state.anchorB};
    point.penetration = penetrationNow(point);
    movePoints_.push_back(point);
    queueKeys_.push_back(point.penetration);
  }
  queue_.reset(queueKeys_, settings_.positionEpsilon);
  const int maxIterations =
      settings_.positionIterationsPerContact * static_cast<int>(states_.size());
  for (int iteration = 0; iteration < maxIterations; ++iteration) {
    const int worst = worstPenetration();
    if (worst < 0) break;
    resolvePenetration(context, worst, iteration);
  }
  storePoses(context);
}

// The penetration phase moves copies of the bodies' poses, with the rotation kept as cosine and
// sine; the bodies get them (and their caches) once, at the end.
void MicroCollisionSolver::loadPoses(const StepContext& context) {
  poses_.resize(context.bodies.size());
  for (int i = 0; i < static_cast<int>(context.bodies.size()); ++i) {
    const Body& body = context.bodies[i];
    poses_[i] = {body.position,
                 body.angle,
                 body.rotation(0, 0),
                 body.rotation(1, 0),
                 body.inverseMass,
                 body.inverseInertia,
                 !body.isStatic(),
                 false,
                 !surfaceTurnsWithShape(body.shape)};
  }
}

void MicroCollisionSolver::storePoses(const StepContext& context) {
  for (int i = 0; i < static_cast<int>(context.bodies.size()); ++i) storePose(context, i);
}

void MicroCollisionSolver::storePose(const StepContext& context, int body) {
  Pose& pose = poses_[body];
  if (!pose.moved) return;
  Body& target = context.bodies[body];
  target.position = pose.position;
  target.angle = pose.angle;
  target.updateCache();
  pose.moved = false;
}

// A point's normal at the poses now: between two circles the line of their centres (their contact
// moves round both as they roll or slide on each other, as in Box2D 2.4's position solver; read
// along the normal found, two circles sliding past each other in a heap are pushed apart along a
// stale line and rain's heap falls through its floor), otherwise the normal found.
Vec2 MicroCollisionSolver::normalNow(const MovePoint& point) const {
  const Pose& a = poses_[point.bodyA];
  const Pose& b = poses_[point.bodyB];
  return a.round && b.round ? directionOr(a.position, b.position, point.normal) : point.normal;
}

// A point's anchors on A and on B at the poses now, given its normal now (a circle's anchor
// follows its centre alone, Pose::anchorNow).
std::array<Vec2, 2> MicroCollisionSolver::anchorsNow(const MovePoint& point,
                                                     const Vec2& normal) const {
  return {poses_[point.bodyA].anchorNow(point.anchorA, normal),
          poses_[point.bodyB].anchorNow(point.anchorB, -normal)};
}

// A point's penetration at the poses now: the anchor on A minus the anchor on B, along the normal
// now.
double MicroCollisionSolver::penetrationNow(const MovePoint& point) const {
  const Vec2 normal = normalNow(point);
  const std::array<Vec2, 2> anchors = anchorsNow(point, normal);
  return (anchors[0] - anchors[1]).dot(normal);
}

int MicroCollisionSolver::worstPenetration() {
  return queue_.empty() ? -1 : queue_.worst();
}

// The deepest point, with the other point of its manifold when pair moves are on and the pair
// can be moved together; alone otherwise, as the lecture does.
void MicroCollisionSolver::resolvePenetration(const StepContext& context, int index,
                                              int iteration) {
  const int partner = settings_.blockMoves ? otherPoint(index) : -1;
  if (partner >= 0 && resolvePair(context, index, partner, iteration)) return;
  resolvePoint(context, index, iteration);
}

// The contact point now: contactPointBetween (contact.h) the anchors at the current poses, given
// the point's normal now (normalNow).
Vec2 MicroCollisionSolver::contactPointNow(const MovePoint& point, const Vec2& normal) const {
  const std::array<Vec2, 2> anchors = anchorsNow(point, normal);
  return contactPointBetween(anchors[0], anchors[1]);
}

// After a move at a point: the penetrations of every point sharing one of its bodies (and their
// places in the queue), and in a traced step the bodies as the move left them.
void MicroCollisionSolver::afterMove(const StepContext& context, const MovePoint& point) {
  refreshPenetrations(point.bodyA, -1);
  refreshPenetrations(point.bodyB, poses_[point.bodyA].movable ? point.bodyA : -1);
  if (context.observer) {
    storePose(context, point.bodyA);
    storePose(context, point.bodyB);
  }
}

// One point alone: Millington's move.
void MicroCollisionSolver::resolvePoint(const StepContext& context, int index, int iteration) {
  const MovePoint& point = movePoints_[index];
  Pose& a = poses_[point.bodyA];
  Pose& b = poses_[point.bodyB];
  const Vec2 normal = normalNow(point);
  const Vec2 at = contactPointNow(point, normal);
  const Vec2 armA = at - a.position;
  const Vec2 armB = at - b.position;
  const double inertiaAtContact = inverseEffectiveMass(a, b, armA, armB, normal);
  const double penetration = point.penetration;
  moveBody(a, armA, -normal, penetration, inertiaAtContact);
  moveBody(b, armB, normal, penetration, inertiaAtContact);
  afterMove(context, point);
  context.report({SolverEvent::Phase::Position, iteration, states_[index].manifold,
                  states_[index].point, penetration, 0.0, 0.0});
}

// Moves one body its share of the penetration along direction: linear and angular shares in
// proportion to its inverse mass and its angular inertia at the contact, the angular share
// limited to angularMoveLimit·|arm| (large turns of small bodies look wrong) with the rest moved
// linearly.
void MicroCollisionSolver::moveBody(Pose& body, const Vec2& arm, const Vec2& direction,
                                    double penetration, double totalInertia) const {
  if (!body.movable || totalInertia <= 0.0) return;
  const double torqueArm = cross(arm, direction);
  const double angularInertia = body.inverseInertia * torqueArm * torqueArm;
  double linearMove = penetration * body.inverseMass / totalInertia;
  double angularMove = penetration * angularInertia / totalInertia;
  const double angularLimit = settings_.angularMoveLimit * arm.norm();
  if (std::abs(angularMove) > angularLimit) {
    const double totalMove = linearMove + angularMove;
    angularMove = std::clamp(angularMove, -angularLimit, angularLimit);
    linearMove = totalMove - angularMove;
  }
  body.position += linearMove * direction;
  if (angularInertia > 0.0) {
    body.turnBy(body.inverseInertia * torqueArm * angularMove / angularInertia);
  }
  body.moved = true;
}

// The points of one body, but for those it shares with `refreshedBody` (as in
// refreshContactVelocities).
void MicroCollisionSolver::refreshPenetrations(int bodyIndex, int refreshedBody) {
  if (!poses_[bodyIndex].movable) return;
  for (int i = contactsOfBodyStart_[bodyIndex]; i < contactsOfBodyStart_[bodyIndex + 1]; ++i) {
    MovePoint& point = movePoints_[contactsOfBody_[i]];
    if (point.bodyA == refreshedBody || point.bodyB == refreshedBody) continue;
    point.penetration = penetrationNow(point);
    queue_.update(contactsOfBody_[i], point.penetration);
  }
}

}  // namespace impulse2d
