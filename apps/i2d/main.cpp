// i2d: the impulse2d command line. Dispatches to a command and turns each kind of failure into
// one "error: ..." line on stderr and its exit code (failures.h).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "commands.h"
#include "failures.h"
#include "impulse2d/scene/scene_file.h"

namespace {

int fail(const std::string& message, int exitCode) {
  std::cerr << "error: " << message << "\n";
  return exitCode;
}

int dispatch(const i2d::CommandLine& line) {
  switch (line.command) {
    case i2d::Command::Help:
      std::cout << line.help;
      return i2d::kSuccess;
    case i2d::Command::Run:
      return i2d::runCommand(line.run);
    case i2d::Command::Check:
      return i2d::checkCommand(line.check);
    case i2d::Command::Compare:
      return i2d::compareCommand(line.compare);
    case i2d::Command::Agree:
      return i2d::agreeCommand(line.agree);
    case i2d::Command::Presets:
      return i2d::presetsCommand();
  }
  return i2d::kSuccess;
}

/// The command's exit code, unless what it printed could not be written (standard output on a
/// full disk): then that is the failure, as for any other file i2d writes.
int checkStandardOutput(int exitCode) {
  std::cout.flush();
  if (std::cout && std::fflush(stdout) == 0 && !std::ferror(stdout)) return exitCode;
  const std::string reason = std::strerror(errno);
  return fail("cannot write standard output: " + reason, i2d::kRunFailed);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return checkStandardOutput(
        dispatch(i2d::parseCommandLine(std::vector<std::string>(argv + 1, argv + argc))));
  } catch (const i2d::UsageError& error) {
    return fail(error.what(), i2d::kBadCommandLine);
  } catch (const impulse2d::SceneError& error) {
    return fail(error.what(), i2d::kInvalidScene);
  } catch (const std::exception& error) {
    return fail(error.what(), i2d::kRunFailed);
  }
}
