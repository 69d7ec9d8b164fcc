// Loading a scene and applying the command line's overrides.
#include "scene_setup.h"

#include <algorithm>

#include "failures.h"
#include "impulse2d/collide.h"
#include "impulse2d/presets.h"
#include "impulse2d/scene/scene.h"
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
  for (const std::string& assignment : options.settings) impulse2d::applySetting(scene, assignment);
  if (options.steps) scene.steps = *options.steps;
  if (options.dt) scene.world.dt = *options.dt;
}

impulse2d::SceneFile loadScene(const SceneOptions& options) {
  impulse2d::SceneFile scene = impulse2d::loadSceneFile(options.scenePath);
  applyOverrides(options, scene);
  impulse2d::checkSceneSize(scene, options.scenePath);
  return scene;
}

double allowedOverlap(const impulse2d::Scene& scene) {
  const impulse2d::SolverSettings& settings = scene.solverSettings;
  if (scene.solver == "sequential") return settings.sequential.targets.allowedPenetration;
  if (scene.solver == "reference") return settings.reference.targets.allowedPenetration;
  if (scene.solver == "micro") return settings.micro.positionEpsilon;
  return impulse2d::ContactTargetSettings{}.allowedPenetration;  // Box2D's linear slop, 5 mm
}

namespace {

/// The deepest overlap of two bodies (m), 0 when they do not touch.
double overlapOf(const impulse2d::Body& a, const impulse2d::Body& b) {
  impulse2d::Manifold manifold;
  const int points = impulse2d::collide(a, b, 0.0, manifold);
  double deepest = 0.0;
  for (int i = 0; i < points; ++i) deepest = std::max(deepest, manifold.points[i].penetration);
  return deepest;
}

}  // namespace

int warnAboutStartingOverlaps(const impulse2d::Scene& scene, std::ostream& out) {
  const std::vector<impulse2d::Body> bodies = impulse2d::buildBodies(scene);
  const double allowed = allowedOverlap(scene);
  int pairs = 0;
  for (size_t i = 0; i < bodies.size(); ++i) {
    for (size_t j = i + 1; j < bodies.size(); ++j) {
      const impulse2d::Body& a = bodies[i];
      const impulse2d::Body& b = bodies[j];
      if ((a.isStatic() && b.isStatic()) || !a.bounds.overlaps(b.bounds)) continue;
      const double depth = overlapOf(a, b);
      if (depth <= allowed) continue;
      out << "warning: bodies " << a.name << " and " << b.name << " start overlapping by " << depth
          << " m, more than the allowed penetration of " << allowed
          << " m; the solver will push them apart\n";
      ++pairs;
    }
  }
  return pairs;
}

}  // namespace i2d
