// Loading a scene and applying the command line's overrides.
#include "scene_setup.h"

#include "failures.h"
#include "impulse2d/scene/scene_file.h"

namespace i2d {

void applyOverrides(const SceneOptions& options, impulse2d::SceneFile& scene) {
  if (options.solver) scene.solver = *options.solver;
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
  impulse2d::checkSceneSize(scene, options.scenePath);
  return scene;
}

}  // namespace i2d
