// Scene files: TOML text -> Scene. The format (every key, its unit, default and range) is
// documented in docs/scene-format.md. Every problem with a file is reported as one SceneError
// that says where it is, so a student can fix a scene without reading the loader.
//
// Positions in files are body origins; a polygon is re-centred on its centroid, so the Scene (and
// everything built from it, the CSV of `i2d run` included) holds the centre of mass.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "impulse2d/render/view.h"
#include "impulse2d/scene/scene.h"

namespace impulse2d {

/// A scene as its file states it: the physics and, from its [render] table, how frames look at
/// it. It is a Scene, so a physics caller can take it as one.
struct SceneFile : Scene {
  /// the [render] table
  ViewDef view;
};

/// A scene that cannot be loaded. what() is exactly "FILE:LINE:COLUMN: message" (lines and
/// columns from 1), or "FILE: message" when the file itself cannot be read.
class SceneError : public std::runtime_error {
 public:
  /// An error at LINE:COLUMN of `source`.
  SceneError(const std::string& source, int line, int column, const std::string& message);
  /// An error of `source` as a whole.
  SceneError(const std::string& source, const std::string& message);

  /// the file
  const std::string& source() const { return source_; }
  int line() const { return line_; }      ///< 0 when the error has no location
  int column() const { return column_; }  ///< 0 when the error has no location
  /// the message without its location
  const std::string& message() const { return message_; }

 private:
  std::string source_;
  int line_ = 0;
  int column_ = 0;
  std::string message_;
};

/// The most a scene file may hold: far beyond any scene a run may take (the size limit on steps ×
/// bodies), and a bound on what reading a device such as /dev/zero would allocate.
constexpr std::size_t kLargestSceneFileBytes = std::size_t(16) << 20;

/// Reads and parses the scene file at `path`; the scene is named after the file's stem. A file
/// larger than kLargestSceneFileBytes is refused.
SceneFile loadSceneFile(const std::string& path);

/// Parses scene text; `sourceName` names it in errors and gives the scene its name (its stem).
SceneFile parseScene(std::string_view text, const std::string& sourceName);

/// Whether `assignment` has the shape "section.key=value" (a dot before the first '='), the
/// shape applySetting needs before it reads the key and the value.
bool isSettingAssignment(const std::string& assignment);

/// Applies one command-line override "section.key=value" (section world or solver) to the scene,
/// with the value written as in a scene file; a bare word counts as a string (world.solver=micro).
/// Errors are SceneErrors located in the assignment, named "--set".
void applySetting(Scene& scene, const std::string& assignment);
/// The same for a scene file, whose [render] table a "render.key=value" changes too
/// (render.scale=300, render.follow=box).
void applySetting(SceneFile& scene, const std::string& assignment);

/// Throws SceneError(sourceName, ...) when the run the scene asks for is too long to finish in
/// reasonable time: steps × dynamic bodies × substeps above kMostBodySteps (setting_ranges.h).
/// Checked when a file is parsed and again after the command line's overrides.
void checkSceneSize(const Scene& scene, const std::string& sourceName);

/// The solver names a scene may choose: the library's solverNames() and "box2d".
std::vector<std::string> sceneSolverNames();

/// The fields of the settings struct of the named solver (empty for an unknown name).
std::vector<SettingField> solverSettingFields(SolverSettings& settings, const std::string& solver);

}  // namespace impulse2d
