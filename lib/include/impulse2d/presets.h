// Presets: each contact method as its authors published it, as one named set of a solver's
// settings. Our defaults are the published method plus refinements (each method's page in docs/
// lists them); a preset turns every refinement off and sets the published constants.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "impulse2d/settings.h"

namespace impulse2d {

/// One published method: the solver it runs on, its name in scene files (`[solver] preset`) and
/// on the command line (`--preset`), one line saying what it is, and the settings it sets.
struct Preset {
  std::string solver;   ///< the solver it runs on: "micro", "sequential", "soft_step"
  std::string name;     ///< its name in scene files and on the command line
  std::string summary;  ///< one line saying what it is (i2d presets)
  /// Replaces the solver's settings in `settings` with the published method's.
  void (*apply)(SolverSettings& settings);
};

/// Every preset, grouped by solver; the first of a solver is the method our default refines.
const std::vector<Preset>& presets();

/// The preset of that solver and name, or null.
const Preset* findPreset(std::string_view solver, std::string_view name);

/// The published method `i2d check` compares a solver's settings with: the named preset if the
/// run chose one of that solver, else the solver's first; null for a solver without presets.
const Preset* publishedMethod(std::string_view solver, std::string_view chosenPreset);

/// The names of a solver's presets, "'a', 'b'", or "none" (for error messages).
std::string presetNames(std::string_view solver);

}  // namespace impulse2d
