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
#include "help.h"
#include "impulse2d/scene/scene_file.h"

namespace {

bool asksForHelp(const std::vector<std::string>& arguments) {
  for (const std::string& argument : arguments) {
    if (argument == "--help" || argument == "-h") return true;
  }
  return false;
}

int printHelp(const char* text) {
  std::cout << text;
  return i2d::kSuccess;
}

int fail(const std::string& message, int exitCode) {
  std::cerr << "error: " << message << "\n";
  return exitCode;
}

int dispatch(const std::string& command, const std::vector<std::string>& arguments) {
  if (command == "run") {
    if (asksForHelp(arguments)) return printHelp(i2d::kRunHelp);
    return i2d::runCommand(i2d::parseRunOptions(arguments));
  }
  if (command == "check") {
    if (asksForHelp(arguments)) return printHelp(i2d::kCheckHelp);
    return i2d::checkCommand(i2d::parseCheckOptions(arguments));
  }
  if (command == "compare") {
    if (asksForHelp(arguments)) return printHelp(i2d::kCompareHelp);
    return i2d::compareCommand(i2d::parseCompareOptions(arguments));
  }
  if (command == "agree") {
    if (asksForHelp(arguments)) return printHelp(i2d::kAgreeHelp);
    return i2d::agreeCommand(i2d::parseAgreeOptions(arguments));
  }
  if (command == "presets") {
    if (asksForHelp(arguments)) return printHelp(i2d::kPresetsHelp);
    if (!arguments.empty()) throw i2d::UsageError("i2d presets takes no arguments");
    return i2d::presetsCommand();
  }
  if (command == "--help" || command == "-h" || command == "help") {
    return printHelp(i2d::kGeneralHelp);
  }
  throw i2d::UsageError("unknown command '" + command + "' (see i2d --help)");
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
  if (argc < 2) return fail("no command given (see i2d --help)", i2d::kBadCommandLine);
  const std::vector<std::string> arguments(argv + 2, argv + argc);
  try {
    return checkStandardOutput(dispatch(argv[1], arguments));
  } catch (const i2d::UsageError& error) {
    return fail(error.what(), i2d::kBadCommandLine);
  } catch (const impulse2d::SceneError& error) {
    return fail(error.what(), i2d::kInvalidScene);
  } catch (const std::exception& error) {
    return fail(error.what(), i2d::kRunFailed);
  }
}
