// The one place i2d turns a scene into a runnable simulation, whichever engine runs it.
#pragma once

#include <memory>

#include "impulse2d/scene.h"
#include "impulse2d/simulation.h"

namespace i2d {

/// Our world with the scene's solver; throws RunFailure for a solver that is not built.
std::unique_ptr<impulse2d::Simulation> makeSimulation(const impulse2d::Scene& scene);

}  // namespace i2d
