// Loading a scene and applying the command line's overrides.
#include "scene_setup.h"

#include "failures.h"
#include "impulse2d/presets.h"
#include "impulse2d/scene/scene_file.h"

namespace i2d {

void applyOverrides(const SceneOptions& options, impulse2d::SceneFile& scene) {
  if (options.solver && *options.solver != scene.solver) {
    scene.solver = *options.solver;
    scene.preset.clear();  // the file's preset was the other solver's
  }
  if (options.preset) {
    const impulse2d::Preset* preset = impulse2d::findPreset(scene.solver, *options.preset);
    if (!preset) {
      throw UsageError("unknown preset '" + *options.preset + "' for solver '" + scene.solver +
                       "' (known: " + impulse2d::presetNames(scene.solver) + "; see i2d presets)");
    }
    preset->apply(scene.solverSettings);
    scene.preset = preset->name;
  }
  for (const std::string& assignment : options.settings) {
    try {
      impulse2d::applySetting(scene, assignment);
    } catch (const impulse2d::SceneError& error) {
      throw UsageError(error.what());
    }
  }
  if (options.steps) scene.steps = *options.steps;
  if (options.dt) scene.world.dt = *options.dt;
}

impulse2d::SceneFile loadScene(const SceneOptions& options) {
  impulse2d::SceneFile scene = impulse2d::loadSceneFile(options.scenePath);
  applyOverrides(options, scene);
  return scene;
}

}  // namespace i2d
