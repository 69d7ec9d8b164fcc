// Figures of a whole simulation: energy, penetration, contact count.
#include "impulse2d/simulation.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "impulse2d/collide.h"

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

double deepestOverlap(const std::vector<Body>& bodies) {
  std::vector<Body> now = bodies;  // bounds brought up to the positions
  for (Body& body : now) body.updateCache();
  // Sweep along x: only bodies whose x ranges overlap are collided.
  std::vector<std::size_t> order(now.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return now[a].bounds.lower.x() < now[b].bounds.lower.x();
  });
  double deepest = 0.0;
  Manifold manifold;
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      if (now[order[j]].bounds.lower.x() > now[order[i]].bounds.upper.x()) break;
      // In scene order, as the world collides them.
      const Body& a = now[std::min(order[i], order[j])];
      const Body& b = now[std::max(order[i], order[j])];
      if ((a.isStatic() && b.isStatic()) || !a.bounds.overlaps(b.bounds)) continue;
      const int points = collide(a, b, 0.0, manifold);
      for (int k = 0; k < points; ++k) deepest = std::max(deepest, manifold.points[k].penetration);
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
