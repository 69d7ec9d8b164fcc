// Small worlds for the concept tests: a ground, a box, a ball, an incline, built in one line each
// so every test reads as the experiment it is.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

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

/// A regular polygon of `sides` corners, `radius` from its centroid, lying on one face of
/// `ground(…, angle)`: its centroid an apothem R·cos(π/n) (plus `lift`) above the surface.
inline BodyDef polygonOnSlope(int sides, double radius, double angle, double friction,
                              double lift = 0.0) {
  const double half = std::acos(-1.0) / sides;  // half the angle a face spans at the centre
  std::vector<Vec2> vertices;
  for (int k = 0; k < sides; ++k) {
    const double at = -0.5 * std::acos(-1.0) - half + 2.0 * half * k;  // a face at the bottom
    vertices.emplace_back(radius * std::cos(at), radius * std::sin(at));
  }
  BodyDef def;
  def.name = "polygon";
  def.shape = impulse2d::makePolygon(vertices).shape;
  def.angle = angle;
  const Vec2 normal(-std::sin(angle), std::cos(angle));
  def.position = (radius * std::cos(half) + lift) * normal;
  def.friction = friction;
  return def;
}

/// rad/s. The spin about a corner at which a regular polygon (`sides`, `radius`) lying on a face
/// just lifts its centroid over that corner, from R·cos(π/n) to R:
/// ½ (I + m R²) ω² = m g R (1 − cos(π/n)).
inline double spinOverCorner(const BodyDef& polygon, int sides, double radius, double gravity) {
  const impulse2d::MassProperties mass = impulse2d::computeMass(polygon.shape, polygon.density);
  const double aboutCorner = mass.inertia + mass.mass * radius * radius;
  const double rise = radius * (1.0 - std::cos(std::acos(-1.0) / sides));
  return std::sqrt(2.0 * mass.mass * gravity * rise / aboutCorner);
}

/// Sets a polygon from polygonOnSlope(…, angle 0) turning clockwise about its front (+x) bottom
/// corner at `spin`: ω = −spin, and its centroid's velocity ω × (centroid − corner).
inline void pivotAboutFrontCorner(BodyDef& polygon, int sides, double radius, double spin) {
  const double half = std::acos(-1.0) / sides;
  polygon.angularVelocity = -spin;
  polygon.velocity = spin * radius * Vec2(std::cos(half), std::sin(half));
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
