// The world: bodies, gravity, a fixed time step and one contact solver.
//
// ONE STEP runs the substep below `substeps` times with h = dt/substeps (settings.h), each after
// applyLoads adds every body's AppliedLoad (body.h) at the substep's start time.
// ONE SUBSTEP, IN ORDER (semi-implicit, "symplectic", Euler). The world does what every method
// shares (1-3, 5); the method's step (ContactSolver::step, solver.h) runs the shared stages of 4
// and its own passes, in its own order:
//   1. wakeDisturbedBodies a sleeping body the user gave a velocity or force wakes.
//   2. findContacts        broad phase (sort and sweep on bounding boxes, fattened by |v|·h when
//                          contacts are found ahead), then the narrow phase for each overlapping
//                          pair with an awake body; a pair of sleeping or static bodies keeps its
//                          manifold as it was. Impulses of the last step are carried over to
//                          points with the same feature id (for warm starting). A point on an
//                          internal edge of flush static pieces is refused (internal_edges.h).
//                          A pair whose last manifold the solver keeps
//                          (ContactSolver::keepManifold) is not found anew.
//   3. wakeTouchedIslands  islands are the dynamic bodies joined by contacts (static bodies join
//                          none); an island with an awake body wakes whole.
//   4. the solver's step, given only the manifolds with an awake body. By default:
//      integrateVelocities awake bodies: v += (g + F/m)·h, ω += (τ/I)·h; the linear acceleration
//                          is kept in Body::lastAcceleration; forces and torques are cleared.
//                          A body whose state is then not finite stops the step (NonFiniteState),
//                          as one left so after the substep does.
//      solveVelocities     the solver's contact impulses act on the new velocities.
//      integratePositions  awake bodies: x += v·h, θ += ω·h, with the velocities after impulses;
//                          the rotation is updated, the bounds wait for refreshCaches.
//      solvePositions      the solver removes what penetration remains.
//      refreshCaches       awake bodies: rotation from the angle and bounds, once per substep.
//      A method that moves the bodies within its own substeps calls clearForces instead.
//   then stopAtTimeOfImpact (with continuous on): an awake body whose motion in the substep
//                          would carry its core into a static body is moved back to where it
//                          reaches it (continuous.h).
//   5. putRestingIslandsToSleep  an island whose bodies have all been slower than the sleep
//                          thresholds for timeToSleep sleeps; its velocities become zero.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "impulse2d/continuous.h"
#include "impulse2d/simulation.h"

namespace impulse2d {

/// What the last substep modelled, so tests and benchmarks can see that sleeping bodies cost
/// nothing.
struct StepStatistics {
  int awakeBodies = 0;       ///< dynamic bodies integrated
  int narrowPhasePairs = 0;  ///< pairs given to collide()
  int keptManifolds = 0;     ///< manifolds of sleeping (or sleeping and static) pairs kept as is
  int reusedManifolds = 0;   ///< manifolds the solver kept from the last substep (keepManifold)
  int solvedManifolds = 0;   ///< manifolds given to the solver
};

/// Our world: bodies stepped in the order written above, contacts resolved by one ContactSolver.
class World : public Simulation {
 public:
  /// Throws std::invalid_argument when settings.substeps < 1.
  World(const WorldSettings& settings, std::unique_ptr<ContactSolver> solver);

  /// Adds a body and returns its index.
  int addBody(Body body);

  void step() override;

  const std::vector<Body>& bodies() const override { return bodies_; }
  /// Bodies may be changed between steps (call Body::updateCache after moving one, and
  /// Body::wake if it sleeps).
  std::vector<Body>& bodies() { return bodies_; }
  /// Every contact, sleeping ones with the impulses of their last awake step; with substeps,
  /// those of the last substep.
  const std::vector<Manifold>& manifolds() const override { return manifolds_; }
  std::string solverName() const override { return solver_->name(); }
  const WorldSettings& settings() const override { return settings_; }
  long stepCount() const override { return stepCount_; }
  /// Observed solver events index the manifolds given to the solver: all of them unless some
  /// sleep.
  void setObserver(SolverObserver* observer) override { observer_ = observer; }

  /// the contact method
  ContactSolver& solver() { return *solver_; }
  /// what the last step did
  const StepStatistics& lastStepStatistics() const { return statistics_; }

  /// Step 2 alone: rebuilds the manifolds from the current positions (keeping those the solver
  /// keeps); the statistics then count this step 2 alone.
  void findContacts();

 private:
  using BodyPair = std::pair<int, int>;
  using ManifoldIterator = std::vector<Manifold>::const_iterator;
  /// The stages below, as a solver's step calls them (StepStages, solver.h).
  class WorldStages;

  /// Adds every body's applied load at simulated time `time` (s), before a substep.
  void applyLoads(double time);
  void substep(double h);
  /// Throws NonFiniteState (simulation.h) naming the first dynamic body whose state overflowed.
  void stopAtNonFiniteBody() const;
  void wakeDisturbedBodies();
  void findContacts(double h);
  void findCandidatePairs(double h);
  void computeSweepBounds(double h);
  void sortSweepOrder();
  void layOutSweep();
  ManifoldIterator keepSleepingManifolds(ManifoldIterator old, const BodyPair& before);
  bool collidePair(const BodyPair& pair, double h, Manifold& manifold);
  void listStaticBodies();
  void rememberStartPoses();
  bool speculativeContacts() const;
  double contactDistance(const Body& a, const Body& b, double h) const;
  bool involvesAwakeBody(const Manifold& manifold) const;
  void buildIslands();
  int islandOf(int body);
  void wakeTouchedIslands();
  void integrateVelocities(double h);
  void clearForces();
  std::vector<Manifold>& manifoldsToSolve();
  void storeSolvedManifolds();
  void integratePositions(double h);
  void refreshCaches();
  void putRestingIslandsToSleep(double h);
  void updateSleepTime(Body& body, double h) const;

  WorldSettings settings_;
  std::unique_ptr<ContactSolver> solver_;
  std::vector<Body> bodies_;
  std::vector<Manifold> manifolds_;          ///< sorted by (bodyA, bodyB)
  std::vector<Manifold> previousManifolds_;  ///< the last substep's, for carrying impulses over
  std::vector<Manifold> solverManifolds_;    ///< the awake ones, when some sleep
  std::vector<int> solvedIndex_;             ///< where each of solverManifolds_ sits in manifolds_
  std::vector<BodyPair> candidatePairs_;
  std::vector<int> staticBodies_;  ///< indices of the static bodies, for internal edges
  std::vector<Pose> startPoses_;   ///< by body: where it began the substep (continuous collision)
  /// One body in the sweep: its fattened bounds and whether it is awake.
  struct SweepEntry {
    Aabb bounds;
    int body;
    bool awake;
  };
  std::vector<int> sweepOrder_;       ///< bodies by the left edge of their bounds
  std::vector<Aabb> sweepBounds_;     ///< by body: bounds fattened for speculative contacts
  std::vector<SweepEntry> sweep_;     ///< in sweep order, so the sweep reads memory in order
  std::vector<int> islandParent_;     ///< union-find forest of the islands, by body
  std::vector<char> islandAwake_;     ///< by island root
  std::vector<double> islandRested_;  ///< s, by island root: the shortest sleep time in it
  StepStatistics statistics_;
  SolverObserver* observer_ = nullptr;
  long stepCount_ = 0;
};

}  // namespace impulse2d
