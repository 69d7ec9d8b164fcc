// `i2d presets`: every preset, one line each: the solver, the name and what it is.
#include <iomanip>
#include <iostream>

#include "commands.h"
#include "failures.h"
#include "impulse2d/presets.h"

namespace i2d {

int presetsCommand() {
  for (const impulse2d::Preset& preset : impulse2d::presets()) {
    std::cout << std::left << std::setw(11) << preset.solver << std::setw(11) << preset.name
              << preset.summary << "\n";
  }
  return kSuccess;
}

}  // namespace i2d
