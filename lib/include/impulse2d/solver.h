// The one interface every contact method sits behind, so a scene can run, trace and compare any
// of them. The world calls the method's step, which runs the shared stages (find contacts,
// integrate, store impulses, ...) and its own passes in its own order (see world.h and
// docs/architecture.md).
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
  /// Which pass of the step the event belongs to: the velocity sweeps, the position pass, a relax
  /// sweep (the velocities solved again without the push-out bias, after the positions moved) or
  /// a restitution pass after the sweeps, which gives a closing contact its bounce.
  enum class Phase { Velocity, Position, Relax, Restitution, Push };
  /// velocity, position, relax or restitution pass, or sequential impulses' push between sweeps
  /// (their conjugate gradient)
  Phase phase = Phase::Velocity;
  /// 0-based: the micro-collision resolver counts its impulses (or moves) in this step,
  /// sequential impulses count their sweeps, a method of substeps its substeps.
  int iteration = 0;
  int manifold = -1;  ///< index into the step's manifolds
  int point = -1;     ///< 0 or 1
  /// Velocity, relax and restitution phases: the velocity change the solver wanted at the point
  /// along the normal (m/s). Position phase: the penetration it removed (m).
  double desiredChange = 0.0;
  double normalImpulse = 0.0;   ///< N s applied by this event along the normal
  double tangentImpulse = 0.0;  ///< N s applied by this event along the tangent

  /// True for an impulse (every phase but the position pass), false for a move of the positions.
  bool changesVelocity() const { return phase != Phase::Position; }
};

/// Watches a solver event by event (a traced step).
class SolverObserver {
 public:
  virtual ~SolverObserver() = default;
  /// Called after the event's impulse or move has been applied to the bodies.
  virtual void onSolverEvent(const SolverEvent& event, const std::vector<Body>& bodies,
                             const std::vector<Manifold>& manifolds) = 0;
  /// Called when the velocities changed outside any event: the world (or a substep) integrated
  /// the forces, before the method's first impulse. The bodies as the next event starts from
  /// them.
  virtual void onVelocitiesChanged(const std::vector<Body>&) {}
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

/// A method that may keep last substep's manifold of a pair instead of having it found anew (as
/// Box2D v3 does while the pair's bodies move little). The world tells it, pair by pair in the
/// order of its manifolds (by bodyA, then bodyB), each manifold it keeps or finds.
class ManifoldKeeping {
 public:
  virtual ~ManifoldKeeping() = default;
  /// The world starts finding a substep's contacts.
  virtual void startFinding() = 0;
  /// Writes the manifold to keep into `kept` and returns true, or returns false to have the pair
  /// found anew; `previous` is the pair's manifold of the last substep.
  virtual bool keep(const Manifold& previous, const std::vector<Body>& bodies, Manifold& kept) = 0;
  /// The narrow phase found `manifold` anew within `distance` (m), the bodies where they are.
  virtual void found(const Manifold& manifold, const std::vector<Body>& bodies,
                     double distance) = 0;
};

/// How a method wants its contacts found.
struct ContactFinding {
  /// Find every contact before the surfaces meet, whatever the world's settings say: the broad
  /// and narrow phases then reach as far as the pair can close in the substep.
  bool ahead = false;
  /// null, or what decides which manifolds the method keeps
  ManifoldKeeping* keeping = nullptr;
};

/// The shared stages of a substep, which a method's step calls in its own order (as Solver2D's
/// solvers call solve_common's). The world provides them; each acts on the awake bodies.
class StepStages {
 public:
  virtual ~StepStages() = default;
  /// Broad and narrow phase, last substep's impulses carried over by feature id, islands touched
  /// by an awake body woken; returns what the method solves: the manifolds with an awake body.
  virtual StepContext findContacts(const ContactFinding& finding) = 0;
  /// v += (g + F/m)·h, ω += (τ/I)·h; the forces and torques are cleared.
  virtual void integrateVelocities() = 0;
  /// x += v·h, θ += ω·h; the rotation is updated, the bounds wait for refreshCaches.
  virtual void integratePositions() = 0;
  /// Clears the forces and torques a method used in its own integration.
  virtual void clearForces() = 0;
  /// The rotation exact from the angle again and the bounds the next broad phase sweeps with.
  virtual void refreshCaches() = 0;
  /// Stops the run (NonFiniteState) at the first body whose state is not finite.
  virtual void stopAtNonFiniteBody() = 0;
  /// The solved manifolds, with their impulses, back into the world's, which the next substep
  /// carries over (warm starting).
  virtual void storeImpulses() = 0;
};

/// The step of the rigid methods (micro-collisions, sequential impulses, the reference), in
/// Box2D-Lite's order: the forces into the velocities, the method's impulses on the new
/// velocities, the positions moved by them, then the method's pass on what penetration remains.
/// Method has solveVelocities and solvePositions, each taking the StepContext; `finding` is how it
/// wants its contacts found (sequential impulses keep those that moved little).
template <typename Method>
void stepVelocitiesThenPositions(StepStages& stages, Method& method,
                                 const ContactFinding& finding = {}) {
  const StepContext context = stages.findContacts(finding);
  stages.integrateVelocities();
  stages.stopAtNonFiniteBody();
  method.solveVelocities(context);
  stages.integratePositions();
  method.solvePositions(context);
  stages.refreshCaches();
  stages.storeImpulses();
}

/// A contact method: one interface, one file per method (docs/architecture.md).
class ContactSolver {
 public:
  virtual ~ContactSolver() = default;
  /// The name scene files use (one of solverNames()).
  virtual std::string name() const = 0;
  /// One substep of contact solving, from finding the contacts to storing their impulses: the
  /// shared stages and the method's own passes, in the method's order.
  virtual void step(StepStages& stages) = 0;
  /// How the last solve went.
  virtual SolveReport lastReport() const { return {}; }
};

/// The names of the solvers this library builds, in the order they were written.
std::vector<std::string> solverNames();

/// The solver of that name with its settings from `settings`; throws std::invalid_argument naming
/// the known solvers when the name is unknown.
std::unique_ptr<ContactSolver> makeSolver(const std::string& name, const SolverSettings& settings);

}  // namespace impulse2d
