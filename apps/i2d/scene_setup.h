// A scene as the command line asks for it: the file, then --solver, each --set in order, then
// --steps and --dt, so the most explicit option wins.
#pragma once

#include "impulse2d/scene/scene_file.h"
#include "options.h"

namespace i2d {

/// Applies the overrides to a loaded scene; a bad --set is a UsageError.
void applyOverrides(const SceneOptions& options, impulse2d::SceneFile& scene);

/// Loads options.scenePath and applies the overrides.
impulse2d::SceneFile loadScene(const SceneOptions& options);

}  // namespace i2d
