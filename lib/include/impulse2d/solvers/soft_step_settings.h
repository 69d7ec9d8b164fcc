// Soft step's settings (soft_step.h), with their documented defaults.
#pragma once

#include "impulse2d/shared_settings.h"

namespace impulse2d {

/// The relax solve: a second solve without bias after the positions moved, taking back the
/// velocity the bias added (v3's relax).
enum class Relaxation {
  /// No relax solve: the body overshoots.
  Off,
  /// A relax solve, friction in both solves (Solver2D, v3.0).
  FrictionInBoth,
  /// A relax solve, friction in it only, against the impulses left once the bias is gone (v3
  /// since 2025).
  FrictionInRelax,
};

/// Soft step (Box2D v3, Catto's Solver2D solve_soft_step; docs/soft-step.md): substeps of soft
/// contact constraints, each a spring-damper of a set stiffness and damping, then relaxation and
/// a restitution pass. Measurements behind each default are in docs/soft-step.md.
struct SoftStepSettings {
  // Box2D v3's method and constants (the preset box2d_v3 keeps these).

  /// Substeps per world step, each: velocities, warm start, biased solve, positions, relax
  /// (Box2D v3: 4).
  int substeps = 4;
  /// Hz. A contact's stiffness as the frequency it would ring at on its own mass (v3: 30).
  double contactHertz = 30.0;
  /// The stiffness never exceeds this fraction of the substep rate, so several substeps resolve a
  /// spring's period (v3: a quarter).
  double maxHertzPerSubstepRate = 0.25;
  /// The contact spring's damping ratio; above 1 it creeps back without overshoot (v3: 10).
  double dampingRatio = 10.0;
  /// Contacts with a static body are this many times stiffer in hertz, so the ground holds a
  /// pile's weight (v3: 2).
  double staticHertzFactor = 2.0;
  /// m/s. The fastest the bias pushes overlapping bodies apart (v3: 3).
  double maxPushVelocity = 3.0;
  /// Soft constraints from hertz and damping; false: the rigid limit, each substep asks the
  /// whole overlap back.
  bool softContacts = true;
  /// Whether a relax solve follows the biased one, and which of them solves friction.
  Relaxation relaxation = Relaxation::FrictionInRelax;
  /// Each step starts from the last step's impulses (by feature id), each substep from the last
  /// substep's; false: from zero.
  bool warmStarting = true;
  /// Speculative contacts whatever the world says, as v3 always has them, so a falling body is
  /// stopped at the surface instead of found overlapping (or tunnelling).
  bool speculativeContacts = true;
  /// Whether a manifold is kept as found while the bodies move little, and by which rules.
  RecyclingSettings recycling;
  /// A restitution pass after the substeps: a closing contact leaves at −e times its closing
  /// speed before the step (v3's b2ApplyRestitution); false: soft contacts do not bounce.
  bool restitution = true;
  /// m/s. Below this closing speed a contact does not bounce (v3: 1).
  double restitutionThreshold = 1.0;

  // Ours beyond Box2D v3: each true turns a refinement on; the failure each fixes and its test
  // are in docs/soft-step.md, "The published method".

  /// Round surfaces: a circle's contact follows its centre, not its turning arm, and a contact
  /// found across a gap acts where the circle will touch.
  bool roundSurfaces = true;
  /// A speculative contact between round surfaces (two circles, or a circle and a polygon's
  /// vertex) takes its normal and arms from where the two will touch within the step, moving at
  /// their velocities, so an oblique round impact leaves at Newton's angles and speeds. Default
  /// on; off (v3, the box2d_v3 preset) the normal is the line of centres where it was found.
  bool speculativeAtTouch = true;
  /// A two-point manifold whose points both bounce gets its restitution impulses as one exact
  /// 2×2 block (two_point_block.h), so a flat box leaves straight up.
  BlockSolveSettings restitutionBlock;
  /// One friction solve after a bounce, bounded by μ times the normal impulse with the bounce in
  /// it (Newton's and Coulomb's laws together).
  bool frictionInRestitution = true;
  /// A bounce may take back what any substep pushed at its point (the step's total stays ≥ 0),
  /// not only the last substep's, so an elastic corner impact gains no energy.
  bool restitutionOnStepTotals = true;

  /// Box2D v3's soft step as published: every refinement marked "ours beyond Box2D v3" off.
  static SoftStepSettings box2dV3();
};

}  // namespace impulse2d
