// What the scene reader refuses, as the one line i2d would print: for the tests of scene files,
// --set, setting ranges and placement.
#pragma once

#include <string>

#include "impulse2d/scene/scene_file.h"

namespace scene_errors {

/// The what() of the SceneError that parsing `text` as "bad.toml" throws ("" if it loads).
inline std::string errorOf(const std::string& text) {
  try {
    impulse2d::parseScene(text, "bad.toml");
  } catch (const impulse2d::SceneError& error) {
    return error.what();
  }
  return "";
}

/// The what() of the SceneError that applying `assignment` to `scene` throws ("" if it applies).
inline std::string errorOfSetting(impulse2d::SceneFile scene, const std::string& assignment) {
  try {
    impulse2d::applySetting(scene, assignment);
  } catch (const impulse2d::SceneError& error) {
    return error.what();
  }
  return "";
}

}  // namespace scene_errors
