// The one interface every contact method sits behind, so a scene can run, trace and compare any
// of them. The world calls solveVelocities after gravity and forces are integrated into the
// velocities, and solvePositions after the positions are integrated (see world.h for the order).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "impulse2d/body.h"
#include "impulse2d/contact.h"
#include "impulse2d/settings.h"

namespace impulse2d {

/// One thing a solver did to one contact point, reported to an observer as it happens, so a
/// student can watch a step iteration by iteration (`i2d run --trace-step`).
struct SolverEvent {
  /// Which pass of the step the event belongs to.
  enum class Phase { Velocity, Position };
  /// velocity or position pass
  Phase phase = Phase::Velocity;
  /// 0-based: the micro-collision resolver counts its impulses (or moves) in this step,
  /// sequential impulses count their sweeps.
  int iteration = 0;
  int manifold = -1;  ///< index into the step's manifolds
  int point = -1;     ///< 0 or 1
  /// Velocity phase: the velocity change the solver wanted at the point along the normal (m/s).
  /// Position phase: the penetration it removed (m).
  double desiredChange = 0.0;
  double normalImpulse = 0.0;   ///< N s applied by this event along the normal
  double tangentImpulse = 0.0;  ///< N s applied by this event along the tangent
};

/// Watches a solver event by event (a traced step).
class SolverObserver {
 public:
  virtual ~SolverObserver() = default;
  /// Called after the event's impulse or move has been applied to the bodies.
  virtual void onSolverEvent(const SolverEvent& event, const std::vector<Body>& bodies,
                             const std::vector<Manifold>& manifolds) = 0;
};

/// What a solver works on in one step.
struct StepContext {
  /// the world's bodies
  std::vector<Body>& bodies;
  /// the contacts to solve
  std::vector<Manifold>& manifolds;
  /// s, the time step
  double dt;
  SolverObserver* observer = nullptr;  ///< null unless the step is being traced
  /// m/s^2. The world's gravity, for a solver that integrates the bodies itself.
  Vec2 gravity = Vec2::Zero();

  /// Tells the observer, if the step is being traced, what the solver just did.
  void report(const SolverEvent& event) const {
    if (observer) observer->onSolverEvent(event, bodies, manifolds);
  }
};

/// How the last solve went. Iterative methods report their iterations; the reference reports its
/// residual and whether it met its tolerance, never a silent half answer.
struct SolveReport {
  /// iterations (or substeps) made
  int iterations = 0;
  /// what was left when the solve stopped
  double residual = 0.0;
  /// the solve met its tolerance
  bool converged = true;
};

/// Contact recycling (Box2D v3): the world keeps a pair's manifold from step to step, its normal
/// and arms as found and only its overlap updated, while neither body has turned more than
/// largestTurn since it was found and B has moved less than `distance` relative to A (world.h).
struct ContactRecycling {
  double distance = 0.0;     ///< m; 0: every manifold is found anew each substep
  double largestTurn = 0.0;  ///< rad
  /// A circle's overlap follows its centre alone, its arm not turned (SoftStepSettings).
  bool roundSurfaces = false;
  /// A one-point manifold is kept only while the bodies moved less than the contact distance it
  /// was found within as well (SoftStepSettings::recycleWithinFoundDistance).
  bool withinFoundDistance = false;
  /// A manifold whose normal runs to a circle's centre (normalRunsToCentre) is found anew every
  /// step (SoftStepSettings::renewRoundNormals); false: it is kept like any other, as in v3.
  bool renewRoundNormals = false;
  /// B's movement is measured in the world's frame, where the recycled normal and arms are kept,
  /// so a pair that turns together counts as moving (SoftStepSettings::recycleInWorldFrame);
  /// false: in A's frame, as Box2D v3 measures it.
  bool inWorldFrame = false;
};

/// A contact method: one interface, one file per method (docs/architecture.md).
class ContactSolver {
 public:
  virtual ~ContactSolver() = default;
  /// The name scene files use: "micro", "sequential", "reference", "soft_step".
  virtual std::string name() const = 0;
  /// Contact impulses: change the velocities so no contact keeps closing.
  virtual void solveVelocities(const StepContext& context) = 0;
  /// Remove the penetration that remains after the positions moved, without adding velocity.
  virtual void solvePositions(const StepContext& context) = 0;
  /// How the last solve went.
  virtual SolveReport lastReport() const { return {}; }
  /// True for a method that moves the bodies itself within its own substeps (soft step): the
  /// world then leaves velocities and positions to it and only clears the forces it used.
  virtual bool integratesBodies() const { return false; }
  /// True for a method whose contacts are speculative whatever the world's speculativeContacts
  /// says (soft step, as Box2D v3: every contact is found before the surfaces meet).
  virtual bool wantsSpeculativeContacts() const { return false; }
  /// The recycling of manifolds this method wants; none by default (soft step, as Box2D v3, keeps
  /// them while the bodies move little).
  virtual ContactRecycling contactRecycling() const { return {}; }
};

/// The names of the solvers this library builds, in the order they were written.
std::vector<std::string> solverNames();

/// The solver of that name with its settings from `settings`; throws std::invalid_argument naming
/// the known solvers when the name is unknown.
std::unique_ptr<ContactSolver> makeSolver(const std::string& name, const SolverSettings& settings);

}  // namespace impulse2d
