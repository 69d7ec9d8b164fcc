// The [world], [solver] and [render] tables of a scene file.
#include <algorithm>

#include "impulse2d/presets.h"
#include "impulse2d/scene/scene_file.h"
#include "scene_tables.h"
#include "toml_reading.h"

namespace impulse2d::scene_file {
namespace {

const toml::table* findTable(const toml::table& root, std::string_view key) {
  const toml::node* node = root.get(key);
  return node ? &readTable(*node, key) : nullptr;
}

void readSolverName(const toml::table& world, Scene& scene) {
  const toml::node* node = world.get("solver");
  if (!node) return;
  const std::string name = readString(*node, "solver");
  const std::vector<std::string> known = sceneSolverNames();
  if (std::find(known.begin(), known.end(), name) == known.end()) {
    fail(node->source(), "unknown solver '" + name + "' (known: " + joinNames(known) + ")");
  }
  scene.solver = name;
}

/// `[solver] preset = "box2d_2_4"`: the solver's settings become the published method's
/// (presets.h); keys after it still apply.
void readPreset(const toml::table& solver, Scene& scene) {
  const toml::node* node = solver.get("preset");
  if (!node) return;
  const std::string name = readString(*node, "preset");
  const Preset* preset = findPreset(scene.solver, name);
  if (!preset) {
    fail(node->source(), "unknown preset '" + name + "' for solver '" + scene.solver +
                             "' (known: " + presetNames(scene.solver) + "; i2d presets lists all)");
  }
  preset->apply(scene.solverSettings);
  scene.preset = name;
}

/// A key a scene file may no longer use, and what to write instead.
struct RetiredKey {
  const char* solver;
  const char* key;
  const char* hint;
};

constexpr RetiredKey kRetiredKeys[] = {
    {"micro", "warm_start", "is now 'warm_starting', its name in every method"},
    {"soft_step", "recycle_round_normals",
     "is now 'renew_round_normals', with its meaning turned so that true turns the idea on: "
     "recycle_round_normals = X is renew_round_normals = not X"},
    {"soft_step", "load_scaled_stiffness",
     "was removed: it made results worse (docs/soft-step.md, \"Removed switches\")"},
    {"soft_step", "load_acceleration",
     "was removed with load_scaled_stiffness (docs/soft-step.md, \"Removed switches\")"},
    {"soft_step", "block_normals",
     "was removed: it made results worse (docs/soft-step.md, \"Removed switches\")"},
    {"soft_step", "block_normals_condition_limit",
     "was removed with block_normals (docs/soft-step.md, \"Removed switches\")"},
};

/// A renamed or removed key is one located error naming what to write instead.
void rejectRetiredKeys(const toml::table& solver, const std::string& solverName) {
  for (const RetiredKey& retired : kRetiredKeys) {
    if (solverName != retired.solver) continue;
    if (const toml::node* node = solver.get(retired.key)) {
      fail(node->source(), "'" + std::string(retired.key) + "' " + retired.hint);
    }
  }
}

}  // namespace

void readWorld(const toml::table& root, Scene& scene) {
  const toml::table* world = findTable(root, "world");
  if (!world) return;
  readSettingsTable(*world, describe(scene.world), {"steps", "solver"}, "[world]");
  readOptional(*world, "steps", scene.steps, 0);
  readSolverName(*world, scene);
}

void readSolver(const toml::table& root, Scene& scene) {
  const toml::table* solver = findTable(root, "solver");
  if (!solver) return;
  rejectRetiredKeys(*solver, scene.solver);
  readPreset(*solver, scene);
  readSettingsTable(*solver, solverSettingFields(scene.solverSettings, scene.solver), {"preset"},
                    "[solver] for solver '" + scene.solver + "'");
}

void readRender(const toml::table& root, SceneFile& scene) {
  const toml::table* render = findTable(root, "render");
  if (!render) return;
  rejectUnknownKeys(*render, {"width", "height", "centre", "scale"}, "[render]");
  readOptional(*render, "width", scene.view.width, 1);
  readOptional(*render, "height", scene.view.height, 1);
  if (const toml::node* centre = render->get("centre")) {
    scene.view.centre = readVec2(*centre, "centre");
  }
  if (const toml::node* scale = render->get("scale")) {
    scene.view.scale = readNumber(*scale, "scale", Range::Positive);
  }
}

}  // namespace impulse2d::scene_file
