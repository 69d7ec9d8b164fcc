// Figures of a whole simulation: energy, penetration, contact count.
#include "impulse2d/simulation.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

NonFiniteState::NonFiniteState(const std::string& body, long step, const std::string& solver)
    : std::runtime_error("body " + body + " became non-finite at step " + std::to_string(step) +
                         " (solver " + solver + ")") {}

bool hasFiniteState(const Body& body, const Vec2& gravity) {
  return body.position.allFinite() && std::isfinite(body.angle) && body.velocity.allFinite() &&
         std::isfinite(body.angularVelocity) && std::isfinite(body.kineticEnergy()) &&
         std::isfinite(body.potentialEnergy(gravity));
}

void stopAtNonFiniteBody(const std::vector<Body>& bodies, const Vec2& gravity, long step,
                         const std::string& solver) {
  for (const Body& body : bodies) {
    if (!body.isStatic() && !hasFiniteState(body, gravity)) {
      throw NonFiniteState(body.name, step, solver);
    }
  }
}

double kineticEnergy(const Simulation& simulation) {
  double energy = 0.0;
  for (const Body& body : simulation.bodies()) energy += body.kineticEnergy();
  return energy;
}

double potentialEnergy(const Simulation& simulation) {
  double energy = 0.0;
  for (const Body& body : simulation.bodies()) {
    energy += body.potentialEnergy(simulation.settings().gravity);
  }
  return energy;
}

double largestPenetration(const Simulation& simulation) {
  double deepest = 0.0;
  for (const Manifold& manifold : simulation.manifolds()) {
    for (int i = 0; i < manifold.pointCount; ++i) {
      deepest = std::max(deepest, manifold.points[i].penetration);
    }
  }
  return deepest;
}

int contactPointCount(const Simulation& simulation) {
  int count = 0;
  for (const Manifold& manifold : simulation.manifolds()) count += manifold.pointCount;
  return count;
}

}  // namespace impulse2d
