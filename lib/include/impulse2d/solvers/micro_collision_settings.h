// The micro-collision resolver's settings (micro_collision.h), with their documented defaults.
#pragma once

#include "impulse2d/shared_settings.h"

namespace impulse2d {

/// What one micro-collision is made of; each value keeps the ones before it.
enum class MicroCollisionImpulses {
  /// Every impulse is the lecture's rule on its own, applied only to a closing point.
  Separate,
  /// Impulse totals per update: the impulses one update applies at a point add up to one
  /// micro-collision whose total can push but never pull, and a pushed point is resolved again
  /// when pushed too hard.
  PointTotals,
  /// Block impulses: the worst point of a two-point manifold whose points both need resolving is
  /// resolved with its other point in one micro-collision (the pair's 3×3 contact matrix; sliding
  /// on the friction cone beyond it), so a box's corners do not rock each other. A bounce passes
  /// point by point, as along the cradle.
  Block,
  /// Block bounces too: a two-point manifold whose points both bounce bounces as one
  /// micro-collision, so a box landing flat leaves straight up without spinning.
  BlockWithBounces,
};

/// The lecture's micro-collision resolver (lecture 3.6, Millington ch. 14-15).
struct MicroCollisionSettings {
  /// Remove the velocity built up by the last update's acceleration from the bounce target:
  /// Δv = −vs − c·(vs − vacc). Off: a resting contact bounces on gravity's velocity (jitter).
  bool removeAccelerationVelocity = true;
  /// Use zero restitution when the closing speed is under restitutionThreshold.
  bool lowerRestitutionAtLowSpeed = true;
  /// m/s. Below this closing speed a contact does not bounce. Millington uses 0.25.
  double restitutionThreshold = 0.25;
  /// Friction as impulses through the 2×2 contact matrix. Off: frictionless normal impulses.
  bool friction = true;
  /// m/s. Velocity resolution stops when no contact needs a larger velocity change; a bounce
  /// smaller than this is none (the point is not marked as bounced).
  double velocityEpsilon = 1e-4;
  /// m. Penetration resolution stops when no contact penetrates deeper than this: resting bodies
  /// settle at up to this overlap. With block moves a stack stays straight at this epsilon, and a
  /// tighter one only costs time (the lecture preset, one corner at a time, needs 1e-5 to settle
  /// level; Millington's engine uses 0.01; docs/micro-collisions.md).
  double positionEpsilon = 1e-4;
  /// Velocity resolution may apply at most this many impulses per contact point in a step: a
  /// stack passes weight down one contact at a time, so a tall stack needs many to hold still
  /// (docs/micro-collisions.md).
  int velocityIterationsPerContact = 200;
  /// Penetration resolution may resolve at most this many times per contact point in a step.
  int positionIterationsPerContact = 8;
  /// The rotation a penetration move may use, as a fraction of the contact arm: a move of d at
  /// arm r turns the body by at most angularMoveLimit·|r| of distance (Millington's 0.2).
  double angularMoveLimit = 0.2;
  /// Below this |determinant| the contact matrix counts as singular (frictionless fallback).
  double singularMatrixTolerance = 1e-12;
  /// m. A point apart by no more than this counts as touching, so the round-off of a resolved
  /// point's zero overlap (1e-16 m) does not stop a collision passing along a row of balls, and
  /// a face landing flat engages both corners together.
  double touchingTolerance = 1e-9;

  // Refinements of ours, beyond the lecture; each is off in lecture() (docs/micro-collisions.md).

  /// Speculative gaps: a point with a gap counts when the gap would close within the step, and
  /// without a bounce may close it, no more. Off: only touching or penetrating points count.
  bool speculativeGaps = true;
  /// What one micro-collision at a point is made of.
  MicroCollisionImpulses impulses = MicroCollisionImpulses::BlockWithBounces;
  /// Worst first also counts, at a point already pushed, being pushed too hard and (while its
  /// friction is static) the slip its neighbours left. Off: only the normal need, as the lecture.
  bool severityCountsPushedPoints = true;
  /// Warm starting: each point starts the step from the totals it ended the last with (by
  /// feature id), so resting weight need not pass down a stack anew every step. False: zero.
  bool warmStarting = true;
  /// Block moves: a two-point manifold's penetrations are removed together by one move of each
  /// body (the 2×2 block solve), so resolving one corner does not drive the other deeper.
  bool blockMoves = true;
  /// Past the cap while progressing: a step at velocityIterationsPerContact goes on while the
  /// waiting points' total velocity change still falls by minimumProgress over progressRounds
  /// rounds, up to velocityIterationsPerContactLimit (docs/design/micro-collision-cost.md).
  bool passCapWhileProgressing = true;
  /// Rounds of one impulse per point over which progress is judged (at least 1; fewer never
  /// pass the cap).
  int progressRounds = 20;
  /// The least fraction by which the waiting total must fall over progressRounds rounds.
  double minimumProgress = 0.2;
  /// Most impulses per contact point in a step when passing the cap.
  int velocityIterationsPerContactLimit = 1000;
  /// A pair is resolved together only when its matrix is this well conditioned: for a move,
  /// k₀₀² < limit · det K (Box2D 2.4's test); for an impulse, det K > (product of K's diagonal) /
  /// limit. A narrower pair (two points almost at one place) is resolved one point at a time.
  double blockConditionLimit = 1000.0;

  /// The plain method of the lecture: every refinement above off, and positionEpsilon 1e-5
  /// (one corner at a time needs the tighter epsilon to settle level).
  static MicroCollisionSettings lecture();
};

}  // namespace impulse2d
