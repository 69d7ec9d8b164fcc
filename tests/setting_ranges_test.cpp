// The valid range of every numeric setting (setting_ranges.h): each is checked where a scene file
// or a --set writes it, refused with "key = value: must be in [a, b]", and the bounds on counts
// that multiply a run's work, on steps × bodies and on a frame's pixels are named when refused.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <type_traits>
#include <variant>

#include "i2d_process.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/scene/setting_ranges.h"
#include "scene_errors.h"

using namespace impulse2d;

namespace {

const std::string kBall = "[[body]]\nname = \"ball\"\nshape = \"circle\"\nradius = 0.5\n";

using scene_errors::errorOf;

/// The error of one --set on a scene of the named solver, or "" when it applies.
std::string errorOfSetting(const std::string& solver, const std::string& assignment) {
  return scene_errors::errorOfSetting(
      parseScene("[world]\nsolver = \"" + solver + "\"\n" + kBall, "ball.toml"), assignment);
}

/// Every numeric field the scope's settings struct names, with its current value.
std::vector<std::pair<std::string, double>> numericFields(const std::vector<SettingField>& fields) {
  std::vector<std::pair<std::string, double>> numbers;
  for (const SettingField& field : fields) {
    std::visit(
        [&](const auto& target) {
          using Target = std::decay_t<decltype(target)>;
          if constexpr (std::is_same_v<Target, double*> || std::is_same_v<Target, int*>) {
            numbers.emplace_back(field.name, double(*target));
          }
        },
        field.value);
  }
  return numbers;
}

/// "[1, 1000]" or "(0, 1]": the range as docs/scene-format.md writes it.
std::string interval(const SettingRange& range, bool integer) {
  const std::string text = describeSettingRange(range, integer, range.lowest);
  return text.substr(text.find_first_of("[("));
}

/// A field's default as the docs write it.
std::string defaultValue(const SettingField& field) {
  std::ostringstream text;
  std::visit(
      [&text](const auto& value) {
        using Value = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<Value, Vec2*>) {
          text << "[" << value->x() << ", " << value->y() << "]";
        } else if constexpr (std::is_same_v<Value, SettingChoice>) {
          text << '"' << value.current() << '"';
        } else {
          text << std::boolalpha << *value;
        }
      },
      field.value);
  return text.str();
}

std::string rangeColumn(const SettingField& field) {
  if (std::holds_alternative<bool*>(field.value)) return "bool";
  if (const auto* choice = std::get_if<SettingChoice>(&field.value)) {
    std::string names;
    for (const std::string& name : choice->names)
      names += (names.empty() ? "`" : ", `") + name + "`";
    return "one of " + names;
  }
  if (!field.range) return "finite";
  const bool integer = std::holds_alternative<int*>(field.value);
  return (integer ? "integer " : "") + interval(*field.range, integer);
}

/// The table docs/scene-format.md shows for one scope, from the settings' declarations.
std::string settingsTable(const std::string& scope, const std::vector<SettingField>& fields) {
  std::string table = "<!-- settings of " + scope + ", generated: see below -->\n" +
                      "| key | unit | default | range | meaning |\n|---|---|---|---|---|\n";
  for (const SettingField& field : fields) {
    table += "| `" + field.name + "` | " + (field.unit.empty() ? "—" : field.unit) + " | `" +
             defaultValue(field) + "` | " + rangeColumn(field) + " | " + field.meaning + " |\n";
  }
  return table + "<!-- end of the settings of " + scope + " -->\n";
}

/// Each scope's fields at their defaults: the world's, then each solver's.
std::vector<std::pair<std::string, std::vector<SettingField>>> defaultFields(
    WorldSettings& world, SolverSettings& solvers) {
  std::vector<std::pair<std::string, std::vector<SettingField>>> scopes = {
      {"world", describe(world)}};
  for (const std::string& solver : sceneSolverNames()) {
    scopes.emplace_back(solver, solverSettingFields(solvers, solver));
  }
  return scopes;
}

}  // namespace

TEST_CASE("every numeric setting of the world and of each method has a range holding its default",
          "[settings][ranges]") {
  SolverSettings solvers;
  WorldSettings world;
  std::vector<std::pair<std::string, std::vector<SettingField>>> scopes = {
      {"world", describe(world)}};
  for (const std::string& solver : sceneSolverNames()) {
    scopes.emplace_back(solver, solverSettingFields(solvers, solver));
  }
  MicroCollisionSettings lecture = MicroCollisionSettings::lecture();
  scopes.emplace_back("micro", describe(lecture));
  for (const auto& [scope, fields] : scopes) {
    for (const auto& [key, value] : numericFields(fields)) {
      INFO(scope << "." << key << " = " << value);
      const std::optional<SettingRange> range = findSettingRange(scope, key);
      REQUIRE(range);
      CHECK(inSettingRange(value, *range));
      CHECK(range->highest < 1e300);  // every number has an upper bound
    }
  }
}

// The tables are generated: I2D_WRITE_DOCS=1 tests/setting_ranges_test "[docs]" writes them into
// docs/scene-format.md, between the marker comments.
TEST_CASE("docs/scene-format.md's settings tables are the settings' declarations",
          "[settings][ranges][docs]") {
  const std::string path = IMPULSE2D_SOURCE_DIR "/docs/scene-format.md";
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  std::string docs = text.str();
  const std::string original = docs;
  WorldSettings world;
  SolverSettings solvers;
  for (const auto& [scope, fields] : defaultFields(world, solvers)) {
    const std::string table = settingsTable(scope, fields);
    const size_t begin = docs.find("<!-- settings of " + scope + ",");
    const std::string endMarker = "<!-- end of the settings of " + scope + " -->\n";
    const size_t end = docs.find(endMarker);
    INFO("docs/scene-format.md should hold:\n" << table);
    REQUIRE(begin != std::string::npos);
    REQUIRE(end != std::string::npos);
    docs.replace(begin, end + endMarker.size() - begin, table);
  }
  if (std::getenv("I2D_WRITE_DOCS") && docs != original) std::ofstream(path) << docs;
  CHECK(docs == original);
}

TEST_CASE("a setting outside its range is refused where it is written", "[settings][ranges]") {
  CHECK(errorOf("[world]\nsolver = \"soft_step\"\n[solver]\nsubsteps = 0\n" + kBall) ==
        "bad.toml:4:12: substeps = 0: must be an integer in [1, 1000]");
  CHECK(errorOf("[world]\nsolver = \"soft_step\"\n[solver]\ndamping_ratio = 1e300\n" + kBall) ==
        "bad.toml:4:17: damping_ratio = 1e+300: must be in [0, 10000]");
  CHECK(errorOfSetting("soft_step", "solver.contact_hertz=0") ==
        "--set:1:22: contact_hertz = 0: must be in (0, 10000]");
  CHECK(errorOfSetting("soft_step", "solver.recycle_distance=-1") ==
        "--set:1:25: recycle_distance = -1: must be in [0, 1]");
  CHECK(errorOfSetting("micro", "solver.minimum_progress=2") ==
        "--set:1:25: minimum_progress = 2: must be in [0, 1]");
  CHECK(errorOfSetting("micro", "solver.progress_rounds=0") ==
        "--set:1:24: progress_rounds = 0: must be an integer in [1, 10000]");
  CHECK(errorOfSetting("sequential", "world.contact_margin=5") ==
        "--set:1:22: contact_margin = 5: must be in [0, 1]");
}

TEST_CASE("a count that would make a run unbounded is refused naming its bound",
          "[settings][ranges][bounds]") {
  const std::string hours = " (more would let one run take hours)";
  CHECK(errorOf("[world]\nsubsteps = 1000000000\n" + kBall) ==
        "bad.toml:2:12: substeps = 1000000000: must be an integer in [1, 1000]" + hours);
  CHECK(errorOfSetting("micro", "solver.velocity_iterations_per_contact=2000000000") ==
        "--set:1:40: velocity_iterations_per_contact = 2000000000: must be an integer in "
        "[0, 10000]" +
            hours);
  CHECK(errorOfSetting("reference", "solver.max_pivots=2000000000") ==
        "--set:1:19: max_pivots = 2000000000: must be an integer in [1, 1000000]" + hours);
  CHECK(errorOfSetting("reference", "solver.lemke_island_points=1000000") ==
        "--set:1:28: lemke_island_points = 1000000: must be an integer in [0, 500] (Lemke's "
        "pivots on a larger island would take minutes each step)");
  CHECK(errorOfSetting("soft_step", "solver.substeps=1000000000") ==
        "--set:1:17: substeps = 1000000000: must be an integer in [1, 1000]" + hours);
  CHECK(errorOf("[world]\nsteps = 10000000\n[[pyramid]]\nrows = 40\nsize = [1, 1]\n"
                "base = [0, 0]\n") ==
        "bad.toml: steps × dynamic bodies × substeps = 10000000 × 820 × 1 = 8.2e+09 is more "
        "than the limit of 1e+08 (a run that long would take hours); take fewer steps");
}

TEST_CASE("a frame's pixels are refused when the scene is read, before anything is drawn",
          "[settings][ranges][pixels]") {
  CHECK(errorOf("[render]\nwidth = 100000\nheight = 1\n" + kBall) ==
        "bad.toml:2:9: 'width' must be <= 16384, not 100000");
  CHECK(errorOf("[render]\nwidth = 16000\nheight = 16000\n" + kBall) ==
        "bad.toml:1:1: a frame of 16000 × 16000 = 256000000 pixels is more than the limit of "
        "67108864 (16384 × 4096); make the [render] width or height smaller");
  CHECK(errorOf("[render]\nwidth = 16384\nheight = 4096\n" + kBall).empty());
  CHECK(checkFramePixels(8192, 4096, 3) ==
        "a frame of 3 panels of 8192 × 4096 = 100663296 pixels is more than the limit of "
        "67108864 (16384 × 4096); make the [render] width or height smaller");
}

TEST_CASE("i2d refuses an out-of-range setting with exit 3, and an out-of-range option with 2",
          "[settings][ranges][i2d]") {
  using namespace i2d_process;
  const Scratch scratch;
  const std::string scene = scratch / "soft.toml";
  writeFile(scene, "[world]\nsolver = \"soft_step\"\n[solver]\nsubsteps = 0\n" + kBall);
  const Outcome file = i2d("run " + scene, scratch);
  CHECK(file.exitCode == 3);
  CHECK(file.err == "error: " + scene + ":4:12: substeps = 0: must be an integer in [1, 1000]\n");

  const Outcome wide = i2d("run " + kScenes + "resting_box.toml --steps 100000000", scratch);
  CHECK(wide.exitCode == 2);
  CHECK(wide.err ==
        "error: --steps: must be an integer in [0, 10000000] (more would let one run "
        "take hours), not '100000000'\n");
  const Outcome panels = i2d("compare " + kScenes + "resting_box.toml --steps 2 --frames " +
                                 (scratch / "frames") + " --solvers micro,sequential",
                             scratch);
  CHECK(panels.exitCode == 0);
  writeFile(scratch / "wide.toml", "[render]\nwidth = 16384\nheight = 4096\n" + kBall);
  const Outcome widePanels = i2d("compare " + (scratch / "wide.toml") + " --frames " +
                                     (scratch / "frames") + " --solvers micro,sequential",
                                 scratch);
  CHECK(widePanels.exitCode == 3);
  CHECK(widePanels.err.find("2 panels of 16384 × 4096") != std::string::npos);
}
