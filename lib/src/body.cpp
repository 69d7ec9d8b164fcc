// Rigid body construction and the energy of one body.
#include "impulse2d/body.h"

namespace impulse2d {

void Body::updateCache() {
  rotation = impulse2d::rotation(angle);
  bounds = computeBounds(shape, position, rotation);
}

// A static body holds no energy: it has no mass, and −0 · g·x would be NaN for a ground placed
// so far away that g·x overflows.
double Body::kineticEnergy() const {
  if (isStatic()) return 0.0;
  return 0.5 * mass * velocity.squaredNorm() + 0.5 * inertia * angularVelocity * angularVelocity;
}

double Body::potentialEnergy(const Vec2& gravity) const {
  if (isStatic()) return 0.0;
  return -mass * gravity.dot(position);
}

Body makeBody(const std::string& name, BodyType type, Shape shape, double density,
              const Vec2& position, double angle) {
  Body body;
  body.name = name;
  body.type = type;
  body.shape = std::move(shape);
  body.position = position;
  body.angle = angle;
  if (type == BodyType::Dynamic) {
    const MassProperties mass = computeMass(body.shape, density);
    body.mass = mass.mass;
    body.inverseMass = 1.0 / mass.mass;
    body.inertia = mass.inertia;
    body.inverseInertia = 1.0 / mass.inertia;
  }
  body.updateCache();
  return body;
}

}  // namespace impulse2d
