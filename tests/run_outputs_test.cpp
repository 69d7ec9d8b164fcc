// What a run writes besides frames (issue 16): the viewer page, the animated GIF and the gnuplot
// plots, and the one-line errors for an unwritable plot directory and an unknown animation kind.
// The page in a browser is scripts/viewer-test's job (headless Chromium).
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "impulse2d/render/animation.h"
#include "impulse2d/render/legend.h"

namespace fs = std::filesystem;
using namespace impulse2d::render;

namespace {

const std::string kBinary = IMPULSE2D_BINARY_DIR "/apps/i2d";
const std::string kScenes = IMPULSE2D_SOURCE_DIR "/demos/scenes/";

/// A fresh directory under /tmp, removed at the end of the test.
struct Scratch {
  Scratch() {
    std::string pattern = (fs::temp_directory_path() / "run_outputs.XXXXXX").string();
    path = mkdtemp(pattern.data());
  }
  ~Scratch() { fs::remove_all(path); }
  fs::path path;
};

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Outcome {
  int exitCode = -1;
  std::string err;
};

Outcome i2d(const std::string& arguments, const Scratch& scratch) {
  const std::string command =
      kBinary + " " + arguments + " >/dev/null 2>" + (scratch.path / "err").string();
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(scratch.path / "err")};
}

int lineCount(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  return lines;
}

}  // namespace

TEST_CASE("run --frames writes a viewer page naming every frame and the run's figures",
          "[outputs][viewer]") {
  const Scratch scratch;
  REQUIRE(i2d("run " + kScenes + "resting_box.toml --steps 20 --every 10 --frames " +
                  scratch.path.string(),
              scratch)
              .exitCode == 0);
  const std::string page = readFile(scratch.path / "resting_box" / "index.html");
  for (const char* frame :
       {"resting_box_00000.png", "resting_box_00001.png", "resting_box_00002.png"}) {
    CHECK(page.find(frame) != std::string::npos);
  }
  CHECK(page.find("\"total energy (J)\"") != std::string::npos);
  CHECK(page.find("const steps = [0,10,20];") != std::string::npos);
  CHECK(page.find("http") == std::string::npos);  // nothing from the network
}

TEST_CASE("run --animation gif writes a looping GIF of the frames' size", "[outputs][gif]") {
  const Scratch scratch;
  REQUIRE(i2d("run " + kScenes +
                  "resting_box.toml --steps 20 --every 10 --animation gif "
                  "--frames " +
                  scratch.path.string(),
              scratch)
              .exitCode == 0);
  const std::string gif = readFile(scratch.path / "resting_box" / "resting_box.gif");
  REQUIRE(gif.size() > 13);
  CHECK(gif.substr(0, 6) == "GIF89a");
  const int width = (unsigned char)gif[6] | ((unsigned char)gif[7] << 8);
  const int height = (unsigned char)gif[8] | ((unsigned char)gif[9] << 8);
  CHECK(width == 800);
  CHECK(height == 600 + legendHeight({}, 800));
  CHECK(gif.find("NETSCAPE2.0") != std::string::npos);
  CHECK(gif.back() == ';');  // the trailer: the file was finished
}

TEST_CASE("the GIF palette holds every colour it is built from exactly", "[outputs][gif]") {
  const std::vector<Color> palette = gifPalette();
  REQUIRE(palette.size() == 256);
  for (int i = 0; i < 256; ++i) CHECK(nearestPaletteIndex(palette, palette[i]) == i);
  CHECK(palette[nearestPaletteIndex(palette, Color{250, 250, 247, 255})] ==
        (Color{255, 255, 255, 255}));
}

TEST_CASE("run --plots writes the five figures as PNGs, and a traced step its velocity errors",
          "[outputs][plots]") {
  const Scratch scratch;
  const std::string plots = (scratch.path / "plots").string();
  REQUIRE(
      i2d("run " + kScenes + "resting_box.toml --steps 30 --plots " + plots, scratch).exitCode ==
      0);
  for (const char* figure : {"kinetic", "potential", "total", "contacts", "penetration"}) {
    const fs::path png = fs::path(plots) / ("resting_box_" + std::string(figure) + ".png");
    INFO(png);
    CHECK(readFile(png).substr(1, 3) == "PNG");
  }
  // Steps 0 to 30 of the one run: a header, a label and 31 rows, then the block's end.
  CHECK(lineCount(readFile(fs::path(plots) / "resting_box_figures.dat")) == 2 + 31 + 2);
  REQUIRE(i2d("run " + kScenes + "resting_box.toml --trace-step 13 --frames " +
                  scratch.path.string() + " --plots " + plots,
              scratch)
              .exitCode == 0);
  CHECK(fs::exists(fs::path(plots) / "resting_box_step00013_velocity_error.png"));
}

TEST_CASE("an unwritable plot directory and an unknown animation are one error line each",
          "[outputs][errors]") {
  const Scratch scratch;
  std::ofstream(scratch.path / "file") << "in the way\n";
  const std::string blocked = (scratch.path / "file/plots").string();
  const Outcome noParent =
      i2d("run " + kScenes + "resting_box.toml --steps 5 --plots " + blocked, scratch);
  CHECK(noParent.exitCode == 1);
  CHECK(lineCount(noParent.err) == 1);
  CHECK(noParent.err.find(blocked) != std::string::npos);

  const Outcome unknown =
      i2d("run " + kScenes + "resting_box.toml --animation avi --frames " + scratch.path.string(),
          scratch);
  CHECK(unknown.exitCode == 2);  // a bad command line, as every malformed option value
  CHECK(lineCount(unknown.err) == 1);
  CHECK(unknown.err.find("unknown animation kind 'avi'") != std::string::npos);
}
