// A scene: the world's settings, the solver it runs and the bodies in it, as plain physics data
// (how frames look at it belongs to the scene file, scene_file.h). Scene files produce it; World,
// Box2D and the tests are all built from it.
#pragma once

#include <string>
#include <vector>

#include "impulse2d/body.h"
#include "impulse2d/settings.h"
#include "impulse2d/world.h"

namespace impulse2d {

/// One body as a scene states it. Defaults are those a scene file gets when it omits a key.
struct BodyDef {
  std::string name;  ///< default "body<index>"
  /// static or dynamic
  BodyType type = BodyType::Dynamic;
  Shape shape = makeCircle(0.5);  ///< centred on the centre of mass
  Vec2 position = Vec2::Zero();   ///< m, centre of mass
  double angle = 0.0;             ///< rad
  Vec2 velocity = Vec2::Zero();   ///< m/s
  double angularVelocity = 0.0;   ///< rad/s
  double density = 1.0;           ///< kg/m^2
  /// coefficient of friction
  double friction = 0.5;
  /// coefficient of restitution
  double restitution = 0.0;
  AppliedLoad load;  ///< force, force_rate, force_point, torque (none by default)
};

/// What a run is made of: the world, the solver and the bodies (a scene file holds one).
struct Scene {
  std::string name = "scene";  ///< file name without extension
  /// gravity, time step and the rest of [world]
  WorldSettings world;
  /// steps a run takes
  int steps = 600;
  /// "micro", "sequential", "reference", "soft_step" or "box2d"
  std::string solver = "sequential";
  /// The solver's preset (presets.h) its settings started from; empty: our defaults.
  std::string preset;
  /// the [solver] table
  SolverSettings solverSettings;
  /// in the order the world indexes them
  std::vector<BodyDef> bodies;
};

/// A world of the scene's bodies running its solver.
std::unique_ptr<World> buildWorld(const Scene& scene);

/// The scene's bodies as the engine holds them (mass, inertia, caches computed).
std::vector<Body> buildBodies(const Scene& scene);

/// Appends `count` boxes of `size` (width, height) standing on `base` (the bottom centre of the
/// lowest box), each level shifted sideways by `levelOffset`, exactly touching.
void addStack(Scene& scene, int count, const Vec2& size, const Vec2& base, double levelOffset,
              const BodyDef& material);

/// Appends a pyramid of `rows` rows of boxes of `size`, exactly touching, the bottom row's base
/// centred on `baseCentre`; row k (from 0 at the bottom) holds rows − k boxes.
void addPyramid(Scene& scene, int rows, const Vec2& size, const Vec2& baseCentre,
                const BodyDef& material);

}  // namespace impulse2d
