// The presets: each method as published (presets.h).
#include "impulse2d/presets.h"

namespace impulse2d {

const std::vector<Preset>& presets() {
  static const std::vector<Preset> all = {
      {"micro", "lecture",
       "the micro-collision resolver as the lecture states it (Millington ch. 14-15)",
       [](SolverSettings& s) { s.micro = MicroCollisionSettings::lecture(); }},
      {"sequential", "box2d_lite",
       "Catto's Box2D-Lite: 10 sweeps of accumulated impulses, warm starting, Baumgarte bias, no "
       "position pass",
       [](SolverSettings& s) { s.sequential = SequentialImpulseSettings::box2dLite(); }},
      {"sequential", "box2d_2_4",
       "as Box2D 2.4.1: 8 sweeps, friction first, block solver, no velocity bias, 3 position "
       "sweeps point by point",
       [](SolverSettings& s) { s.sequential = SequentialImpulseSettings::box2d24(); }},
      {"soft_step", "box2d_v3", "Box2D v3's soft step as published: none of our refinements",
       [](SolverSettings& s) { s.softStep = SoftStepSettings::box2dV3(); }},
  };
  return all;
}

const Preset* findPreset(std::string_view solver, std::string_view name) {
  for (const Preset& preset : presets()) {
    if (preset.solver == solver && preset.name == name) return &preset;
  }
  return nullptr;
}

const Preset* publishedMethod(std::string_view solver, std::string_view chosenPreset) {
  if (const Preset* chosen = findPreset(solver, chosenPreset)) return chosen;
  for (const Preset& preset : presets()) {
    if (preset.solver == solver) return &preset;
  }
  return nullptr;
}

std::string presetNames(std::string_view solver) {
  std::string names;
  for (const Preset& preset : presets()) {
    if (preset.solver != solver) continue;
    names += (names.empty() ? "'" : ", '") + preset.name + "'";
  }
  return names.empty() ? "none" : names;
}

}  // namespace impulse2d
