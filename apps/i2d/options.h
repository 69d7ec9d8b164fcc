// The command line of each i2d command, parsed into plain options. Options take their value as
// the next argument or after '=' (--steps 100, --steps=100); malformed ones throw UsageError.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace i2d {

struct RunOptions {
  std::string scenePath;
  std::optional<std::string> solver;   ///< --solver: replaces the scene's solver
  std::optional<int> steps;            ///< --steps: replaces [world] steps
  std::optional<double> dt;            ///< --dt: replaces [world] dt (s)
  std::vector<std::string> settings;   ///< --set section.key=value, applied in order
  std::optional<std::string> csvPath;  ///< --csv: the trajectory file
  int every = 1;                       ///< --every: record every K-th step, step 0 and the last
  std::optional<std::string> framesDirectory;  ///< --frames: PNG frames
};

struct CheckOptions {
  std::string scenePath;
};

RunOptions parseRunOptions(const std::vector<std::string>& arguments);
CheckOptions parseCheckOptions(const std::vector<std::string>& arguments);

}  // namespace i2d
