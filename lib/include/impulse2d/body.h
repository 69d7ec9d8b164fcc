// Rigid bodies: mass from shape and density, state, and the forces accumulated for one step.
#pragma once

#include <cmath>
#include <string>

#include "impulse2d/math.h"
#include "impulse2d/shape.h"

namespace impulse2d {

/// A load the scene keeps on a body (docs/scene-format.md): a constant force and torque, and a
/// force that grows linearly with time, acting at a point fixed in the body. World applies it at
/// the start of every substep, Box2D's adapter at the start of every step.
struct AppliedLoad {
  Vec2 force = Vec2::Zero();      ///< N, constant
  Vec2 forceRate = Vec2::Zero();  ///< N/s: the force grows by this much each second from t = 0
  Vec2 point = Vec2::Zero();      ///< m, body frame: where the force acts (0: the centre of mass)
  double torque = 0.0;            ///< N m, constant

  /// The force at simulated time t (s): force + t · forceRate.
  Vec2 forceAt(double time) const { return force + time * forceRate; }
  /// True when the load pushes with nothing: no force, no force rate, no torque.
  bool isZero() const {
    return force == Vec2::Zero() && forceRate == Vec2::Zero() && torque == 0.0;
  }
};

/// Static bodies never move and have zero inverse mass and inertia; dynamic bodies integrate.
enum class BodyType { Static, Dynamic };

/// A rigid body: its shape and material, mass properties, state, and what the world caches.
struct Body {
  /// as the scene names it
  std::string name;
  /// static bodies never move
  BodyType type = BodyType::Dynamic;
  /// centred on the centre of mass
  Shape shape;

  double friction = 0.5;     ///< coefficient of friction of the material (mixed per contact)
  double restitution = 0.0;  ///< coefficient of restitution of the material (mixed per contact)

  double mass = 0.0;            ///< kg; 0 for static bodies
  double inverseMass = 0.0;     ///< 1/kg; 0 for static bodies
  double inertia = 0.0;         ///< kg m^2 about the centre of mass
  double inverseInertia = 0.0;  ///< 0 for static bodies

  Vec2 position = Vec2::Zero();  ///< m, world position of the centre of mass
  double angle = 0.0;            ///< rad, counter-clockwise
  Vec2 velocity = Vec2::Zero();  ///< m/s of the centre of mass
  double angularVelocity = 0.0;  ///< rad/s, counter-clockwise

  Vec2 force = Vec2::Zero();  ///< N, accumulated until the next step, then cleared
  double torque = 0.0;        ///< N m, accumulated until the next step, then cleared

  /// What the scene keeps pushing the body with (none by default).
  AppliedLoad load;

  /// m/s^2. The linear acceleration (gravity plus force/mass) applied in the last velocity update:
  /// what the micro-collision resolver removes from a resting contact's bounce (lecture 3.6).
  Vec2 lastAcceleration = Vec2::Zero();

  Mat2 rotation = Mat2::Identity();  ///< cached rotation(angle)
  Aabb bounds;                       ///< cached world bounding box

  /// Put to sleep with its island (world.h): not integrated, its contacts not solved. A sleeping
  /// body has zero velocity; a velocity, force or impulse given to it wakes it at the next step.
  bool asleep = false;
  /// s. How long the body has been slower than the world's sleep thresholds.
  double sleepTime = 0.0;
  /// m/s and rad/s. Its speed and spin when that rest began (Sleep::KeepSpeedingUpAwake).
  double restSpeed = 0.0;
  /// rad/s
  double restSpin = 0.0;

  /// A static body: infinite mass, never moves.
  bool isStatic() const { return type == BodyType::Static; }
  /// Dynamic and not asleep: integrated and solved this step.
  bool isAwake() const { return !isStatic() && !asleep; }

  /// Wakes the body (its island follows at the next step) and restarts its sleep timer. Call it
  /// after moving a sleeping body by hand, so its contacts are found again.
  void wake() {
    if (!asleep) return;
    asleep = false;
    sleepTime = 0.0;
  }

  /// Body-frame point -> world point.
  Vec2 toWorld(const Vec2& local) const { return position + rotation * local; }
  /// World point -> body-frame point.
  Vec2 toLocal(const Vec2& world) const { return rotation.transpose() * (world - position); }
  /// Velocity of the body's material at world point p.
  Vec2 velocityAt(const Vec2& p) const {
    return velocity + cross(angularVelocity, Vec2(p - position));
  }

  /// Applies an impulse (N s) at world point p: Δv = P/m, Δω = (r × P)/I.
  void applyImpulse(const Vec2& impulse, const Vec2& p) {
    wake();
    velocity += inverseMass * impulse;
    angularVelocity += inverseInertia * cross(Vec2(p - position), impulse);
  }

  /// Adds a force (N) acting at world point p for the next step.
  void applyForce(const Vec2& f, const Vec2& p) {
    wake();
    force += f;
    torque += cross(Vec2(p - position), f);
  }

  /// Adds the load's force at simulated time t (at its body point) and its torque for the next
  /// update; a body without a load is left as it is (asleep if it was).
  void applyLoad(double time) {
    if (isStatic() || load.isZero()) return;
    applyForce(load.forceAt(time), toWorld(load.point));
    torque += load.torque;
  }

  /// The velocity update of a substep h under gravity g: v += (g + F/m)·h, ω += (τ/I)·h, the
  /// linear acceleration kept in lastAcceleration, the force and torque cleared.
  void integrateVelocity(const Vec2& gravity, double h) {
    lastAcceleration = gravity + inverseMass * force;
    velocity += h * lastAcceleration;
    angularVelocity += h * inverseInertia * torque;
    force.setZero();
    torque = 0.0;
  }

  /// Recomputes the cached rotation and bounds after position or angle changed.
  void updateCache();
  /// Recomputes only the cached rotation (one sine and cosine); the bounds wait for updateCache.
  void updateRotation() { rotation = impulse2d::rotation(angle); }
  /// Turns the body by a small angle without trigonometry, as the position pass does many times a
  /// step: (cos, sin) moves along its tangent by `angleChange` and is put back on the unit circle
  /// (Box2D v3's b2IntegrateRotation; exact to angleChange³/3). The bounds are left for the
  /// world's updateCache after the pass.
  void turnBy(double angleChange) {
    angle += angleChange;
    const double c = rotation(0, 0) - angleChange * rotation(1, 0);
    const double s = rotation(1, 0) + angleChange * rotation(0, 0);
    const double inverseLength = 1.0 / std::sqrt(c * c + s * s);
    rotation << c * inverseLength, -s * inverseLength, s * inverseLength, c * inverseLength;
  }

  /// Kinetic energy ½ m v² + ½ I ω² (J); zero for a static body.
  double kineticEnergy() const;
  /// Potential energy in the gravity field g: −m g·x (J); zero for a static body, wherever it is.
  double potentialEnergy(const Vec2& gravity) const;
};

/// A body of the given shape, type and density (kg/m^2), with mass and inertia computed from the
/// shape; static bodies get zero inverse mass and inertia whatever the density.
Body makeBody(const std::string& name, BodyType type, Shape shape, double density,
              const Vec2& position, double angle);

}  // namespace impulse2d
