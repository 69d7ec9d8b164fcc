// Running the i2d program from a test: a scratch directory, the exit code and both streams.
#pragma once

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace i2d_process {

inline const std::string kBinary = IMPULSE2D_BINARY_DIR "/apps/i2d";
inline const std::string kScenes = IMPULSE2D_SOURCE_DIR "/demos/scenes/";

/// A fresh directory under /tmp, removed with everything in it at the end of the test.
struct Scratch {
  Scratch() {
    std::string pattern = (std::filesystem::temp_directory_path() / "i2d_process.XXXXXX").string();
    path = mkdtemp(pattern.data());
  }
  ~Scratch() { std::filesystem::remove_all(path); }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
  /// The names of the entries directly in the directory, sorted.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }
  std::filesystem::path path;
};

inline std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void writeFile(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

struct Outcome {
  int exitCode = -1;  ///< -1: killed by a signal (a crash)
  std::string out;
  std::string err;
};

/// Runs i2d with the arguments (a shell word list); its streams go to files in `scratch`, or its
/// standard output to `standardOutput` when one is named (/dev/full), leaving `out` empty.
inline Outcome i2d(const std::string& arguments, const Scratch& scratch,
                   const std::string& standardOutput = "") {
  const std::string out = standardOutput.empty() ? scratch / "stdout.txt" : standardOutput;
  const std::string command =
      kBinary + " " + arguments + " >" + out + " 2>" + (scratch / "stderr.txt");
  const int status = std::system(command.c_str());
  const Outcome outcome{WIFEXITED(status) ? WEXITSTATUS(status) : -1,
                        standardOutput.empty() ? readFile(out) : "",
                        readFile(scratch / "stderr.txt")};
  std::filesystem::remove(scratch / "stdout.txt");
  std::filesystem::remove(scratch / "stderr.txt");
  return outcome;
}

inline int lineCount(const std::string& text) {
  return int(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace i2d_process
