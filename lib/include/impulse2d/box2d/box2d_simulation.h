// Box2D 2.4 running a scene: the behaviour reference. The scene's bodies become a b2World with the
// same shapes, densities, positions, velocities, materials, gravity and time step, and after each
// step the bodies and contacts are read back in our types and our sign convention (contact.h), so
// frames, CSV and the agreement table treat Box2D like any of our solvers. Box2D's types stay in
// the source file: this header links nothing but the core. See docs/box2d-reference.md.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "impulse2d/scene/scene.h"
#include "impulse2d/simulation.h"

namespace impulse2d {

/// The name a scene or the command line uses for Box2D, beside solverNames().
inline const std::string kBox2dName = "box2d";

/// Box2D features our engine lacks. Each is set for a like-for-like comparison, with the reason.
struct Box2dOptions {
  /// Box2D freezes bodies that rested for half a second; ours never sleep. Off, so a resting
  /// body keeps being solved in both and its drift and time to rest mean the same thing.
  bool allowSleeping = false;
  /// Box2D's continuous collision (time of impact) against static bodies stops a fast body at
  /// the instant it touches and drops the rest of its step, so it bounces lower than the same
  /// body resolved from the overlap found at the next step. Off, so both engines see the same
  /// impacts in the lecture's scenes, whose bodies never outrun their own size in a step.
  bool continuousPhysics = false;
};

/// Box2D's collision skin around every polygon (b2_polygonRadius = 2·b2_linearSlop = 0.01 m):
/// a Box2D polygon's surface lies this far outside the polygon's vertices.
double box2dPolygonSkin();
/// Box2D's linear slop (b2_linearSlop = 0.005 m): the overlap its position pass leaves.
double box2dLinearSlop();

/// Box2D 2.4 running a scene: the behaviour reference, read like any Simulation.
class Box2dSimulation : public Simulation {
 public:
  /// Throws std::invalid_argument for a polygon Box2D cannot hold: more than 8 vertices
  /// (b2_maxPolygonVertices), or vertices so close Box2D's hull would weld them.
  explicit Box2dSimulation(const Scene& scene, const Box2dOptions& options = {});
  ~Box2dSimulation() override;

  void step() override;
  const std::vector<Body>& bodies() const override { return bodies_; }
  /// Box2D's touching contacts after the last step, with the impulses its solver stored there.
  const std::vector<Manifold>& manifolds() const override { return manifolds_; }
  std::string solverName() const override { return kBox2dName; }
  const WorldSettings& settings() const override { return settings_; }
  long stepCount() const override { return stepCount_; }

  /// Mass and inertia about the centre of mass as Box2D computed them from the density.
  MassProperties box2dMass(int body) const;

  /// µs the last step spent inside b2World::Step alone: Box2D's own cost, without the loads,
  /// the reading back of bodies and contacts and the checks this adapter adds around it.
  double engineStepMicroseconds() const { return engineStepMicroseconds_; }

 private:
  struct Box2dWorld;

  void applyLoads();
  void readBodies();
  void readContacts();

  WorldSettings settings_;
  Box2dSettings iterations_;
  std::unique_ptr<Box2dWorld> world_;
  std::vector<Body> bodies_;
  std::vector<Manifold> manifolds_;
  long stepCount_ = 0;
  double engineStepMicroseconds_ = 0.0;
};

/// The simulation a scene asks for: Box2D when scene.solver is "box2d", else our world running
/// that solver (buildWorld). Throws std::invalid_argument naming every method for an unknown one.
std::unique_ptr<Simulation> makeSimulation(const Scene& scene);

/// Every name makeSimulation accepts: solverNames() followed by "box2d".
std::vector<std::string> simulationNames();

}  // namespace impulse2d
