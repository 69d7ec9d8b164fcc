// Finding a scene by its name in the installed scene directory.
#include "scene_search.h"

#include <filesystem>
#include <system_error>

namespace i2d {
namespace {

namespace fs = std::filesystem;

/// The installed scene directory: IMPULSE2D_SCENES_FROM_BIN (set by apps/CMakeLists.txt, e.g.
/// "../share/impulse2d/scenes") from the directory of the running i2d, so the installed tree
/// can be moved to any prefix. Empty when the running program cannot be found.
fs::path installedScenes() {
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (error) return {};
  return program.parent_path() / IMPULSE2D_SCENES_FROM_BIN;
}

}  // namespace

std::string findScene(const std::string& scene) {
  std::error_code error;
  if (fs::exists(scene, error) || scene.find('/') != std::string::npos) return scene;
  const fs::path directory = installedScenes();
  if (directory.empty()) return scene;
  for (const fs::path& name : {fs::path(scene), fs::path(scene + ".toml")}) {
    const fs::path candidate = directory / name;
    if (fs::is_regular_file(candidate, error)) return candidate.lexically_normal().string();
  }
  return scene;
}

}  // namespace i2d
