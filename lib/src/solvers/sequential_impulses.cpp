// Sequential impulses: PreStep (masses, targets, warm start), then sweeps that solve one contact
// at a time — normal impulses, then friction — clamping the accumulated totals.
#include "impulse2d/solvers/sequential_impulses.h"

#include <algorithm>
#include <cmath>

#include "impulse2d/solvers/contact_math.h"
#include "impulse2d/solvers/position_correction.h"
#include "impulse2d/solvers/two_point_block.h"

namespace impulse2d {

void SequentialImpulseSolver::solveVelocities(const StepContext& context) {
  prepare(context);
  warmStart(context);
  report_ = SolveReport{};
  for (int sweep = 0; sweep < settings_.velocityIterations; ++sweep) {
    report_.residual = 0.0;
    for (const ManifoldState& manifold : manifoldStates_) {
      report_.residual = std::max(report_.residual, solveManifold(context, manifold, sweep));
    }
    report_.iterations = sweep + 1;
  }
  updateFrictionStates(context);
}

// PreStep: the masses from the unit-impulse response, and the target separating velocity from the
// closing velocity before any impulse of this step (so warm starting does not hide a bounce).
void SequentialImpulseSolver::prepare(const StepContext& context) {
  states_.clear();
  manifoldStates_.clear();
  for (size_t m = 0; m < context.manifolds.size(); ++m) {
    const Manifold& manifold = context.manifolds[m];
    const Body& a = context.bodies[static_cast<size_t>(manifold.bodyA)];
    const Body& b = context.bodies[static_cast<size_t>(manifold.bodyB)];
    addManifoldState(context, static_cast<int>(m), static_cast<int>(states_.size()));
    for (int i = 0; i < manifold.pointCount; ++i) {
      const ContactPoint& point = manifold.points[static_cast<size_t>(i)];
      PointState state;
      state.manifold = static_cast<int>(m);
      state.point = i;
      state.normalMass = 1.0 / unitImpulseResponse(a, b, point.point, manifold.normal);
      state.tangentMass = 1.0 / unitImpulseResponse(a, b, point.point, manifold.tangent());
      const double normalVelocity = relativeVelocity(a, b, point.point, manifold.normal);
      state.targetNormalVelocity = targetSeparatingVelocity(
          normalVelocity, point.penetration, manifold.restitution, context.dt, settings_.targets);
      states_.push_back(state);
    }
  }
}

// The block solve needs running totals to clamp, so it goes with accumulated impulses.
void SequentialImpulseSolver::addManifoldState(const StepContext& context, int manifold,
                                               int firstPoint) {
  const Manifold& contact = context.manifolds[static_cast<size_t>(manifold)];
  ManifoldState state;
  state.manifold = manifold;
  state.firstPoint = firstPoint;
  state.pointCount = contact.pointCount;
  if (settings_.block.enabled && settings_.accumulateImpulses && contact.pointCount == 2) {
    state.normalCoupling =
        normalCouplingMatrix(context.bodies[static_cast<size_t>(contact.bodyA)],
                             context.bodies[static_cast<size_t>(contact.bodyB)], contact.normal,
                             contact.points[0].point, contact.points[1].point);
    state.block = isWellConditioned(state.normalCoupling, settings_.block.conditionLimit);
  }
  manifoldStates_.push_back(state);
}

// Warm starting: the last step's totals (carried over by feature id) are applied up front, so the
// sweeps only correct what changed. Without it the totals start from zero.
void SequentialImpulseSolver::warmStart(const StepContext& context) const {
  const bool warm = settings_.warmStarting && settings_.accumulateImpulses;
  for (const PointState& state : states_) {
    Manifold& manifold = context.manifolds[static_cast<size_t>(state.manifold)];
    ContactPoint& point = manifold.points[static_cast<size_t>(state.point)];
    if (!warm) {
      point.normalImpulse = 0.0;
      point.tangentImpulse = 0.0;
      continue;
    }
    applyContactImpulse(context.bodies, manifold, state.point, point.normalImpulse,
                        point.tangentImpulse);
  }
}

// One contact in one sweep: the normal impulses of its points (together, or one at a time), then
// friction at each point. Returns the largest |normal impulse change|, the sweep's residual.
double SequentialImpulseSolver::solveManifold(const StepContext& context,
                                              const ManifoldState& manifold, int sweep) const {
  std::array<PointImpulse, 2> impulses;
  const auto stateOf = [&](int i) -> const PointState& {
    return states_[static_cast<size_t>(manifold.firstPoint + i)];
  };
  if (manifold.block) {
    solveNormalsTogether(context, manifold, impulses);
  } else {
    for (int i = 0; i < manifold.pointCount; ++i) impulses[i] = solveNormal(context, stateOf(i));
  }
  double largestChange = 0.0;
  for (int i = 0; i < manifold.pointCount; ++i) {
    PointImpulse& impulse = impulses[static_cast<size_t>(i)];
    impulse.tangentImpulse = solveFriction(context, stateOf(i), impulse.normalImpulse);
    largestChange = std::max(largestChange, std::abs(impulse.normalImpulse));
    context.report({SolverEvent::Phase::Velocity, sweep, manifold.manifold, i,
                    impulse.desiredChange, impulse.normalImpulse, impulse.tangentImpulse});
  }
  return largestChange;
}

// The text's step: the relative normal velocity, the change wanted to reach the target, and the
// impulse = normal mass × that change (clamped as accumulation says).
SequentialImpulseSolver::PointImpulse SequentialImpulseSolver::solveNormal(
    const StepContext& context, const PointState& state) const {
  Manifold& manifold = context.manifolds[static_cast<size_t>(state.manifold)];
  ContactPoint& point = manifold.points[static_cast<size_t>(state.point)];
  const double relativeNormalVelocity = relativeVelocity(
      context.bodies[static_cast<size_t>(manifold.bodyA)],
      context.bodies[static_cast<size_t>(manifold.bodyB)], point.point, manifold.normal);
  PointImpulse impulse;
  impulse.desiredChange = state.targetNormalVelocity - relativeNormalVelocity;
  impulse.normalImpulse = normalImpulseChange(point, state.normalMass * impulse.desiredChange);
  applyContactImpulse(context.bodies, manifold, state.point, impulse.normalImpulse, 0.0);
  return impulse;
}

// Both points of a flat contact at once: the new totals x solve the 2×2 complementarity problem
// K x + q ≥ 0 ⟂ x ≥ 0, with q the velocity error the totals would leave if they were zero.
void SequentialImpulseSolver::solveNormalsTogether(const StepContext& context,
                                                   const ManifoldState& state,
                                                   std::array<PointImpulse, 2>& impulses) const {
  Manifold& manifold = context.manifolds[static_cast<size_t>(state.manifold)];
  const Body& a = context.bodies[static_cast<size_t>(manifold.bodyA)];
  const Body& b = context.bodies[static_cast<size_t>(manifold.bodyB)];
  Vec2 totals;
  Vec2 velocityError;
  for (int i = 0; i < 2; ++i) {
    const PointState& point = states_[static_cast<size_t>(state.firstPoint + i)];
    const Vec2& where = manifold.points[static_cast<size_t>(i)].point;
    totals(i) = manifold.points[static_cast<size_t>(i)].normalImpulse;
    velocityError(i) = relativeVelocity(a, b, where, manifold.normal) - point.targetNormalVelocity;
    impulses[static_cast<size_t>(i)].desiredChange = -velocityError(i);
  }
  const Vec2 newTotals =
      solveTwoPointLcp(state.normalCoupling, velocityError - state.normalCoupling * totals);
  for (int i = 0; i < 2; ++i) {
    impulses[static_cast<size_t>(i)].normalImpulse = newTotals(i) - totals(i);
    manifold.points[static_cast<size_t>(i)].normalImpulse = newTotals(i);
    applyContactImpulse(context.bodies, manifold, i, newTotals(i) - totals(i), 0.0);
  }
}

// Friction the same way along the tangent: the impulse that stops the sliding, within Coulomb's
// limit. Returns the friction impulse applied.
double SequentialImpulseSolver::solveFriction(const StepContext& context, const PointState& state,
                                              double normalImpulseThisSweep) const {
  Manifold& manifold = context.manifolds[static_cast<size_t>(state.manifold)];
  ContactPoint& point = manifold.points[static_cast<size_t>(state.point)];
  const double relativeTangentVelocity = relativeVelocity(
      context.bodies[static_cast<size_t>(manifold.bodyA)],
      context.bodies[static_cast<size_t>(manifold.bodyB)], point.point, manifold.tangent());
  const double impulse = tangentImpulseChange(point, -state.tangentMass * relativeTangentVelocity,
                                              manifold.friction, normalImpulseThisSweep);
  applyContactImpulse(context.bodies, manifold, state.point, 0.0, impulse);
  return impulse;
}

// Accumulated impulses: the running total may only push (≥ 0); what is applied is the change of
// the total, so a later sweep can take back part of an earlier push. Without accumulation each
// impulse is clamped on its own and can never be taken back.
double SequentialImpulseSolver::normalImpulseChange(ContactPoint& point, double impulse) const {
  const double before = point.normalImpulse;
  if (settings_.accumulateImpulses) {
    point.normalImpulse = std::max(before + impulse, 0.0);
  } else {
    point.normalImpulse = before + std::max(impulse, 0.0);
  }
  return point.normalImpulse - before;
}

// Coulomb's limit: the running friction total stays within ±μ × the running normal total; without
// accumulation each friction impulse is capped at μ × this sweep's normal impulse (the text's cap).
double SequentialImpulseSolver::tangentImpulseChange(ContactPoint& point, double impulse,
                                                     double friction,
                                                     double normalImpulseThisSweep) const {
  const double before = point.tangentImpulse;
  if (settings_.accumulateImpulses) {
    const double limit = friction * point.normalImpulse;
    point.tangentImpulse = std::clamp(before + impulse, -limit, limit);
  } else {
    const double limit = friction * std::max(normalImpulseThisSweep, 0.0);
    point.tangentImpulse = before + std::clamp(impulse, -limit, limit);
  }
  return point.tangentImpulse - before;
}

void SequentialImpulseSolver::updateFrictionStates(const StepContext& context) const {
  for (const PointState& state : states_) {
    Manifold& manifold = context.manifolds[static_cast<size_t>(state.manifold)];
    ContactPoint& point = manifold.points[static_cast<size_t>(state.point)];
    point.friction =
        frictionStateOf(point.normalImpulse, point.tangentImpulse, manifold.friction, 0.0);
  }
}

void SequentialImpulseSolver::solvePositions(const StepContext& context) {
  correctPositions(context, settings_.positionPass, settings_.targets.allowedPenetration,
                   settings_.block);
}

}  // namespace impulse2d
