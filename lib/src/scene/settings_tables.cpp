// The [world], [solver] and [render] tables of a scene file, and the range of every numeric
// setting they may hold.
#include <algorithm>
#include <sstream>

#include "impulse2d/presets.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/scene/setting_ranges.h"
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
  readSettingsTable(*world, describe(scene.world), {"steps", "solver"}, "[world]", "world");
  if (const toml::node* steps = world->get("steps")) {
    scene.steps = readSettingInteger(*steps, "steps", "world");
  }
  readSolverName(*world, scene);
}

void readSolver(const toml::table& root, Scene& scene) {
  const toml::table* solver = findTable(root, "solver");
  if (!solver) return;
  rejectRetiredKeys(*solver, scene.solver);
  readPreset(*solver, scene);
  readSettingsTable(*solver, solverSettingFields(scene.solverSettings, scene.solver), {"preset"},
                    "[solver] for solver '" + scene.solver + "'", scene.solver);
}

namespace {

/// [render] view = [[x0, y0], [x1, y1]]: the lower left and upper right corners, x0 < x1, y0 < y1.
Aabb readWindow(const toml::node& node) {
  const toml::array* corners = node.as_array();
  if (!corners || corners->size() != 2) {
    fail(node.source(),
         "'view' must be the lower left and upper right corners [[x0, y0], [x1, y1]] in metres");
  }
  const Aabb window{readVec2((*corners)[0], "view"), readVec2((*corners)[1], "view")};
  if (!(window.lower.x() < window.upper.x() && window.lower.y() < window.upper.y())) {
    fail(node.source(),
         "'view' must go from its lower left corner [x0, y0] to its upper right "
         "[x1, y1], with x0 < x1 and y0 < y1");
  }
  return window;
}

}  // namespace

void readRender(const toml::table& root, SceneFile& scene) {
  const toml::table* render = findTable(root, "render");
  if (!render) return;
  rejectUnknownKeys(*render, {"width", "height", "centre", "scale", "view", "follow", "zoom"},
                    "[render]");
  if (const toml::node* width = render->get("width")) {
    scene.view.width = readInteger(*width, "width", 1, kMostFrameSide);
  }
  if (const toml::node* height = render->get("height")) {
    scene.view.height = readInteger(*height, "height", 1, kMostFrameSide);
  }
  const std::string pixels = checkFramePixels(scene.view.width, scene.view.height, 1);
  if (!pixels.empty()) fail(render->source(), pixels);
  if (const toml::node* centre = render->get("centre")) {
    scene.view.centre = readVec2(*centre, "centre");
  }
  if (const toml::node* scale = render->get("scale")) {
    scene.view.scale = readNumber(*scale, "scale", Range::Positive);
  }
  if (const toml::node* window = render->get("view")) scene.view.window = readWindow(*window);
  if (const toml::node* follow = render->get("follow")) {
    scene.view.follow = readString(*follow, "follow");
  }
  if (const toml::node* zoom = render->get("zoom")) {
    scene.view.zoom = readNumber(*zoom, "zoom", Range::Positive);
  }
}

void checkFollowedBody(const toml::table& root, const SceneFile& scene) {
  if (!scene.view.follow) return;
  for (const BodyDef& body : scene.bodies) {
    if (body.name == *scene.view.follow) return;
  }
  const toml::table* render = findTable(root, "render");
  fail(render && render->get("follow") ? render->get("follow")->source() : root.source(),
       "the view follows body '" + *scene.view.follow + "', which the scene does not have");
}

}  // namespace impulse2d::scene_file

namespace impulse2d {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// The reason given for the upper bound of a count that multiplies the work of a step.
const std::string kWork = "more would let one run take hours";
/// The reason given for Lemke's island size: a pivot costs points², a path points³.
const std::string kCubic = "Lemke's pivots on a larger island would take minutes each step";

struct RangeEntry {
  const char* scope;  ///< "world", a solver's name, or "rigid" for sequential and reference
  const char* key;
  SettingRange range;
};

SettingRange closed(double lowest, double highest, const std::string& bound = {}) {
  return {lowest, true, highest, bound};
}

SettingRange aboveZero(double highest, const std::string& bound = {}) {
  return {0.0, false, highest, bound};
}

/// Every numeric setting's range (docs/scene-format.md lists the same).
const std::vector<RangeEntry>& rangeTable() {
  static const std::vector<RangeEntry> table = {
      {"world", "dt", closed(1e-6, 1.0)},
      {"world", "contact_margin", closed(0.0, 1.0)},
      {"world", "substeps", closed(1, 1000, kWork)},
      {"world", "sleep_linear_speed", closed(0.0, 100.0)},
      {"world", "sleep_angular_speed", closed(0.0, 100.0)},
      {"world", "time_to_sleep", closed(0.0, 1e6)},
      {"world", "speed_up_share", closed(0.0, 1.0)},
      {"world", "steps", closed(0, 10000000, kWork)},
      {"micro", "restitution_velocity_limit", closed(0.0, 1000.0)},
      {"micro", "velocity_epsilon", closed(0.0, 1.0)},
      {"micro", "position_epsilon", closed(0.0, 1.0)},
      {"micro", "velocity_iterations_per_contact", closed(0, 10000, kWork)},
      {"micro", "position_iterations_per_contact", closed(0, 1000, kWork)},
      {"micro", "angular_move_limit", closed(0.0, 10.0)},
      {"micro", "singular_matrix_tolerance", closed(0.0, 1.0)},
      {"micro", "touching_tolerance", closed(0.0, 0.1)},
      {"micro", "progress_rounds", closed(1, 10000)},
      {"micro", "minimum_progress", closed(0.0, 1.0)},
      {"micro", "velocity_iterations_per_contact_limit", closed(0, 10000, kWork)},
      {"micro", "pair_condition_limit", closed(1.0, 1e12)},
      {"sequential", "velocity_iterations", closed(0, 10000, kWork)},
      {"sequential", "converged_impulse_change", closed(0.0, 1000.0)},
      {"rigid", "bias_factor", closed(0.0, 1.0)},
      {"rigid", "allowed_penetration", closed(0.0, 1.0)},
      {"rigid", "max_bias_velocity", closed(0.0, 1000.0)},
      {"rigid", "restitution_velocity_threshold", closed(0.0, 1000.0)},
      {"rigid", "position_iterations", closed(0, 1000, kWork)},
      {"rigid", "position_correction_factor", closed(0.0, 1.0)},
      {"rigid", "max_position_correction", closed(0.0, 10.0)},
      {"rigid", "block_condition_limit", closed(1.0, 1e12)},
      {"reference", "residual_tolerance", aboveZero(1.0)},
      {"reference", "max_pivots", closed(1, 1000000, kWork)},
      {"reference", "max_pivots_per_variable", closed(1, 100, kWork)},
      {"reference", "pivot_tolerance", closed(0.0, 1.0)},
      {"reference", "tie_tolerance", closed(0.0, 1.0)},
      {"reference", "degeneracy_perturbation", closed(0.0, 1e-3)},
      {"reference", "covering_retries", closed(0, 100, kWork)},
      {"reference", "harris_tolerance", closed(0.0, 1.0)},
      {"reference", "lemke_island_points", closed(0, 500, kCubic)},
      {"reference", "lemke_fallback_points", closed(0, 500, kCubic)},
      {"reference", "guess_sweeps", closed(0, 10000, kWork)},
      {"reference", "max_guess_sweeps", closed(0, 10000, kWork)},
      {"reference", "kept_rounds", closed(0, 10000, kWork)},
      {"reference", "kept_tolerance", closed(0.0, 1.0)},
      {"reference", "refactor_after_solves", closed(0, 100000)},
      {"reference", "diagonal_pivot_threshold", closed(0.0, 1.0)},
      {"reference", "max_factorizations", closed(0, 10000, kWork)},
      {"reference", "block_failures", closed(0, 10000)},
      {"reference", "regularization", closed(0.0, 1.0)},
      {"reference", "refinements", closed(0, 100, kWork)},
      {"reference", "refinement_tolerance", closed(0.0, 1.0)},
      {"reference", "flip_tolerance", closed(0.0, 1.0)},
      {"box2d", "velocity_iterations", closed(0, 1000, kWork)},
      {"box2d", "position_iterations", closed(0, 1000, kWork)},
      {"soft_step", "substeps", closed(1, 1000, kWork)},
      {"soft_step", "contact_hertz", aboveZero(1e4)},
      {"soft_step", "max_hertz_per_substep_rate", aboveZero(1.0)},
      {"soft_step", "damping_ratio", closed(0.0, 1e4)},
      {"soft_step", "static_hertz_factor", aboveZero(100.0)},
      {"soft_step", "max_push_velocity", closed(0.0, 1000.0)},
      {"soft_step", "recycle_distance", closed(0.0, 1.0)},
      {"soft_step", "recycle_largest_turn", closed(0.0, kPi)},
      {"soft_step", "restitution_velocity_threshold", closed(0.0, 1000.0)},
      {"soft_step", "pair_restitution_condition_limit", closed(1.0, 1e12)},
  };
  return table;
}

bool inScope(const std::string& entryScope, const std::string& scope) {
  return entryScope == scope ||
         (entryScope == "rigid" && (scope == "sequential" || scope == "reference"));
}

std::string formatBound(double value, bool integer) {
  std::ostringstream text;
  if (integer) {
    text << static_cast<long long>(value);
  } else {
    text << value;
  }
  return text.str();
}

}  // namespace

std::string checkRunSize(long steps, long dynamicBodies, int substeps) {
  const double work = double(steps) * double(dynamicBodies) * double(substeps);
  if (work <= kMostBodySteps) return {};
  std::ostringstream text;
  text << "steps × dynamic bodies × substeps = " << steps << " × " << dynamicBodies << " × "
       << substeps << " = " << work << " is more than the limit of " << kMostBodySteps
       << " (a run that long would take hours); take fewer steps";
  return text.str();
}

std::string checkFramePixels(int width, int height, int panels) {
  const long pixels = long(width) * long(height) * long(panels);
  if (pixels <= kMostFramePixels) return {};
  std::string frame = std::to_string(width) + " × " + std::to_string(height);
  if (panels > 1) frame = std::to_string(panels) + " panels of " + frame;
  return "a frame of " + frame + " = " + std::to_string(pixels) +
         " pixels is more than the limit of " + std::to_string(kMostFramePixels) +
         " (16384 × 4096); make the [render] width or height smaller";
}

std::optional<SettingRange> findSettingRange(const std::string& scope, const std::string& key) {
  for (const RangeEntry& entry : rangeTable()) {
    if (entry.key == key && inScope(entry.scope, scope)) return entry.range;
  }
  return std::nullopt;
}

bool inSettingRange(double value, const SettingRange& range) {
  const bool aboveLowest = range.lowestIncluded ? value >= range.lowest : value > range.lowest;
  return aboveLowest && value <= range.highest;
}

std::string describeSettingRange(const SettingRange& range, bool integer, double value) {
  std::string text = std::string("must be ") + (integer ? "an integer " : "") + "in " +
                     (range.lowestIncluded ? "[" : "(") + formatBound(range.lowest, integer) +
                     ", " + formatBound(range.highest, integer) + "]";
  if (value > range.highest && !range.bound.empty()) text += " (" + range.bound + ")";
  return text;
}

}  // namespace impulse2d
