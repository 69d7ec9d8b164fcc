// How i2d fails. Each kind of failure has its own exit code, documented in `i2d --help` and
// docs/i2d.md; an invalid scene is an impulse2d::SceneError (exit 3).
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace i2d {

enum ExitCode : int {
  kSuccess = 0,
  kRunFailed = 1,       ///< the run could not finish: non-finite state, write error, no ffmpeg
  kBadCommandLine = 2,  ///< unknown command or option, missing or malformed value
  kInvalidScene = 3,    ///< the scene file cannot be read or is not a valid scene
};

/// A bad command line (exit 2).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A run that could not finish (exit 1).
class RunFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Where a run stopped, for its error line: "step 37 (t = 0.616667 s)".
inline std::string stepAndTime(long step, double dt) {
  std::ostringstream where;
  where << "step " << step << " (t = " << double(step) * dt << " s)";
  return where.str();
}

}  // namespace i2d
