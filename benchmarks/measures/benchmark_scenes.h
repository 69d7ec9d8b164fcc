// The scenes and method settings the benchmarks measure: the shipped benchmark scenes
// (demos/scenes/), the family of pyramids for the scaling chart, and each method's own
// iteration knob set by its [solver] name, so every benchmark configures a method the way a
// scene file would.
#pragma once

#include <string>
#include <vector>

#include "impulse2d/scene/scene.h"

namespace benchmarks {

/// A scene of demos/scenes/ by name, with sleeping off (every body solved every step).
impulse2d::Scene shippedScene(const std::string& name);

/// s. When the scene should be at rest and its settled figures start: 4 s for rain, whose last
/// circles land at about 3 s, 1 s for the stacks and pyramids.
double settledTime(const impulse2d::Scene& scene);

/// A pyramid of `rows` rows of unit boxes as demos/scenes/pyramid20.toml builds it (gravity −10,
/// 60 Hz, density 1, friction 0.6, exactly touching), on ground wide enough for it.
impulse2d::Scene pyramidScene(int rows);

/// The rows of the scaling family: pyramids of 10 to about 5000 boxes.
std::vector<int> scalingFamilyRows();

/// Boxes in a pyramid of `rows` rows.
int pyramidBoxes(int rows);

/// The [solver] key that sets the method's iterations; empty for reference, which has none.
std::string iterationKey(const std::string& solver);

/// A copy of the scene running `solver` from its default settings, with `iterations` set through
/// iterationKey (0 keeps the default). Iterations set are exact: sequential sweeps k times and
/// micro applies at most k impulses per point.
impulse2d::Scene withMethod(impulse2d::Scene scene, const std::string& solver, int iterations);

/// The scene with its solver's settings set to the preset `name` (presets.h); empty: unchanged.
impulse2d::Scene withPreset(impulse2d::Scene scene, const std::string& name);

}  // namespace benchmarks
