// The benchmark scenes and method settings (benchmark_scenes.h).
#include "benchmark_scenes.h"

#include <stdexcept>

#include "impulse2d/presets.h"
#include "impulse2d/scene/scene_file.h"

using namespace impulse2d;

namespace benchmarks {

namespace {

/// The material of the field's benchmark boxes.
constexpr double kBoxFriction = 0.6;
constexpr double kGravity = -10.0;
/// m of ground beyond the pyramid's base on either side.
constexpr double kGroundMargin = 10.0;

}  // namespace

Scene shippedScene(const std::string& name) {
  Scene scene = loadSceneFile(IMPULSE2D_SOURCE_DIR "/demos/scenes/" + name + ".toml");
  scene.world.sleep = Sleep::Off;
  return scene;
}

double settledTime(const Scene& scene) {
  return scene.name == "rain" ? 4.0 : 1.0;
}

Scene pyramidScene(int rows) {
  Scene scene;
  scene.name = "pyramid" + std::to_string(rows);
  scene.world.gravity = Vec2(0.0, kGravity);
  scene.world.sleep = Sleep::Off;
  BodyDef ground;
  ground.name = "ground";
  ground.type = BodyType::Static;
  ground.shape = makeBox(rows + 2.0 * kGroundMargin, 1.0);
  ground.position = Vec2(0.0, -0.5);
  ground.friction = kBoxFriction;
  scene.bodies.push_back(ground);
  BodyDef box;
  box.friction = kBoxFriction;
  addPyramid(scene, rows, Vec2(1.0, 1.0), Vec2::Zero(), box);
  return scene;
}

std::vector<int> scalingFamilyRows() {
  return {4, 6, 9, 12, 14, 20, 28, 40, 56, 80, 99};
}

int pyramidBoxes(int rows) {
  return rows * (rows + 1) / 2;
}

std::string iterationKey(const std::string& solver) {
  if (solver == "micro") return "velocity_iterations_per_contact";
  if (solver == "reference") return "";
  if (solver == "soft_step") return "substeps";  // one biased and one relax sweep per substep
  return "velocity_iterations";                  // sequential and box2d
}

Scene withMethod(Scene scene, const std::string& solver, int iterations) {
  scene.solver = solver;
  scene.solverSettings = SolverSettings{};
  if (iterations > 0 && !iterationKey(solver).empty()) {
    applySetting(scene, "solver." + iterationKey(solver) + "=" + std::to_string(iterations));
  }
  // k sweeps means exactly k, as in Box2D: no early stop once converged (the defaults keep it).
  if (iterations > 0 && solver == "sequential") {
    applySetting(scene, "solver.converged_impulse_change=0");
  }
  // A cap of k impulses per point means at most k, as the lecture counts (the defaults go on
  // past the cap while the impulses still make progress).
  if (iterations > 0 && solver == "micro") {
    applySetting(scene, "solver.pass_cap_while_progressing=false");
  }
  return scene;
}

Scene withPreset(Scene scene, const std::string& name) {
  if (name.empty()) return scene;
  const Preset* preset = findPreset(scene.solver, name);
  if (!preset) throw std::invalid_argument("no preset '" + name + "' for " + scene.solver);
  preset->apply(scene.solverSettings);
  scene.preset = name;
  return scene;
}

}  // namespace benchmarks
