// A scene as the command line asks for it: the file, then --solver, each --set in order, then
// --steps and --dt, so the most explicit option wins.
#pragma once

#include <ostream>

#include "impulse2d/scene/scene_file.h"
#include "options.h"

namespace i2d {

/// Applies the overrides to a loaded scene; a bad --set is a UsageError.
void applyOverrides(const SceneOptions& options, impulse2d::SceneFile& scene);

/// Loads options.scenePath and applies the overrides.
impulse2d::SceneFile loadScene(const SceneOptions& options);

/// The overlap a scene's solver leaves alone (m): sequential's and the reference's allowed
/// penetration, micro's position epsilon, Box2D's linear slop for soft step and box2d.
double allowedOverlap(const impulse2d::Scene& scene);

/// Writes one warning line to `out` for each pair of bodies (one of them dynamic) that starts
/// overlapping by more than allowedOverlap: the solver will push them apart at once, which the
/// scene's author rarely means. Returns the number of such pairs.
int warnAboutStartingOverlaps(const impulse2d::Scene& scene, std::ostream& out);

}  // namespace i2d
