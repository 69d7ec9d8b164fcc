// The micro-collision resolver of lecture 3.6. Velocity resolution: repeatedly take the contact
// whose desired velocity change is largest, apply the one impulse that achieves it (with static
// or dynamic friction), and update the contact velocities of every contact sharing a body.
// Penetration resolution: repeatedly take the deepest contact and move its two bodies apart,
// split between linear and angular motion in proportion to their inertia at the contact.
#include "impulse2d/solvers/micro_collision.h"

#include <algorithm>
#include <cmath>

#include "impulse2d/solvers/contact_math.h"

namespace impulse2d {
namespace {

/// The penetration of a manifold's point as the bodies stand now.
double penetrationNow(const StepContext& context, int manifoldIndex, int point) {
  const Manifold& manifold = context.manifolds[manifoldIndex];
  return currentPenetration(context.bodies[manifold.bodyA], context.bodies[manifold.bodyB],
                            manifold, point);
}

}  // namespace
// ---- velocity resolution ----

void MicroCollisionSolver::solveVelocities(const StepContext& context) {
  prepare(context);
  queueKeys_.clear();
  for (const PointState& state : states_) queueKeys_.push_back(severity(state));
  queue_.reset(queueKeys_);
  const int maxIterations = settings_.velocityIterationsPerContact * int(states_.size());
  report_ = SolveReport{};
  while (report_.iterations < maxIterations) {
    const int worst = worstVelocityPoint();
    if (worst < 0) break;
    applyVelocityChange(context, worst, report_.iterations);
    ++report_.iterations;
  }
  const int remaining = worstVelocityPoint();
  report_.residual = remaining < 0 ? 0.0 : severity(states_[remaining]);
  report_.converged = remaining < 0;
}

void MicroCollisionSolver::prepare(const StepContext& context) {
  dt_ = context.dt;
  states_.clear();
  for (int m = 0; m < int(context.manifolds.size()); ++m) {
    Manifold& manifold = context.manifolds[m];
    const Body& a = context.bodies[manifold.bodyA];
    const Body& b = context.bodies[manifold.bodyB];
    for (int p = 0; p < manifold.pointCount; ++p) {
      ContactPoint& point = manifold.points[p];
      point.normalImpulse = 0.0;
      point.tangentImpulse = 0.0;
      point.friction = FrictionState::None;
      PointState state;
      state.manifold = m;
      state.point = p;
      state.contactMatrix = contactMatrix(a, b, point.point, manifold.normal);
      state.inverseContactMatrix =
          inverseOrZero(state.contactMatrix, settings_.singularMatrixTolerance);
      state.contactVelocity = contactVelocity(a, b, point.point, manifold.normal);
      state.penetration = point.penetration;
      const double separatingVelocity = state.contactVelocity.x();
      const double restitution = appliedRestitution(manifold, -separatingVelocity);
      const double bounce = std::max(
          0.0, -restitution * (separatingVelocity - accelerationVelocity(context, manifold)));
      // Without a bounce, a contact with a gap may close it within the step, and no more.
      state.targetNormalVelocity =
          bounce > 0.0 ? bounce : std::min(0.0, point.penetration / context.dt);
      states_.push_back(state);
    }
  }
  indexContactsByBody(context);
}

// Lists, for every body, the contact points it takes part in (compressed rows), so an impulse
// updates only the contacts that share a body with it.
void MicroCollisionSolver::indexContactsByBody(const StepContext& context) {
  const int bodyCount = int(context.bodies.size());
  contactsOfBodyStart_.assign(bodyCount + 1, 0);
  for (const PointState& state : states_) {
    const Manifold& manifold = context.manifolds[state.manifold];
    ++contactsOfBodyStart_[manifold.bodyA + 1];
    ++contactsOfBodyStart_[manifold.bodyB + 1];
  }
  for (int i = 0; i < bodyCount; ++i) contactsOfBodyStart_[i + 1] += contactsOfBodyStart_[i];
  contactsOfBody_.resize(contactsOfBodyStart_[bodyCount]);
  std::vector<int>& next = contactsOfBodyStart_;
  for (int s = 0; s < int(states_.size()); ++s) {
    const Manifold& manifold = context.manifolds[states_[s].manifold];
    contactsOfBody_[next[manifold.bodyA]++] = s;
    contactsOfBody_[next[manifold.bodyB]++] = s;
  }
  for (int i = bodyCount; i > 0; --i) next[i] = next[i - 1];
  next[0] = 0;
}

// Lowering the restitution: a contact closing slower than the velocity limit does not bounce.
double MicroCollisionSolver::appliedRestitution(const Manifold& manifold,
                                                double closingSpeed) const {
  if (settings_.lowerRestitutionAtLowSpeed && closingSpeed < settings_.restitutionVelocityLimit) {
    return 0.0;
  }
  return manifold.restitution;
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

// The velocity change a contact point wants: along the normal, the bounce target minus the
// separating velocity while the contact penetrates or its gap would close within the step (a
// speculative contact, found one step early rather than one step deep); along the tangent, all
// the slip.
Vec2 MicroCollisionSolver::desiredVelocityChange(const PointState& state) const {
  const double separatingVelocity = state.contactVelocity.x();
  const bool closesThisStep = separatingVelocity * dt_ < state.penetration;
  const bool pressed = state.totalImpulse.x() > 0.0;
  const double normalChange = state.penetration >= 0.0 || closesThisStep || pressed
                                  ? state.targetNormalVelocity - separatingVelocity
                                  : 0.0;
  return Vec2(normalChange, -state.contactVelocity.y());
}

// How badly a point needs resolving. A point not yet pushed in this update counts only its
// normal need, as in the lecture; a point this update already pushes also counts being pushed
// too hard and, while its friction is static, the slip left by impulses at its neighbours — so
// the impulses of one update converge to resting contact instead of leaving a box rocking.
double MicroCollisionSolver::severity(const PointState& state) const {
  const Vec2 desired = desiredVelocityChange(state);
  if (state.totalImpulse.x() <= 0.0) return desired.x();
  const double slip = state.friction == FrictionState::Static ? std::abs(desired.y()) : 0.0;
  return std::max(std::abs(desired.x()), slip);
}

int MicroCollisionSolver::worstVelocityPoint() const {
  if (queue_.empty() || queue_.worstKey() <= settings_.velocityEpsilon) return -1;
  return queue_.worst();
}

// The total impulse (normal, tangent) at a point after this micro-collision: the inverse contact
// matrix turns the desired velocity change into an impulse. Beyond the limit of static friction,
// dynamic friction: the tangent total is exactly μ times the normal total, against the slip, and
// the normal part is recomputed so the normal target still holds. The totals of one update can
// push but never pull. For the first impulse at a point (totals zero) this is the lecture's rule.
Vec2 MicroCollisionSolver::newTotalImpulse(const PointState& state, double friction,
                                           const Vec2& desiredChange,
                                           FrictionState& frictionState) const {
  const Mat2& matrix = state.contactMatrix;
  const Vec2& total = state.totalImpulse;
  const double frictionlessNormal = std::max(0.0, total.x() + desiredChange.x() / matrix(0, 0));
  frictionState = FrictionState::None;
  if (!settings_.friction || friction <= 0.0) return Vec2(frictionlessNormal, 0.0);

  const Vec2 proposed = total + state.inverseContactMatrix * desiredChange;
  if (proposed.x() > 0.0 && std::abs(proposed.y()) <= friction * proposed.x()) {
    frictionState = FrictionState::Static;
    return proposed;
  }
  const double slip = -desiredChange.y();
  const double againstSlip =
      slip != 0.0 ? -std::copysign(1.0, slip) : std::copysign(1.0, proposed.y());
  const double coupling = matrix(0, 0) + matrix(0, 1) * againstSlip * friction;
  if (coupling <= settings_.singularMatrixTolerance) return Vec2(frictionlessNormal, 0.0);
  const double normalChange =
      (desiredChange.x() - matrix(0, 1) * (againstSlip * friction * total.x() - total.y())) /
      coupling;
  const double normal = std::max(0.0, total.x() + normalChange);
  frictionState = FrictionState::Dynamic;
  return Vec2(normal, againstSlip * friction * normal);
}

void MicroCollisionSolver::applyVelocityChange(const StepContext& context, int index,
                                               int iteration) {
  PointState& state = states_[index];
  Manifold& manifold = context.manifolds[state.manifold];
  ContactPoint& point = manifold.points[state.point];
  const Vec2 desired = desiredVelocityChange(state);
  const Vec2 total = newTotalImpulse(state, manifold.friction, desired, state.friction);
  const Vec2 impulse = total - state.totalImpulse;
  state.totalImpulse = total;
  point.normalImpulse = total.x();
  point.tangentImpulse = total.y();
  point.friction = state.friction;
  const Vec2 worldImpulse = impulse.x() * manifold.normal + impulse.y() * manifold.tangent();
  context.bodies[manifold.bodyA].applyImpulse(-worldImpulse, point.point);
  context.bodies[manifold.bodyB].applyImpulse(worldImpulse, point.point);
  refreshContactVelocities(context, manifold.bodyA);
  refreshContactVelocities(context, manifold.bodyB);
  context.report({SolverEvent::Phase::Velocity, iteration, state.manifold, state.point, desired.x(),
                  impulse.x(), impulse.y()});
}

void MicroCollisionSolver::refreshContactVelocities(const StepContext& context, int bodyIndex) {
  if (context.bodies[bodyIndex].isStatic()) return;
  for (int i = contactsOfBodyStart_[bodyIndex]; i < contactsOfBodyStart_[bodyIndex + 1]; ++i) {
    PointState& state = states_[contactsOfBody_[i]];
    const Manifold& manifold = context.manifolds[state.manifold];
    state.contactVelocity =
        contactVelocity(context.bodies[manifold.bodyA], context.bodies[manifold.bodyB],
                        manifold.points[state.point].point, manifold.normal);
    queue_.update(contactsOfBody_[i], severity(state));
  }
}

// ---- penetration resolution ----

void MicroCollisionSolver::solvePositions(const StepContext& context) {
  queueKeys_.clear();
  for (PointState& state : states_) {
    state.penetration = penetrationNow(context, state.manifold, state.point);
    queueKeys_.push_back(state.penetration);
  }
  queue_.reset(queueKeys_);
  const int maxIterations = settings_.positionIterationsPerContact * int(states_.size());
  for (int iteration = 0; iteration < maxIterations; ++iteration) {
    const int worst = worstPenetration();
    if (worst < 0) break;
    resolvePenetration(context, worst, iteration);
  }
}

int MicroCollisionSolver::worstPenetration() const {
  if (queue_.empty() || queue_.worstKey() <= settings_.positionEpsilon) return -1;
  return queue_.worst();
}

void MicroCollisionSolver::resolvePenetration(const StepContext& context, int index,
                                              int iteration) {
  const PointState& state = states_[index];
  const Manifold& manifold = context.manifolds[state.manifold];
  Body& a = context.bodies[manifold.bodyA];
  Body& b = context.bodies[manifold.bodyB];
  const Vec2 point = currentContactPoint(a, b, manifold.points[state.point]);
  const Vec2 armA = point - a.position;
  const Vec2 armB = point - b.position;
  const Mat2 inertiaAtContact = contactMatrix(a, b, point, manifold.normal);
  const double penetration = state.penetration;
  moveBody(a, armA, -manifold.normal, penetration, inertiaAtContact(0, 0));
  moveBody(b, armB, manifold.normal, penetration, inertiaAtContact(0, 0));
  refreshPenetrations(context, manifold.bodyA);
  refreshPenetrations(context, manifold.bodyB);
  context.report({SolverEvent::Phase::Position, iteration, state.manifold, state.point, penetration,
                  0.0, 0.0});
}

// Moves one body its share of the penetration along direction: linear and angular shares in
// proportion to its inverse mass and its angular inertia at the contact, the angular share
// limited to angularMoveLimit·|arm| (large turns of small bodies look wrong) with the rest moved
// linearly.
void MicroCollisionSolver::moveBody(Body& body, const Vec2& arm, const Vec2& direction,
                                    double penetration, double totalInertia) const {
  if (body.isStatic() || totalInertia <= 0.0) return;
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
    body.angle += body.inverseInertia * torqueArm * angularMove / angularInertia;
  }
  body.updateCache();
}

void MicroCollisionSolver::refreshPenetrations(const StepContext& context, int bodyIndex) {
  if (context.bodies[bodyIndex].isStatic()) return;
  for (int i = contactsOfBodyStart_[bodyIndex]; i < contactsOfBodyStart_[bodyIndex + 1]; ++i) {
    PointState& state = states_[contactsOfBody_[i]];
    state.penetration = penetrationNow(context, state.manifold, state.point);
    queue_.update(contactsOfBody_[i], state.penetration);
  }
}

}  // namespace impulse2d
