// Scene files: reading the file, parsing the TOML, and the --set overrides.
#include "impulse2d/scene/scene_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "impulse2d/scene/setting_ranges.h"
#include "impulse2d/solver.h"
#include "scene_tables.h"
#include "toml_reading.h"

namespace impulse2d {
namespace {

toml::table parseToml(std::string_view text, const std::string& sourceName) {
  try {
    return toml::parse(text, std::string_view(sourceName));
  } catch (const toml::parse_error& error) {
    scene_file::fail(error.source(), std::string(error.description()));
  }
}

// The scene's name names its output directories and files, so it may not be "." or ".." (the
// stems of "..toml" and "...toml"), which would put them beside the directory asked for.
std::string sceneName(const std::string& sourceName) {
  const std::string stem = std::filesystem::path(sourceName).stem().string();
  return stem.empty() || stem == "." || stem == ".." ? Scene().name : stem;
}

bool isBareWord(std::string_view text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '-';
  });
}

/// "section.key=value" as TOML, the value quoted when it is a bare word that is no TOML value.
toml::table parseAssignment(const std::string& assignment, size_t equals) {
  const std::string source = "--set";
  try {
    return toml::parse(assignment, std::string_view(source));
  } catch (const toml::parse_error& error) {
    const std::string value = assignment.substr(equals + 1);
    if (!isBareWord(value)) scene_file::fail(error.source(), std::string(error.description()));
  }
  return parseToml(assignment.substr(0, equals + 1) + "\"" + assignment.substr(equals + 1) + "\"",
                   source);
}

}  // namespace

SceneError::SceneError(const std::string& source, int line, int column, const std::string& message)
    : std::runtime_error(source + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                         message),
      source_(source),
      line_(line),
      column_(column),
      message_(message) {}

SceneError::SceneError(const std::string& source, const std::string& message)
    : std::runtime_error(source + ": " + message), source_(source), message_(message) {}

std::vector<std::string> sceneSolverNames() {
  std::vector<std::string> names = solverNames();
  if (std::find(names.begin(), names.end(), "box2d") == names.end()) names.push_back("box2d");
  return names;
}

std::vector<SettingField> solverSettingFields(SolverSettings& settings, const std::string& solver) {
  if (solver == "micro") return describe(settings.micro);
  if (solver == "sequential") return describe(settings.sequential);
  if (solver == "reference") return describe(settings.reference);
  if (solver == "soft_step") return describe(settings.softStep);
  if (solver == "box2d") return describe(settings.box2d);
  return {};
}

SceneFile loadSceneFile(const std::string& path) {
  if (std::filesystem::is_directory(path)) throw SceneError(path, "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path, "cannot read the file: " + std::string(std::strerror(errno)));
  // Read to one byte past the limit: a device such as /dev/zero never ends.
  std::string text(kLargestSceneFileBytes + 1, '\0');
  in.read(text.data(), std::streamsize(text.size()));
  text.resize(std::size_t(in.gcount()));
  if (text.size() > kLargestSceneFileBytes) {
    throw SceneError(path, "is larger than " + std::to_string(kLargestSceneFileBytes >> 20) +
                               " MiB, the most a scene file may hold");
  }
  return parseScene(text, path);
}

SceneFile parseScene(std::string_view text, const std::string& sourceName) {
  const toml::table root = parseToml(text, sourceName);
  if (root.empty()) throw SceneError(sourceName, 1, 1, "scene file is empty");
  scene_file::rejectUnknownKeys(root, {"world", "solver", "render", "body", "stack", "pyramid"},
                                "the scene file");
  SceneFile scene;
  scene.name = sceneName(sourceName);
  scene_file::readWorld(root, scene);
  scene_file::readSolver(root, scene);
  scene_file::readRender(root, scene);
  scene_file::readBodies(root, scene);
  scene_file::checkFollowedBody(root, scene);
  if (scene.bodies.empty()) {
    throw SceneError(sourceName, 1, 1,
                     "scene has no bodies (add [[body]], [[stack]] or [[pyramid]])");
  }
  checkSceneSize(scene, sourceName);
  return scene;
}

void checkSceneSize(const Scene& scene, const std::string& sourceName) {
  const auto dynamic =
      std::count_if(scene.bodies.begin(), scene.bodies.end(),
                    [](const BodyDef& body) { return body.type == BodyType::Dynamic; });
  const int solverSubsteps =
      scene.solver == "soft_step" ? scene.solverSettings.softStep.substeps : 1;
  const std::string refused =
      checkRunSize(scene.steps, long(dynamic), scene.world.substeps * solverSubsteps);
  if (!refused.empty()) throw SceneError(sourceName, refused);
}

bool isSettingAssignment(const std::string& assignment) {
  const size_t equals = assignment.find('=');
  const size_t dot = assignment.find('.');
  return equals != std::string::npos && dot != std::string::npos && dot < equals;
}

namespace {

/// The parsed "section.key=value", its section one of `sections`.
toml::table parseSetting(const std::string& assignment, const std::vector<std::string>& sections) {
  if (!isSettingAssignment(assignment)) {
    throw SceneError("--set", 1, 1,
                     "expected section.key=value, such as solver.velocity_iterations=12, not '" +
                         assignment + "'");
  }
  toml::table root = parseAssignment(assignment, assignment.find('='));
  scene_file::rejectUnknownKeys(root, sections, "--set");
  return root;
}

}  // namespace

void applySetting(Scene& scene, const std::string& assignment) {
  const toml::table root = parseSetting(assignment, {"world", "solver"});
  scene_file::readWorld(root, scene);
  scene_file::readSolver(root, scene);
}

void applySetting(SceneFile& scene, const std::string& assignment) {
  const toml::table root = parseSetting(assignment, {"world", "solver", "render"});
  scene_file::readWorld(root, scene);
  scene_file::readSolver(root, scene);
  scene_file::readRender(root, scene);
  scene_file::checkFollowedBody(root, scene);
}

}  // namespace impulse2d
