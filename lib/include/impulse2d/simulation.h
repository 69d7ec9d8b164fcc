// What every runnable simulation offers the command line, the frames and the tests: our world
// with any of its solvers, or Box2D running the same scene.
#pragma once

#include <string>
#include <vector>

#include "impulse2d/body.h"
#include "impulse2d/contact.h"
#include "impulse2d/settings.h"
#include "impulse2d/solver.h"

namespace impulse2d {

/// A runnable simulation: our World with any of its solvers, or Box2D.
class Simulation {
 public:
  virtual ~Simulation() = default;
  /// Advances one fixed time step.
  virtual void step() = 0;
  /// The bodies as they stand, in scene order.
  virtual const std::vector<Body>& bodies() const = 0;
  /// The contacts of the last step, with the impulses applied at them.
  virtual const std::vector<Manifold>& manifolds() const = 0;
  /// The solver's name as scene files write it ("micro", ..., "box2d").
  virtual std::string solverName() const = 0;
  /// The world's settings (gravity, time step, ...).
  virtual const WorldSettings& settings() const = 0;
  /// Steps taken so far.
  virtual long stepCount() const = 0;
  /// Watch the solver's iterations; simulations that cannot report them ignore it.
  virtual void setObserver(SolverObserver* observer) { (void)observer; }
};

/// Total kinetic energy of the dynamic bodies (J).
double kineticEnergy(const Simulation& simulation);
/// Total potential energy of the dynamic bodies in the world's gravity (J), zero at y = 0.
double potentialEnergy(const Simulation& simulation);
/// Deepest penetration among the last step's contact points (m); 0 without contacts.
double largestPenetration(const Simulation& simulation);
/// Number of contact points in the last step.
int contactPointCount(const Simulation& simulation);

}  // namespace impulse2d
