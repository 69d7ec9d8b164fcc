// Stacks, pyramids and the figures read from them, for the tests of the iterative and global
// contact solvers: gravity 10 m/s², unit boxes of density 1, 60 steps a second.
#pragma once

#include <algorithm>
#include <memory>
#include <string>

#include "impulse2d/scene/scene.h"
#include "lecture_scenes.h"

namespace solvers {

using impulse2d::Vec2;

constexpr double kGravity = 10.0;
constexpr double kDt = 1.0 / 60.0;
constexpr double kBoxMass = 1.0;  ///< a 1 m × 1 m box of density 1

/// An empty scene for `solver` with gravity −10 and dt 1/60 on a wide static ground of friction
/// `friction` whose top is y = 0 (body 0).
inline impulse2d::Scene groundScene(const std::string& solver, double friction) {
  impulse2d::Scene scene;
  scene.solver = solver;
  scene.world.gravity = Vec2(0.0, -kGravity);
  scene.world.dt = kDt;
  scene.bodies.push_back(lecture::ground(friction));
  return scene;
}

inline impulse2d::BodyDef unitBoxMaterial(double friction) {
  impulse2d::BodyDef material;
  material.friction = friction;
  material.density = kBoxMass;
  return material;
}

/// `count` unit boxes stacked on the ground, exactly touching, at rest: box k is body k + 1.
inline impulse2d::Scene stackScene(const std::string& solver, int count, double friction) {
  impulse2d::Scene scene = groundScene(solver, friction);
  impulse2d::addStack(scene, count, Vec2(1.0, 1.0), Vec2(0.0, 0.0), 0.0, unitBoxMaterial(friction));
  return scene;
}

/// A pyramid of `rows` rows of unit boxes on the ground, exactly touching, at rest.
inline impulse2d::Scene pyramidScene(const std::string& solver, int rows, double friction) {
  impulse2d::Scene scene = groundScene(solver, friction);
  impulse2d::addPyramid(scene, rows, Vec2(1.0, 1.0), Vec2(0.0, 0.0), unitBoxMaterial(friction));
  return scene;
}

/// N. The force through the contact of bodies a and b in the last step: the sum of its points'
/// normal impulses over dt; 0 when they did not touch.
inline double contactForce(const impulse2d::Simulation& simulation, int a, int b) {
  for (const impulse2d::Manifold& manifold : simulation.manifolds()) {
    if (std::minmax(manifold.bodyA, manifold.bodyB) != std::minmax(a, b)) continue;
    double impulse = 0.0;
    for (int i = 0; i < manifold.pointCount; ++i) impulse += manifold.points[i].normalImpulse;
    return impulse / simulation.settings().dt;
  }
  return 0.0;
}

inline void runSteps(impulse2d::Simulation& simulation, int steps) {
  for (int i = 0; i < steps; ++i) simulation.step();
}

inline int stepsIn(double seconds) {
  return static_cast<int>(std::lround(seconds / kDt));
}

}  // namespace solvers
