// The short report `i2d run` prints on stdout when a run ends.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "impulse2d/simulation.h"

namespace i2d {

/// Kinetic and potential energy of the dynamic bodies at one moment (J).
struct Energy {
  double kinetic = 0.0;
  double potential = 0.0;
};

Energy measureEnergy(const impulse2d::Simulation& simulation);

struct RunSummary {
  std::string scene;
  std::string solver;
  long steps = 0;
  double dt = 0.0;                ///< s
  double wallSeconds = 0.0;       ///< time spent in Simulation::step
  int contactPoints = 0;          ///< at the end
  double penetrationAtEnd = 0.0;  ///< m, the deepest overlap of the bodies as the run left them
  Energy start;
  Energy end;
  std::optional<std::string> csvPath;
  long csvRows = 0;
  std::vector<std::string> outputs;  ///< lines on the frames, sheet and video written
};

void printSummary(std::ostream& out, const RunSummary& summary);

}  // namespace i2d
