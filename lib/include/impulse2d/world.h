// The world: bodies, gravity, a fixed time step and one contact solver.
//
// ONE STEP runs the substep below `substeps` times with h = dt/substeps (settings.h), each after
// applyLoads adds every body's AppliedLoad (body.h) at the substep's start time.
// ONE SUBSTEP (semi-implicit, "symplectic", Euler). The world wakes disturbed bodies, calls the
// method's step (ContactSolver::step, solver.h), then checks the state and puts resting islands
// to sleep. The method's step calls the shared stages (StepStages) in its own order:
//   findContacts        broad phase (sort and sweep on bounding boxes, fattened by |v|·h when the
//                       method finds contacts ahead), then the narrow phase for each overlapping
//                       pair with an awake body; a pair of sleeping or static bodies keeps its
//                       manifold as it was. Impulses of the last step are carried over to points
//                       with the same feature id (warm starting). A point on an internal edge
//                       of flush static pieces is refused (internal_edges.h). A pair whose last
//                       manifold the method keeps (ManifoldKeeping) is not found anew. Islands
//                       (the dynamic bodies joined by contacts) with an awake body wake whole.
//                       Returns the manifolds with an awake body: what the method solves.
//   integrateVelocities awake bodies: v += (g + F/m)·h, ω += (τ/I)·h; the linear acceleration is
//                       kept in Body::lastAcceleration; forces and torques are cleared.
//   stopAtNonFiniteBody a body whose state is not finite stops the step (NonFiniteState).
//   integratePositions  awake bodies: x += v·h, θ += ω·h; the rotation is updated, the bounds
//                       wait for refreshCaches.
//   refreshCaches       awake bodies: rotation from the angle and bounds, once per substep.
//   clearForces         for a method that integrated the forces in its own substeps.
//   storeImpulses       the solved manifolds back into the world's, for the next substep.
// Micro, sequential and the reference find contacts, integrate velocities, solve velocities,
// integrate positions, solve positions, refresh caches and store impulses; a method of substeps
// finds contacts ahead, keeping some, moves the bodies in its own substeps, clears the forces and
// stores impulses. After the step, stopAtTimeOfImpact (with continuous on): an awake body whose
// motion in the substep would carry its core into a static body is moved back to where it reaches
// it (continuous.h). Then putRestingIslandsToSleep: an island whose bodies have all been slower
// than the sleep thresholds for timeToSleep sleeps; its velocities become zero.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "impulse2d/continuous.h"
#include "impulse2d/simulation.h"
#include "impulse2d/union_find.h"

namespace impulse2d {

/// What the last substep modelled, so tests and benchmarks can see that sleeping bodies cost
/// nothing.
struct StepStatistics {
  int awakeBodies = 0;       ///< dynamic bodies integrated
  int narrowPhasePairs = 0;  ///< pairs given to collide()
  int keptManifolds = 0;     ///< manifolds of sleeping (or sleeping and static) pairs kept as is
  int reusedManifolds = 0;   ///< manifolds the method kept from the last substep (ManifoldKeeping)
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
  /// the contact method, to read its last report
  const ContactSolver& solver() const { return *solver_; }
  /// what the last step did
  const StepStatistics& lastStepStatistics() const { return statistics_; }

  /// Step 2 alone: rebuilds the manifolds from the current positions, found as `finding` asks
  /// (a method's ManifoldKeeping keeps what it keeps); the statistics then count step 2 alone.
  void findContacts(const ContactFinding& finding = {});

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
  void findContacts(double h, const ContactFinding& finding);
  void findCandidatePairs(double h);
  void sortCandidatePairs();
  void placeCandidatePairs(int BodyPair::*body);
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
  std::vector<BodyPair> sortedPairs_;  ///< the candidate pairs being sorted
  std::vector<int> pairsStart_;        ///< by body: where its pairs go in sortedPairs_
  std::vector<int> staticBodies_;      ///< indices of the static bodies, for internal edges
  std::vector<Pose> startPoses_;  ///< by body: where it began the substep (continuous collision)
  /// One body in the sweep: its fattened bounds, the upper edges grown by the contact margin
  /// (m), and whether it is awake.
  struct SweepEntry {
    double reachRight;
    double bottom;
    double reachTop;
    int body;
    bool awake;
  };
  std::vector<int> sweepOrder_;       ///< bodies by the left edge of their bounds
  std::vector<Aabb> sweepBounds_;     ///< by body: bounds fattened for speculative contacts
  std::vector<SweepEntry> sweep_;     ///< in sweep order, so the sweep reads memory in order
  std::vector<double> sweepLeft_;     ///< m, in sweep order: the left edges the sweep stops at
  UnionFind islands_;                 ///< the islands, by body
  std::vector<char> islandAwake_;     ///< by island root
  std::vector<double> islandRested_;  ///< s, by island root: the shortest sleep time in it
  StepStatistics statistics_;
  ContactFinding finding_;  ///< how the method asked for this substep's contacts
  SolverObserver* observer_ = nullptr;
  long stepCount_ = 0;
};

}  // namespace impulse2d
