// Fuzz target for the scene loader: any bytes given to parseScene either load or are rejected
// with a SceneError. Any other exception, a crash, a sanitizer report or a hang is a bug, and so
// is a scene that loads but cannot be simulated (a non-finite state, or a body without a positive,
// finite mass and inverse mass): the loader promises to reject those (docs/scene-format.md).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "impulse2d/scene/scene.h"
#include "impulse2d/scene/scene_file.h"

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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    checkSimulable(impulse2d::parseScene(text, "fuzz.toml"));
  } catch (const impulse2d::SceneError&) {
    // A rejected scene, with its location: the expected outcome for most inputs.
  }
  return 0;
}
