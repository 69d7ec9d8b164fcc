// Fuzz target for the scene loader: any bytes given to parseScene either load or are rejected
// with a SceneError. Any other exception, a crash, a sanitizer report or a hang is a bug, and so
// is a scene that loads but cannot be simulated (a non-finite state, or a body without a positive,
// finite mass and inverse mass): the loader promises to reject those (docs/scene-format.md).
// A small scene that loads is then stepped a few times under its solver, Box2D's included, its
// settings and loads being whatever the fuzzer wrote inside their ranges: each step ends finite
// or stops with NonFiniteState or a reference solve without an answer, and a shape Box2D cannot
// take is refused (std::invalid_argument naming Box2D's limit) before Box2D asserts on it.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

#include "impulse2d/box2d/box2d_simulation.h"
#include "impulse2d/scene/scene.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/solvers/reference_solver.h"
#include "impulse2d/world.h"

namespace {

void require(bool condition, const char* what) {
  if (condition) return;
  std::fprintf(stderr, "scene_loader_fuzzer: a loaded scene breaks its promise: %s\n", what);
  std::abort();
}

bool finiteState(const impulse2d::Body& body) {
  return body.position.allFinite() && std::isfinite(body.angle) && body.velocity.allFinite() &&
         std::isfinite(body.angularVelocity) && body.rotation.allFinite();
}

bool positiveAndFinite(double value) {
  return std::isfinite(value) && value > 0.0;
}

bool positiveFiniteMass(const impulse2d::Body& body) {
  return positiveAndFinite(body.mass) && positiveAndFinite(body.inverseMass) &&
         positiveAndFinite(body.inertia) && positiveAndFinite(body.inverseInertia);
}

void checkSimulable(const impulse2d::Scene& scene) {
  for (const impulse2d::Body& body : impulse2d::buildBodies(scene)) {
    require(finiteState(body), "a body's state is not finite");
    require(body.isStatic() || positiveFiniteMass(body),
            "a body's mass is not positive and finite");
  }
}

/// Scenes this small are stepped this often: enough for a load to overflow or a solver setting
/// to act, few enough that every input stays quick.
constexpr std::size_t kSteppedBodies = 12;
constexpr int kSteps = 4;

/// Box2D's simulation of the scene, or none when it refuses a shape Box2D cannot take.
std::unique_ptr<impulse2d::Simulation> makeBox2dSimulation(const impulse2d::Scene& scene) {
  try {
    return impulse2d::makeSimulation(scene);
  } catch (const std::invalid_argument& refused) {
    require(std::string_view(refused.what()).find("Box2D") != std::string_view::npos,
            "Box2D refused a scene without naming its limit");
    return nullptr;
  }
}

void stepBriefly(const impulse2d::Scene& scene) {
  if (scene.bodies.size() > kSteppedBodies) return;
  try {
    const std::unique_ptr<impulse2d::Simulation> simulation =
        scene.solver == impulse2d::kBox2dName ? makeBox2dSimulation(scene)
                                              : impulse2d::makeSimulation(scene);
    if (!simulation) return;
    for (int step = 0; step < kSteps; ++step) {
      simulation->step();
      for (const impulse2d::Body& body : simulation->bodies()) {
        require(impulse2d::hasFiniteState(body, simulation->settings().gravity),
                "a step ended with a non-finite body and did not stop");
      }
    }
  } catch (const impulse2d::NonFiniteState&) {
    // A load or speed beyond a double: the step stops at the first non-finite body.
  } catch (const impulse2d::ReferenceSolveFailure&) {
    // The reference found no exact answer for a step: a clean stop with its reason.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const impulse2d::SceneFile scene = impulse2d::parseScene(text, "fuzz.toml");
    checkSimulable(scene);
    stepBriefly(scene);
  } catch (const impulse2d::SceneError&) {
    // A rejected scene, with its location: the expected outcome for most inputs.
  }
  return 0;
}
