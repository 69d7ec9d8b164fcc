// Every tunable number of the engine, with its documented default. One struct for the world and
// one per contact solver; a scene file's [world] and [solver] tables set their fields by name.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "impulse2d/math.h"

namespace impulse2d {

struct WorldSettings {
  /// m/s^2. Earth's gravity, downwards.
  Vec2 gravity = Vec2(0.0, -9.81);
  /// s. The fixed time step: 60 updates a second, as most games run.
  double dt = 1.0 / 60.0;
  /// m. Contact points are generated while the surfaces are closer than this, so a resting body
  /// whose correction left a hair's gap keeps its contact. Solvers treat a gap as speculative:
  /// they only act if the gap would close within the step.
  double contactMargin = 0.005;
};

/// The lecture's micro-collision resolver (lecture 3.6, Millington ch. 14-15).
struct MicroCollisionSettings {
  /// Remove the velocity built up by the last update's acceleration from the bounce target:
  /// Δv = −vs − c·(vs − vacc). Off: a resting contact bounces on gravity's velocity (jitter).
  bool removeAccelerationVelocity = true;
  /// Use zero restitution when the closing speed is under restitutionVelocityLimit.
  bool lowerRestitutionAtLowSpeed = true;
  /// m/s. Below this closing speed a contact does not bounce. Millington uses 0.25.
  double restitutionVelocityLimit = 0.25;
  /// Friction as impulses through the 2×2 contact matrix. Off: frictionless normal impulses.
  bool friction = true;
  /// m/s. Velocity resolution stops when no contact needs a larger velocity change.
  double velocityEpsilon = 1e-4;
  /// m. Penetration resolution stops when no contact penetrates deeper than this.
  double positionEpsilon = 1e-5;
  /// Velocity resolution may apply at most this many impulses per contact point in a step.
  int velocityIterationsPerContact = 8;
  /// Penetration resolution may resolve at most this many times per contact point in a step.
  int positionIterationsPerContact = 4;
  /// The rotation a penetration move may use, as a fraction of the contact arm: a move of d at
  /// arm r turns the body by at most angularMoveLimit·|r| of distance (Millington's 0.2).
  double angularMoveLimit = 0.2;
  /// Below this |determinant| the contact matrix counts as singular (frictionless fallback).
  double singularMatrixTolerance = 1e-12;
};

/// Sequential impulses ("Explaining the rigid body solver", Box2D-Lite).
struct SequentialImpulseSettings {
  /// Sweeps over all contacts per step.
  int velocityIterations = 8;
  /// Clamp each contact's running total of impulse rather than each impulse.
  bool accumulateImpulses = true;
  /// Begin each step from the last step's totals, matched by feature id (needs accumulation).
  bool warmStarting = true;
  /// Target a small separating velocity that grows with penetration (Baumgarte bias).
  bool penetrationBias = true;
  /// Fraction of the penetration beyond the slop removed per step by the bias velocity.
  double biasFactor = 0.2;
  /// m. Penetration the bias leaves alone, so resting contacts stay touching.
  double allowedPenetration = 0.005;
  /// m/s. Cap on the bias velocity, so deep overlaps separate without an explosion.
  double maxBiasVelocity = 4.0;
  /// m/s. Below this closing speed a contact does not bounce (Box2D 2.4: 1 m/s).
  double restitutionVelocityThreshold = 1.0;
  /// Sweeps of the position pass after the positions are integrated; 0 turns it off.
  int positionIterations = 3;
  /// Fraction of the remaining penetration beyond the slop the position pass removes per sweep.
  double positionCorrectionFactor = 0.2;
  /// m. Largest correction the position pass makes at one contact in one sweep.
  double maxPositionCorrection = 0.2;
};

/// The global solve of all contact impulses together: the accuracy reference.
struct ReferenceSolverSettings {
  /// Required residual of the complementarity problem, relative to the largest impulse.
  double residualTolerance = 1e-10;
  /// Pivot limit of the LCP solver; reaching it is reported, never silently accepted.
  int maxPivots = 100000;
  /// Target a separating velocity that grows with penetration, as sequential impulses do.
  double biasFactor = 0.2;
  /// m. Penetration the bias leaves alone.
  double allowedPenetration = 0.005;
  /// m/s. Cap on the bias velocity.
  double maxBiasVelocity = 4.0;
  /// m/s. Below this closing speed a contact does not bounce.
  double restitutionVelocityThreshold = 1.0;
};

/// Box2D 2.4 running the same scene (the behaviour reference): its iteration counts.
struct Box2dSettings {
  /// Box2D's velocity iterations per step (its testbed default).
  int velocityIterations = 8;
  /// Box2D's position iterations per step (its testbed default).
  int positionIterations = 3;
};

/// The settings of every solver; a scene picks one solver, and its [solver] table sets that
/// solver's struct.
struct SolverSettings {
  MicroCollisionSettings micro;
  SequentialImpulseSettings sequential;
  ReferenceSolverSettings reference;
  Box2dSettings box2d;
};

/// One named field of a settings struct, for setting it by name from a scene file or the command
/// line and for listing it in `i2d check`.
struct SettingField {
  std::string name;  ///< snake_case, as in scene files
  std::variant<double*, int*, bool*, Vec2*> value;
};

std::vector<SettingField> describe(WorldSettings& settings);
std::vector<SettingField> describe(MicroCollisionSettings& settings);
std::vector<SettingField> describe(SequentialImpulseSettings& settings);
std::vector<SettingField> describe(ReferenceSolverSettings& settings);
std::vector<SettingField> describe(Box2dSettings& settings);

}  // namespace impulse2d
