// Sequential impulses: PreStep (arms, masses, targets, warm start), then sweeps that solve one
// contact at a time — normal impulses, then friction — clamping the accumulated totals.
#include "impulse2d/solvers/sequential_impulses.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "impulse2d/solvers/contact_math.h"
#include "impulse2d/solvers/position_correction.h"
#include "impulse2d/solvers/two_point_block.h"

namespace impulse2d {

// Box2D-Lite's and 2.4's step: the sweeps on the velocities the forces gave, then the position
// pass once the bodies have moved. The contacts of pairs that moved little are kept as found
// (settings' recycling).
void SequentialImpulseSolver::step(StepStages& stages) {
  const bool recycles = settings_.recycling.rule != RecyclingRule::Off;
  stepVelocitiesThenPositions(stages, *this, {false, recycles ? &recycling_ : nullptr});
}

void SequentialImpulseSolver::solveVelocities(const StepContext& context) {
  prepare(context);
  warmStart();
  report_ = SolveReport{};
  for (int sweep = 0; sweep < settings_.velocityIterations; ++sweep) {
    report_.residual = 0.0;
    sweepChangeSquared_ = 0.0;
    for (const ManifoldState& manifold : manifoldStates_) {
      report_.residual = std::max(report_.residual, solveManifold(context, manifold, sweep));
    }
    report_.iterations = sweep + 1;
    if (converged()) break;
    if (pushes() && sweep + 1 < settings_.velocityIterations) pushOn(context, sweep);
  }
  storeResults(context);
}

// The conjugate gradient's push after a sweep (settings' conjugateGradient): β from this sweep's
// squared changes over the last's; from the first sweep, after a sweep that changed nothing, or
// when β > 1 the direction starts again as this sweep's changes and nothing is pushed. The last
// sweep of a step pushes nothing, so every total the step keeps was clamped by a sweep.
void SequentialImpulseSolver::pushOn(const StepContext& context, int sweep) {
  const double beta = sweep > 0 && lastChangeSquared_ > 0.0
                          ? sweepChangeSquared_ / lastChangeSquared_
                          : std::numeric_limits<double>::infinity();
  lastChangeSquared_ = sweepChangeSquared_;
  if (!(beta <= 1.0)) {
    for (PointDirection& direction : directions_) direction.restartFromChange();
    return;
  }
  for (const ManifoldState& manifold : manifoldStates_) {
    const Vec2 tangent = leftPerpendicular(manifold.normal);
    BodyPair bodies = loadBodies(manifold);
    std::array<PointImpulse, 2> pushed;
    for (int i = 0; i < manifold.pointCount; ++i) {
      PointState& point = states_[manifold.firstPoint + i];
      PointDirection& direction = directions_[manifold.firstPoint + i];
      pushed[i].normalImpulse = beta * direction.normal;
      pushed[i].tangentImpulse = beta * direction.tangent;
      point.normalImpulse += pushed[i].normalImpulse;
      point.tangentImpulse += pushed[i].tangentImpulse;
      bodies.applyNormalImpulse(point, manifold.normal, pushed[i].normalImpulse);
      bodies.applyTangentImpulse(point, tangent, pushed[i].tangentImpulse);
      direction.continueWith(pushed[i]);
    }
    storeBodies(manifold, bodies);
    if (context.observer) reportPoints(context, manifold, sweep, pushed, SolverEvent::Phase::Push);
  }
}

// Converged: the last sweep changed no impulse (normal or friction) by more than the settings'
// fraction of the largest normal total.
bool SequentialImpulseSolver::converged() const {
  if (settings_.convergedImpulseChange <= 0.0) return false;
  double largestTotal = 0.0;
  for (const PointState& point : states_)
    largestTotal = std::max(largestTotal, point.normalImpulse);
  return report_.residual <= settings_.convergedImpulseChange * largestTotal;
}

// PreStep: the masses from the unit-impulse response, and the target separating velocity from the
// closing velocity before any impulse of this step (so warm starting does not hide a bounce).
void SequentialImpulseSolver::prepare(const StepContext& context) {
  prepareBodies(context);
  states_.clear();
  manifoldStates_.clear();
  const bool warm = settings_.impulses == ImpulseAccumulation::WarmStarted;
  directions_.clear();
  lastChangeSquared_ = 0.0;
  for (int m = 0; m < static_cast<int>(context.manifolds.size()); ++m) {
    const Manifold& manifold = context.manifolds[m];
    Body& a = context.bodies[manifold.bodyA];
    Body& b = context.bodies[manifold.bodyB];
    a.wake();  // a contact's impulses wake its bodies, as Body::applyImpulse does
    b.wake();
    addManifoldState(context, m);
    for (int i = 0; i < manifold.pointCount; ++i) {
      const ContactPoint& point = manifold.points[i];
      PointState state;
      const Vec2 armA = point.point - a.position;
      const Vec2 armB = point.point - b.position;
      const Vec2 tangent = manifold.tangent();
      state.normalTorqueArmA = cross(armA, manifold.normal);
      state.normalTorqueArmB = cross(armB, manifold.normal);
      state.tangentTorqueArmA = cross(armA, tangent);
      state.tangentTorqueArmB = cross(armB, tangent);
      state.normalMass = 1.0 / unitImpulseResponse(a, b, point.point, manifold.normal);
      state.tangentMass = 1.0 / unitImpulseResponse(a, b, point.point, manifold.tangent());
      const double normalVelocity = impulse2d::relativeVelocity(a, b, point.point, manifold.normal);
      state.targetNormalVelocity = targetSeparatingVelocity(
          normalVelocity, point.penetration, manifold.restitution, context.dt, settings_.targets);
      state.normalImpulse = warm ? point.normalImpulse : 0.0;
      state.tangentImpulse = warm ? point.tangentImpulse : 0.0;
      states_.push_back(state);
      if (pushes()) directions_.emplace_back();
    }
  }
}

// The solver bodies: copies of what the sweeps touch, one per body (static ones have zero
// inverse mass and inertia, so impulses leave them still).
void SequentialImpulseSolver::prepareBodies(const StepContext& context) {
  loadSolverBodies(context.bodies, solverBodies_);
}

// The block solve needs running totals to clamp, so it goes with accumulated impulses.
void SequentialImpulseSolver::addManifoldState(const StepContext& context, int manifold) {
  const Manifold& contact = context.manifolds[manifold];
  ManifoldState state;
  state.load(contact, manifold);
  state.firstPoint = static_cast<int>(states_.size());
  if (settings_.block.enabled && accumulated() && contact.pointCount == 2) {
    state.normalCoupling =
        normalCouplingMatrix(context.bodies[contact.bodyA], context.bodies[contact.bodyB],
                             contact.normal, contact.points[0].point, contact.points[1].point);
    state.block = isWellConditioned(state.normalCoupling, settings_.block.conditionLimit);
    state.inverseCoupling = inverseOrZero(state.normalCoupling, 0.0);
  }
  manifoldStates_.push_back(state);
}

// Warm starting: the last step's totals (carried over by feature id) are applied up front, so the
// sweeps only correct what changed. Without it the totals start from zero (set in prepare).
void SequentialImpulseSolver::warmStart() {
  if (settings_.impulses != ImpulseAccumulation::WarmStarted) return;
  for (const ManifoldState& manifold : manifoldStates_) {
    const Vec2 tangent = leftPerpendicular(manifold.normal);
    BodyPair bodies = loadBodies(manifold);
    for (int i = 0; i < manifold.pointCount; ++i) {
      const PointState& point = states_[manifold.firstPoint + i];
      bodies.applyNormalImpulse(point, manifold.normal, point.normalImpulse);
      bodies.applyTangentImpulse(point, tangent, point.tangentImpulse);
    }
    storeBodies(manifold, bodies);
  }
}

// One contact in one sweep: the normal impulses of its points (together, or one at a time), then
// friction at each point. Returns the largest impulse change (normal or friction), the sweep's
// residual.
inline double SequentialImpulseSolver::solveManifold(const StepContext& context,
                                                     const ManifoldState& manifold, int sweep) {
  std::array<PointImpulse, 2> impulses;
  BodyPair bodies = loadBodies(manifold);
  if (settings_.frictionFirst) solveFrictions(manifold, bodies, impulses);
  if (manifold.block) {
    solveNormalsTogether(manifold, bodies, impulses);
  } else {
    PointState* points = &states_[manifold.firstPoint];
    for (int i = 0; i < manifold.pointCount; ++i) {
      solveNormal(manifold, points[i], bodies, impulses[i]);
    }
  }
  if (!settings_.frictionFirst) solveFrictions(manifold, bodies, impulses);
  storeBodies(manifold, bodies);
  if (context.observer)
    reportPoints(context, manifold, sweep, impulses, SolverEvent::Phase::Velocity);
  double largestChange = 0.0;
  for (int i = 0; i < manifold.pointCount; ++i) {
    if (pushes()) {
      directions_[manifold.firstPoint + i].change = impulses[i];
      sweepChangeSquared_ += impulses[i].normalImpulse * impulses[i].normalImpulse +
                             impulses[i].tangentImpulse * impulses[i].tangentImpulse;
    }
    largestChange = std::max(
        {largestChange, std::abs(impulses[i].normalImpulse), std::abs(impulses[i].tangentImpulse)});
  }
  return largestChange;
}

// The text's step: the relative normal velocity, the change wanted to reach the target, and the
// impulse = normal mass × that change (clamped as accumulation says).
inline void SequentialImpulseSolver::solveNormal(const ManifoldState& manifold, PointState& point,
                                                 BodyPair& bodies, PointImpulse& impulse) {
  const double relativeNormalVelocity = bodies.relativeNormalVelocity(point, manifold.normal);
  impulse.desiredChange = point.targetNormalVelocity - relativeNormalVelocity;
  impulse.normalImpulse = normalImpulseChange(point, point.normalMass * impulse.desiredChange);
  bodies.applyNormalImpulse(point, manifold.normal, impulse.normalImpulse);
}

// Friction at each point of a contact, against the normal totals as they stand.
inline void SequentialImpulseSolver::solveFrictions(const ManifoldState& manifold, BodyPair& bodies,
                                                    std::array<PointImpulse, 2>& impulses) {
  PointState* points = &states_[manifold.firstPoint];
  for (int i = 0; i < manifold.pointCount; ++i) {
    PointImpulse& impulse = impulses[i];
    impulse.tangentImpulse = solveFriction(manifold, points[i], bodies, impulse.normalImpulse);
  }
}

// Both points of a flat contact at once: the new totals x solve the 2×2 complementarity problem
// K x + q ≥ 0 ⟂ x ≥ 0, with q the velocity error the totals would leave if they were zero. The
// two points' figures are built as whole vectors from scalars: filled in one element at a time,
// each vector would go through memory and stall the packed arithmetic that reads it back.
inline void SequentialImpulseSolver::solveNormalsTogether(const ManifoldState& manifold,
                                                          BodyPair& bodies,
                                                          std::array<PointImpulse, 2>& impulses) {
  PointState* points = &states_[manifold.firstPoint];
  const double error0 =
      bodies.relativeNormalVelocity(points[0], manifold.normal) - points[0].targetNormalVelocity;
  const double error1 =
      bodies.relativeNormalVelocity(points[1], manifold.normal) - points[1].targetNormalVelocity;
  impulses[0].desiredChange = -error0;
  impulses[1].desiredChange = -error1;
  const Vec2 totals(points[0].normalImpulse, points[1].normalImpulse);
  const Vec2 newTotals = solveTwoPointLcp(manifold.normalCoupling, manifold.inverseCoupling,
                                          Vec2(error0, error1) - manifold.normalCoupling * totals);
  for (int i = 0; i < 2; ++i) {
    impulses[i].normalImpulse = newTotals(i) - totals(i);
    points[i].normalImpulse = newTotals(i);
    bodies.applyNormalImpulse(points[i], manifold.normal, newTotals(i) - totals(i));
  }
}

// Friction the same way along the tangent: the impulse that stops the sliding, within Coulomb's
// limit. Returns the friction impulse applied.
inline double SequentialImpulseSolver::solveFriction(const ManifoldState& manifold,
                                                     PointState& point, BodyPair& bodies,
                                                     double normalImpulseThisSweep) {
  const Vec2 tangent = leftPerpendicular(manifold.normal);
  const double relativeTangentVelocity = bodies.relativeTangentVelocity(point, tangent);
  const double impulse = tangentImpulseChange(point, -point.tangentMass * relativeTangentVelocity,
                                              manifold.friction, normalImpulseThisSweep);
  bodies.applyTangentImpulse(point, tangent, impulse);
  return impulse;
}

// Accumulated impulses: the running total may only push (≥ 0); what is applied is the change of
// the total, so a later sweep can take back part of an earlier push. Without accumulation each
// impulse is clamped on its own and can never be taken back.
inline double SequentialImpulseSolver::normalImpulseChange(PointState& point,
                                                           double impulse) const {
  const double before = point.normalImpulse;
  if (accumulated()) {
    point.normalImpulse = std::max(before + impulse, 0.0);
  } else {
    point.normalImpulse = before + std::max(impulse, 0.0);
  }
  return point.normalImpulse - before;
}

// Coulomb's limit: the running friction total stays within ±μ × the running normal total; without
// accumulation each friction impulse is capped at μ × this sweep's normal impulse (the text's cap).
inline double SequentialImpulseSolver::tangentImpulseChange(PointState& point, double impulse,
                                                            double friction,
                                                            double normalImpulseThisSweep) const {
  const double before = point.tangentImpulse;
  if (accumulated()) {
    const double limit = friction * point.normalImpulse;
    point.tangentImpulse = std::clamp(before + impulse, -limit, limit);
  } else {
    const double limit = friction * std::max(normalImpulseThisSweep, 0.0);
    point.tangentImpulse = before + std::clamp(impulse, -limit, limit);
  }
  return point.tangentImpulse - before;
}

// The sweeps' results back where the world keeps them: velocities on the bodies, the totals (the
// next step's warm start) and the friction state on the manifolds' points.
void SequentialImpulseSolver::storeResults(const StepContext& context) const {
  for (int i = 0; i < static_cast<int>(context.bodies.size()); ++i) {
    Body& body = context.bodies[i];
    if (body.isStatic()) continue;
    body.velocity = solverBodies_[i].velocity;
    body.angularVelocity = solverBodies_[i].angularVelocity;
  }
  for (const ManifoldState& state : manifoldStates_) {
    Manifold& manifold = context.manifolds[state.manifold];
    for (int i = 0; i < state.pointCount; ++i) {
      const PointState& solved = states_[state.firstPoint + i];
      ContactPoint& point = manifold.points[i];
      point.normalImpulse = solved.normalImpulse;
      point.tangentImpulse = solved.tangentImpulse;
      point.friction =
          frictionStateOf(point.normalImpulse, point.tangentImpulse, manifold.friction, 0.0);
    }
  }
}

// A traced step shows the bodies and manifolds as they are after the contact's solve, so the
// results are stored before its points are reported; an untraced step stores them once, after
// the sweeps.
void SequentialImpulseSolver::reportPoints(const StepContext& context,
                                           const ManifoldState& manifold, int sweep,
                                           const std::array<PointImpulse, 2>& impulses,
                                           SolverEvent::Phase phase) const {
  storeResults(context);
  for (int i = 0; i < manifold.pointCount; ++i) {
    const PointImpulse& impulse = impulses[i];
    context.report({phase, sweep, manifold.manifold, i, impulse.desiredChange,
                    impulse.normalImpulse, impulse.tangentImpulse});
  }
}

void SequentialImpulseSolver::solvePositions(const StepContext& context) {
  correctPositions(context, settings_.positionPass, settings_.targets.allowedPenetration,
                   settings_.block.conditionLimit);
}

}  // namespace impulse2d
