// Figures of a whole simulation: energy, penetration, contact count.
#include "impulse2d/simulation.h"

#include <algorithm>

namespace impulse2d {

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
