// The parts of a scene file, each read into the Scene by its own function. Each reads only the
// keys present, so the same functions apply a whole file and a one-key --set override.
#pragma once

#include <toml++/toml.h>

#include "impulse2d/scene/scene_file.h"

namespace impulse2d::scene_file {

/// [world]: the WorldSettings fields by name, and the scene's steps and solver.
void readWorld(const toml::table& root, Scene& scene);

/// [solver]: fields of the settings struct of the scene's solver (read [world] first).
void readSolver(const toml::table& root, Scene& scene);

/// [render]: how frames look at the scene.
void readRender(const toml::table& root, SceneFile& scene);
/// Throws, at [render] follow, when the view follows a body the scene does not have (read the
/// bodies first).
void checkFollowedBody(const toml::table& root, const SceneFile& scene);

/// [[body]], then [[stack]] and [[pyramid]] expanded to bodies; names must be unique.
void readBodies(const toml::table& root, Scene& scene);

}  // namespace impulse2d::scene_file
