// Small worlds for the concept tests: a ground, a box, a ball, an incline, built in one line each
// so every test reads as the experiment it is.
#pragma once

#include <cmath>
#include <memory>
#include <string>

#include "impulse2d/scene/scene.h"

namespace lecture {

using impulse2d::BodyDef;
using impulse2d::BodyType;
using impulse2d::Scene;
using impulse2d::Vec2;

constexpr double kGravity = 9.81;

/// A static box 40 m wide whose top face is the line y = 0, turned by `angle` about the origin.
inline BodyDef ground(double friction, double angle = 0.0) {
  BodyDef def;
  def.name = "ground";
  def.type = BodyType::Static;
  def.shape = impulse2d::makeBox(40.0, 1.0);
  def.angle = angle;
  def.position = Vec2(0.5 * std::sin(angle), -0.5 * std::cos(angle));
  def.friction = friction;
  return def;
}

/// A dynamic box of the given size resting exactly on the surface of `ground(…, angle)` with its
/// centre a distance `along` down the slope from the origin, or `lift` above the surface.
inline BodyDef boxOnSlope(const Vec2& size, double angle, double friction, double lift = 0.0) {
  BodyDef def;
  def.name = "box";
  def.shape = impulse2d::makeBox(size.x(), size.y());
  def.angle = angle;
  const Vec2 normal(-std::sin(angle), std::cos(angle));
  def.position = (0.5 * size.y() + lift) * normal;
  def.friction = friction;
  return def;
}

/// A disk of the given radius resting on the surface of `ground(…, angle)`.
inline BodyDef diskOnSlope(double radius, double angle, double friction, double lift = 0.0) {
  BodyDef def;
  def.name = "disk";
  def.shape = impulse2d::makeCircle(radius);
  const Vec2 normal(-std::sin(angle), std::cos(angle));
  def.position = (radius + lift) * normal;
  def.friction = friction;
  return def;
}

/// Unit vector down the slope of `ground(…, angle)` (for angle > 0 the slope falls to the left).
inline Vec2 downSlope(double angle) {
  return Vec2(-std::cos(angle), -std::sin(angle));
}

inline Scene sceneWith(const std::string& solver, double dt) {
  Scene scene;
  scene.solver = solver;
  scene.world.gravity = Vec2(0.0, -kGravity);
  scene.world.dt = dt;
  return scene;
}

}  // namespace lecture
