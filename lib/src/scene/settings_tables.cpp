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
  const char* solver;  ///< the solver whose [solver] table had it, or "world" for [world]
  const char* key;
  const char* hint;
};

constexpr RetiredKey kRetiredKeys[] = {
    {"micro", "restitution_velocity_limit", "is now 'restitution_threshold', Box2D's word"},
    {"sequential", "restitution_velocity_threshold",
     "is now 'restitution_threshold', Box2D's word"},
    {"reference", "restitution_velocity_threshold", "is now 'restitution_threshold', Box2D's word"},
    {"soft_step", "restitution_velocity_threshold", "is now 'restitution_threshold', Box2D's word"},
    {"sequential", "max_bias_velocity", "is now 'max_push_velocity', Box2D's word"},
    {"reference", "max_bias_velocity", "is now 'max_push_velocity', Box2D's word"},
    {"soft_step", "pair_restitution",
     "is now 'block_restitution': a two-point contact solved together is a block"},
    {"soft_step", "pair_restitution_condition_limit",
     "is now 'block_condition_limit', as in the other methods"},
    {"micro", "warm_start", "is now 'warm_starting', as in soft step"},
    {"soft_step", "recycle_round_normals",
     "is now a value of 'recycling': recycle_round_normals = false is recycling = \"refined\", "
     "true is \"box2d_v3\""},
    {"soft_step", "load_scaled_stiffness",
     "was removed: it made results worse (docs/soft-step.md, \"Removed switches\")"},
    {"soft_step", "load_acceleration",
     "was removed with load_scaled_stiffness (docs/soft-step.md, \"Removed switches\")"},
    {"soft_step", "block_normals",
     "was removed: it made results worse (docs/soft-step.md, \"Removed switches\")"},
    {"soft_step", "block_normals_condition_limit",
     "was removed with block_normals (docs/soft-step.md, \"Removed switches\")"},
    {"micro", "pair_moves",
     "is now 'block_moves': a two-point contact solved together is a block, as in Box2D"},
    {"micro", "pair_condition_limit", "is now 'block_condition_limit', as in the other methods"},
    {"micro", "impulse_totals",
     "is now a value of 'impulses': impulse_totals = false is impulses = \"separate\", true is "
     "\"point_totals\" or more"},
    {"micro", "pair_impulses",
     "is now a value of 'impulses': pair_impulses = true is impulses = \"block\" (bounces "
     "point by point) or \"block_with_bounces\"; false is \"point_totals\""},
    {"micro", "pair_bounces",
     "is now a value of 'impulses': pair_bounces = true is impulses = \"block_with_bounces\", "
     "false is \"block\""},
    {"sequential", "accumulate_impulses",
     "is now a value of 'impulses': accumulate_impulses = false is impulses = \"clamped_each\", "
     "true is \"accumulated\" or \"warm_started\""},
    {"sequential", "warm_starting",
     "is now a value of 'impulses': warm_starting = true is impulses = \"warm_started\", false "
     "is \"accumulated\""},
    {"reference", "backtrack",
     "is now a value of 'cycling_safeguard': backtrack = true is cycling_safeguard = "
     "\"backtrack\", false is \"judice_pires\""},
    {"soft_step", "relax",
     "is now 'relaxation': relax = false is relaxation = \"off\", true is "
     "\"friction_in_relax\" (or \"friction_in_both\")"},
    {"soft_step", "friction_in_relax",
     "is now a value of 'relaxation': friction_in_relax = true is relaxation = "
     "\"friction_in_relax\", false is \"friction_in_both\""},
    {"soft_step", "contact_recycling",
     "is now 'recycling': contact_recycling = false is recycling = \"off\", true is "
     "\"refined\" (or \"box2d_v3\", v3's rule alone)"},
    {"soft_step", "recycle_within_found_distance",
     "is now a value of 'recycling': our rules beyond v3's are recycling = \"refined\", v3's "
     "alone \"box2d_v3\""},
    {"soft_step", "recycle_in_world_frame",
     "is now a value of 'recycling': our rules beyond v3's are recycling = \"refined\", v3's "
     "alone \"box2d_v3\""},
    {"soft_step", "renew_round_normals",
     "is now a value of 'recycling': our rules beyond v3's are recycling = \"refined\", v3's "
     "alone \"box2d_v3\""},
    {"reference", "pivot_tolerance",
     "is now the constant kPivotTolerance in lcp.cpp: it tells round-off from a pivot"},
    {"reference", "tie_tolerance",
     "is now the constant kTieTolerance in lcp.cpp: it tells round-off from a tie"},
    {"reference", "harris_tolerance",
     "is now the constant kHarrisTolerance in lcp.cpp: Harris's overshoot is round-off's size"},
    {"reference", "degeneracy_perturbation",
     "is now the constant kDegeneracyPerturbation in reference_solver.cpp: the retry's answer is "
     "checked anyway"},
    {"reference", "covering_retries",
     "is now the constant kCoveringRetries in reference_solver.cpp: each retry's answer is checked "
     "anyway"},
    {"reference", "max_guess_sweeps",
     "is now the constant kMaxGuessSweeps in active_set.cpp: the sweeps only guess; 'guess_sweeps' "
     "is still the least"},
    {"reference", "block_failures",
     "is now the constant kJudicePiresBlockFailures in active_set.cpp; 'cycling_safeguard' chooses "
     "the rule"},
    {"reference", "flip_tolerance",
     "is now the constant kFlipTolerance in active_set.cpp: it tells round-off from a violation"},
    {"reference", "kept_rounds",
     "is now the constant kKeptRounds in kept_factorization.cpp: it changes the cost, not the "
     "answer; 'keep_factors' turns kept factors off"},
    {"reference", "kept_tolerance",
     "is now the constant kKeptTolerance in kept_factorization.cpp: a solve on kept factors ends "
     "at round-off"},
    {"reference", "diagonal_pivot_threshold",
     "is now the constant kDiagonalPivotThreshold in kept_factorization.cpp: it keeps the "
     "factorization's symmetric fill-reducing order"},
    {"reference", "refinement_tolerance",
     "is now the constant kRefinementTolerance in kept_factorization.h; 'refinements' still caps "
     "the corrections"},
    {"world", "sleeping",
     "is now 'sleep': sleeping = false is sleep = \"off\", true is "
     "\"keep_speeding_up_awake\" (or \"box2d\", Box2D's rule alone)"},
    {"world", "keep_speeding_up_awake",
     "is now a value of 'sleep': keep_speeding_up_awake = true is sleep = "
     "\"keep_speeding_up_awake\", false is \"box2d\""},
};

/// A renamed or removed key is one located error naming what to write instead; `scope` is the
/// table's solver, or "world".
void rejectRetiredKeys(const toml::table& table, const std::string& scope) {
  for (const RetiredKey& retired : kRetiredKeys) {
    if (scope != retired.solver) continue;
    if (const toml::node* node = table.get(retired.key)) {
      fail(node->source(), "'" + std::string(retired.key) + "' " + retired.hint);
    }
  }
}

}  // namespace

void readWorld(const toml::table& root, Scene& scene) {
  const toml::table* world = findTable(root, "world");
  if (!world) return;
  rejectRetiredKeys(*world, "world");
  readSettingsTable(*world, describe(scene.world), {"steps", "solver"}, "[world]");
  if (const toml::node* steps = world->get("steps")) {
    scene.steps = readSettingInteger(*steps, "steps", findSettingRange("world", "steps"));
  }
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

/// `steps`, the one [world] key that is the scene's rather than WorldSettings'.
const SettingRange kStepsRange = closed(0, 10000000, "more would let one run take hours");

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
  if (scope == "world" && key == "steps") return kStepsRange;
  WorldSettings world;
  SolverSettings solvers;
  const std::vector<SettingField> fields =
      scope == "world" ? describe(world) : solverSettingFields(solvers, scope);
  for (const SettingField& field : fields) {
    if (field.name == key) return field.range;
  }
  return std::nullopt;
}

}  // namespace impulse2d
