// An installed i2d finds the shipped lecture scenes by name: `i2d check resting_box` and
// `i2d check resting_box.toml` read PREFIX/share/impulse2d/scenes/resting_box.toml when i2d is
// PREFIX/bin/i2d and no such file is in the current directory (docs/i2d.md, docs/packaging.md).
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace fs = std::filesystem;

namespace {

/// An install tree under /tmp: PREFIX/bin/i2d and PREFIX/share/impulse2d/scenes/resting_box.toml,
/// and an empty directory PREFIX/work to run in; removed at the end of the test.
class InstalledTree {
 public:
  InstalledTree() {
    std::string pattern = (fs::temp_directory_path() / "scene_search_test.XXXXXX").string();
    prefix_ = mkdtemp(pattern.data());
    fs::create_directories(prefix_ / "bin");
    fs::create_directories(scenes());
    fs::create_directories(work());
    fs::copy_file(IMPULSE2D_BINARY_DIR "/apps/i2d", prefix_ / "bin/i2d");
    fs::copy_file(IMPULSE2D_SOURCE_DIR "/demos/scenes/resting_box.toml",
                  scenes() / "resting_box.toml");
  }
  ~InstalledTree() { fs::remove_all(prefix_); }
  fs::path scenes() const { return prefix_ / "share/impulse2d/scenes"; }
  fs::path work() const { return prefix_ / "work"; }

  struct Result {
    int exitCode = -1;
    std::string output;  ///< stdout and stderr
  };
  /// Runs `PREFIX/bin/i2d ARGUMENTS` in PREFIX/work.
  Result i2d(const std::string& arguments) const {
    const std::string command = "cd '" + work().string() + "' && ../bin/i2d " + arguments + " 2>&1";
    Result result;
    FILE* pipe = popen(command.c_str(), "r");
    char buffer[256];
    while (fgets(buffer, sizeof buffer, pipe)) result.output += buffer;
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
  }

 private:
  fs::path prefix_;
};

}  // namespace

TEST_CASE("An installed i2d runs a shipped scene by its name, with or without .toml",
          "[i2d][packaging]") {
  const InstalledTree tree;
  const std::string installed = (tree.scenes() / "resting_box.toml").string();
  for (const std::string name : {"resting_box", "resting_box.toml"}) {
    const auto result = tree.i2d("check " + name);
    INFO(result.output);
    CHECK(result.exitCode == 0);
    CHECK(result.output.find("scene resting_box (" + installed + "): valid") != std::string::npos);
  }
}

TEST_CASE("A scene file in the current directory comes before the shipped one of that name",
          "[i2d][packaging]") {
  const InstalledTree tree;
  fs::copy_file(IMPULSE2D_SOURCE_DIR "/demos/scenes/stack.toml", tree.work() / "resting_box.toml");
  const auto result = tree.i2d("check resting_box.toml");
  INFO(result.output);
  CHECK(result.exitCode == 0);
  CHECK(result.output.find("(resting_box.toml): valid") != std::string::npos);
  CHECK(result.output.find(tree.scenes().string()) == std::string::npos);
}

TEST_CASE("A name that is neither a file nor a shipped scene is one error naming it",
          "[i2d][packaging]") {
  const InstalledTree tree;
  for (const std::string name : {"no_such_scene", "./resting_box"}) {
    const auto result = tree.i2d("check " + name);
    INFO(result.output);
    CHECK(result.exitCode != 0);
    CHECK(result.output.find(name) != std::string::npos);
    CHECK(result.output.find("error") != std::string::npos);
  }
}
