// Scene -> simulation: the core solvers through buildWorld; Box2D is not wired in yet.
#include "simulation_factory.h"

#include "failures.h"

namespace i2d {

std::unique_ptr<impulse2d::Simulation> makeSimulation(const impulse2d::Scene& scene) {
  if (scene.solver == "box2d") throw RunFailure("solver box2d is not built yet");
  return impulse2d::buildWorld(scene);
}

}  // namespace i2d
