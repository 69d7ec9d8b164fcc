// Sequential impulses' settings (sequential_impulses.h), with their documented defaults.
#pragma once

#include "impulse2d/shared_settings.h"

namespace impulse2d {

/// Accumulated impulses and warm starting (Box2D-Lite's two switches); each value keeps the ones
/// before it.
enum class ImpulseAccumulation {
  /// Each impulse clamped on its own, as the text first states the method.
  ClampedEach,
  /// Accumulated impulses: each contact's running total of impulse is clamped, not each impulse.
  Accumulated,
  /// Warm starting: each step begins from the last step's totals, matched by feature id.
  WarmStarted,
};

/// Sequential impulses ("Explaining the rigid body solver", Box2D-Lite).
struct SequentialImpulseSettings {
  /// Most sweeps over all contacts per step. A stack of n boxes starting from rest needs about n
  /// sweeps before the weight reaches the bottom within one step, and a 40-row pyramid rests only
  /// with about 40; once a pile rests the sweeps stop after one (convergedImpulseChange).
  int velocityIterations = 40;
  /// The sweeps stop once a whole sweep changed no impulse by more than this fraction of the
  /// largest normal total: the answer has converged (at 1e-6 the figures equal full sweeps' to
  /// three digits; docs/sequential-impulses.md). 0: always velocityIterations, the text's method.
  double convergedImpulseChange = 1e-6;
  /// What each contact's impulse is clamped as, and where each step begins.
  ImpulseAccumulation impulses = ImpulseAccumulation::WarmStarted;
  /// Bias and bounce targets.
  ContactTargetSettings targets;
  /// The position pass after integration; its block solve takes block.conditionLimit.
  PositionPassSettings positionPass;
  /// The block solve of two-point contacts' velocities (it needs accumulated impulses).
  BlockSolveSettings block;
  /// Friction before the normal impulses in each contact's solve, as Box2D 2.4 orders them ("non
  /// -penetration is more important than friction", so the normal has the last word in a sweep).
  /// False: the normal first, then friction against it, as Box2D-Lite and the text do. Needs
  /// accumulated impulses (without them friction is capped by this sweep's normal impulse).
  bool frictionFirst = false;
  /// After each sweep the impulses are pushed on along the direction the last sweeps moved them,
  /// by β = (this sweep's squared changes) / (the last sweep's), the Fletcher–Reeves ratio; when
  /// a sweep changed more than the one before (β > 1) the direction starts again from that
  /// sweep's changes. This is the nonsmooth nonlinear conjugate gradient of Silcowitz, Niebe and
  /// Erleben (2010; Bullet's btNNCGConstraintSolver). Plain sweeps pass a pile's weight down only
  /// a few contacts per sweep, so its slowest error shrinks by about 1 − c/n² a sweep for a pile
  /// n contacts tall; the push carries it on (docs/sequential-impulses.md). Needs accumulated
  /// impulses: the next sweep clamps what the push carried past zero or the friction cone.
  bool conjugateGradient = true;
  /// A resting contact's manifold is kept as found while its bodies move little, its overlap
  /// following how far they moved, instead of being clipped anew every step (Box2D v3's contact
  /// recycling, contact_recycling.h). A settled pile then pays the narrow phase only for the pairs
  /// that moved (docs/sequential-impulses.md). Kept only within 5 mm (the contact margin) and
  /// 0.01 rad, a tenth of soft step's v3 distances: without speculative contacts or substeps, a
  /// box bouncing onto a steep slope kept its manifold through the bounce at v3's and missed the
  /// corner that should have caught it.
  RecyclingSettings recycling = {RecyclingRule::Refined, 0.005, 0.01};

  /// Catto's Box2D-Lite: 10 sweeps to the end, normal then friction, Baumgarte bias 0.2 beyond a
  /// slop of 0.01 m with no cap, no bounce, no block solve, no position pass, every contact found
  /// anew every step.
  static SequentialImpulseSettings box2dLite();
  /// Box2D 2.4.1's b2ContactSolver: 8 sweeps to the end, friction first, the block solver, bounce
  /// above 1 m/s and no penetration bias in the velocities; then 3 sweeps of its position solver
  /// one point at a time (0.2 of the penetration beyond 0.005 m, at most 0.2 m); every contact
  /// found anew every step.
  static SequentialImpulseSettings box2d24();
};

}  // namespace impulse2d
