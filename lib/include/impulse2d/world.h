// The world: bodies, gravity, a fixed time step and one contact solver.
//
// ONE STEP, IN ORDER (semi-implicit, "symplectic", Euler):
//   1. findContacts        broad phase (sort and sweep on bounding boxes), then the narrow phase
//                          for each overlapping pair; impulses of the last step are carried over
//                          to points with the same feature id (for warm starting).
//   2. integrateVelocities v += (g + F/m)·dt, ω += (τ/I)·dt; the linear acceleration is kept in
//                          Body::lastAcceleration; forces and torques are cleared.
//   3. solveVelocities     the solver's contact impulses act on the new velocities.
//   4. integratePositions  x += v·dt, θ += ω·dt, with the velocities after the impulses.
//   5. solvePositions      the solver removes what penetration remains.
#pragma once

#include <memory>
#include <vector>

#include "impulse2d/simulation.h"

namespace impulse2d {

class World : public Simulation {
 public:
  World(const WorldSettings& settings, std::unique_ptr<ContactSolver> solver);

  /// Adds a body and returns its index.
  int addBody(Body body);

  void step() override;

  const std::vector<Body>& bodies() const override { return bodies_; }
  /// Bodies may be changed between steps (call Body::updateCache after moving one).
  std::vector<Body>& bodies() { return bodies_; }
  const std::vector<Manifold>& manifolds() const override { return manifolds_; }
  std::string solverName() const override { return solver_->name(); }
  const WorldSettings& settings() const override { return settings_; }
  long stepCount() const override { return stepCount_; }
  void setObserver(SolverObserver* observer) override { observer_ = observer; }

  ContactSolver& solver() { return *solver_; }

  /// Step 1 alone: rebuilds the manifolds from the current positions.
  void findContacts();

 private:
  void findCandidatePairs();
  void carryOverImpulses(std::vector<Manifold>& previous);
  void integrateVelocities();
  void integratePositions();

  WorldSettings settings_;
  std::unique_ptr<ContactSolver> solver_;
  std::vector<Body> bodies_;
  std::vector<Manifold> manifolds_;
  std::vector<Manifold> previousManifolds_;
  std::vector<std::pair<int, int>> candidatePairs_;
  std::vector<int> sweepOrder_;
  SolverObserver* observer_ = nullptr;
  long stepCount_ = 0;
};

}  // namespace impulse2d
