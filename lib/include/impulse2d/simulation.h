// What every runnable simulation offers the command line, the frames and the tests: our world
// with any of its solvers, or Box2D running the same scene.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "impulse2d/body.h"
#include "impulse2d/contact.h"
#include "impulse2d/settings.h"
#include "impulse2d/solver.h"

namespace impulse2d {

/// A step left a dynamic body's state non-finite (a load, mass or speed beyond what a double
/// holds). The step throws it at once, naming the first such body, so no solver and no figure
/// ever reads the overflowed state; the bodies keep the state the step left.
/// what(): "body NAME became non-finite at step N (solver S)".
class NonFiniteState : public std::runtime_error {
 public:
  /// The error naming the body, the step and the solver.
  NonFiniteState(const std::string& body, long step, const std::string& solver);
};

/// A body's state is finite when its position, angle, velocity and angular velocity are, and so
/// are the kinetic energy and the potential energy in `gravity` they give: every figure a run
/// reports of the body is then finite too.
bool hasFiniteState(const Body& body, const Vec2& gravity);

/// Throws NonFiniteState for the first dynamic body of `bodies` whose state is not finite.
void stopAtNonFiniteBody(const std::vector<Body>& bodies, const Vec2& gravity, long step,
                         const std::string& solver);

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
/// Deepest penetration among the last step's contact points (m); 0 without contacts. The points
/// were found at the start of the last step, before its solve moved the bodies.
double largestPenetration(const Simulation& simulation);
/// Deepest overlap of any two bodies (one of them dynamic) as they stand now (m): the penetration
/// of the run's state, found by colliding the bodies afresh; 0 when none overlap.
double deepestOverlap(const std::vector<Body>& bodies);
/// Number of contact points in the last step.
int contactPointCount(const Simulation& simulation);

}  // namespace impulse2d
