// The settings every method shares: the world's (time step, gravity, contacts, sleeping) and the
// contact rules two or more methods use (targets, the position pass, the two-point block solve,
// contact recycling).
// Each method's own settings live beside it (solvers/*_settings.h); settings.h gathers them all.
#pragma once

#include "impulse2d/math.h"

namespace impulse2d {

/// Islands of bodies at rest go to sleep: they are not integrated, their contacts are neither
/// recomputed nor solved, until an awake body touches them or the user pushes one.
enum class Sleep {
  /// Nothing sleeps: every body is integrated and every contact solved each step.
  Off,
  /// Box2D's rule: a body slower than sleepLinearSpeed and sleepAngularSpeed counts as resting.
  Box2d,
  /// Keep a body that is speeding up awake, ours beyond Box2D: a body counts as resting only
  /// while its speed and spin have grown by less than speedUpShare of the thresholds since its
  /// rest began; past that its rest begins again. A body that starts from rest and gathers speed
  /// slowly is then not frozen before it reaches the thresholds: under Box2D's rule a disc
  /// rolling down a gentle slope, a box on a slope just under its friction's limit or a seesaw
  /// slightly out of balance is still slower than them after timeToSleep, falls asleep and never
  /// moves again, since a static body wakes nothing (docs/sleeping.md; the slowest starts that
  /// freeze with and without it are in docs/design/sleeping-while-speeding-up.md).
  KeepSpeedingUpAwake,
};

/// The settings of a world: gravity, the time step and what every step does besides solving.
struct WorldSettings {
  /// m/s^2. Earth's gravity, downwards.
  Vec2 gravity = Vec2(0.0, -9.81);
  /// s. The fixed time step: 60 updates a second, as most games run.
  double dt = 1.0 / 60.0;
  /// m. Contact points are generated while the surfaces are closer than this, so a resting body
  /// whose correction left a hair's gap keeps its contact. Solvers treat a gap as speculative:
  /// they only act if the gap would close within the step.
  double contactMargin = 0.005;
  /// Each step runs the whole pipeline this many times with dt/substeps: a cure for a time step
  /// too large for the scene (deep overlaps, soft stacks) that keeps the step the caller sees.
  int substeps = 1;
  /// Fast bodies find their contacts one step early: the broad phase fattens each body's bounds
  /// by |v|·dt and a pair keeps contact points while the gap is under contactMargin + |vB−vA|·dt,
  /// so the solver can stop a fast small ball at a thin wall instead of letting it tunnel.
  bool speculativeContacts = false;
  /// Continuous collision against static bodies (continuous.h): a body whose substep would carry
  /// the core of it (half its smallest extent) into a static body is stopped where it reaches
  /// that body, its velocity kept for the next step's contact. Off, a 0.1 m ball faster than
  /// 12 m/s passes through a 0.1 m wall at 60 Hz under the rigid methods. Box2D's word.
  bool continuous = true;
  /// Refuse contacts on internal edges (internal_edges.h): where static pieces lie flush, a
  /// moving body meets one surface. Off, a box sliding across the seam of two floor tiles catches
  /// on the second tile's side face, and a disc rolling over it hops off the corner.
  bool refuseInternalEdges = true;
  /// Whether islands at rest sleep, and by which rule a body counts as resting.
  Sleep sleep = Sleep::Off;
  /// m/s. A body slower than this (and sleepAngularSpeed) counts as resting. Box2D's 0.01: a
  /// hundredth of a body width of 1 m per second is invisible at 60 frames a second.
  double sleepLinearSpeed = 0.01;
  /// rad/s. The angular speed below which a body counts as resting: Box2D's 2 degrees a second.
  double sleepAngularSpeed = 2.0 * kPi / 180.0;
  /// s. An island sleeps once every body in it has rested this long (Box2D's half a second:
  /// long enough that a body at the top of a bounce or a swing is not frozen).
  double timeToSleep = 0.5;
  /// The share of sleepLinearSpeed (sleepAngularSpeed) by which a resting body's speed (spin) may
  /// grow before it counts as speeding up: 1 mm/s and 0.2°/s. A settled pile's bodies jitter up
  /// by less than half of that (docs/design/sleeping-while-speeding-up.md).
  double speedUpShare = 0.1;
};

/// The separating velocity a contact should reach after the solve (contact_math.h,
/// targetSeparatingVelocity): penetration bias and the bounce threshold. Shared by the methods
/// that fix their targets once per step (sequential impulses, the reference).
struct ContactTargetSettings {
  /// Target a small separating velocity that grows with penetration (Baumgarte bias).
  bool penetrationBias = true;
  /// Fraction of the penetration beyond the slop removed per step by the bias velocity.
  double biasFactor = 0.2;
  /// m. The slop: penetration the bias and the position pass leave alone, so resting contacts
  /// stay touching. Its one home for each solver.
  double allowedPenetration = 0.005;
  /// m/s. Cap on the bias velocity, so deep overlaps separate without an explosion.
  double maxPushVelocity = 4.0;
  /// m/s. Below this closing speed a contact does not bounce (Box2D 2.4: 1 m/s).
  double restitutionThreshold = 1.0;
};

/// The rules above with penetration bias off: the reference's default.
inline ContactTargetSettings unbiasedTargets() {
  ContactTargetSettings targets;
  targets.penetrationBias = false;
  return targets;
}

/// The position pass (position_correction.h) run after the positions are integrated. It leaves
/// the slop of the solver's ContactTargetSettings alone.
struct PositionPassSettings {
  /// Sweeps of the position pass; 0 turns it off.
  int iterations = 3;
  /// Fraction of the remaining penetration beyond the slop removed per sweep.
  double correctionFactor = 0.2;
  /// m. Largest correction at one contact in one sweep.
  double maxCorrection = 0.2;
  /// Block solve: a two-point contact's corners corrected together (the 2×2 block solve,
  /// two_point_block.h). Off: one corner at a time, as Box2D 2.4's position solver does; the
  /// corner visited first then sinks the other deeper.
  bool blockSolve = true;
};

/// Solving the two points of a flat contact together, exactly (two_point_block.h).
struct BlockSolveSettings {
  /// On: both corners at once (Box2D 2.4's block solver). Off: one point at a time, as the text
  /// does; the corner visited first then always gets more, and a tall stack leans and sways.
  bool enabled = true;
  /// A two-point contact is solved as a block only while k₀₀² < this × det K (Box2D's 1000).
  double conditionLimit = 1000.0;
};

/// Contact recycling: a manifold is kept, normal and arms as found, while the bodies move little
/// (Box2D v3's default), so a leaning box's Jacobians do not turn, a 40-box stack stands under
/// soft step, and a resting pile's contacts are not clipped again every step.
enum class RecyclingRule {
  /// Every manifold is found anew every step.
  Off,
  /// v3's rule: found anew once the bodies moved past its distance or largest turn.
  Box2dV3,
  /// Ours beyond v3, each for a failure of its rule: a one-point manifold is also found anew
  /// once the bodies moved as far as the contact distance it was found within, so a pivoting
  /// polygon's next vertex is not missed; the distance is measured in the world's frame, where
  /// the kept normal and arms live, so a pair turning together counts as moving; and a manifold
  /// whose normal runs to a circle's centre is found anew every step, since that normal turns as
  /// the bodies move past each other.
  Refined,
};

/// When a method keeps a pair's manifold from one step to the next (contact_recycling.h).
struct RecyclingSettings {
  /// Whether a manifold is kept as found while the bodies move little, and by which rules.
  RecyclingRule rule = RecyclingRule::Refined;
  /// m. A manifold is found anew once B has moved this far relative to A, counting the turn at
  /// the farther-reaching body's extent (v3: 10 × its 0.005 m slop).
  double distance = 0.05;
  /// rad. ...or once either body has turned this far (v3: cosine above 0.98).
  double largestTurn = 0.2;
};

}  // namespace impulse2d
