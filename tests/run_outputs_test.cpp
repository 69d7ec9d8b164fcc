// What a run writes besides frames: the viewer page, the animated GIF and the gnuplot
// plots, and the one-line errors for an unwritable plot directory and an unknown animation kind.
// The page in a browser is scripts/viewer-test's job (headless Chromium).
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

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
  CHECK(height == 600);  // the strips lie inside the frame's size
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

TEST_CASE("plots of a run with no time to plot are drawn without a word on stderr",
          "[outputs][plots]") {
  // gnuplot warns of an empty range when a figure is one point or constant; the plots still
  // draw, so the warning is not the user's concern.
  const Scratch scratch;
  const std::string plots = (scratch.path / "plots").string();
  const Outcome outcome =
      i2d("run " + kScenes + "resting_box.toml --steps 0 --plots " + plots, scratch);
  CHECK(outcome.exitCode == 0);
  CHECK(outcome.err.empty());
  CHECK(readFile(fs::path(plots) / "resting_box_kinetic.png").substr(1, 3) == "PNG");
  CHECK_FALSE(fs::exists(fs::path(plots) / "resting_box_plots.gp.log"));
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
  CHECK(unknown.err == "error: --animation: avi not in {gif,mp4}\n");
}

TEST_CASE("run --contacts: static friction answers the push exactly, then slides at mu N",
          "[outputs][contacts][friction]") {
  // pushed_box: 1 kg, mu 0.5, a push growing at 2 N/s; friction holds up to mu m g = 4.905 N.
  const Scratch scratch;
  const fs::path csv = scratch.path / "contacts.csv";
  REQUIRE(
      i2d("run " + kScenes + "pushed_box.toml --steps 200 --every 20 --contacts " + csv.string(),
          scratch)
          .exitCode == 0);
  std::istringstream rows(readFile(csv));
  std::string line;
  std::getline(rows, line);
  CHECK(line.rfind("step,t,body_a,body_b,point,x,y,nx,ny,normal_impulse_Ns", 0) == 0);
  // Per step: the summed friction force on the box, the summed limit, the push, any sliding.
  std::map<long, std::array<double, 3>> sums;
  std::map<long, bool> sliding;
  while (std::getline(rows, line)) {
    std::vector<std::string> fields;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
    REQUIRE(fields.size() == 20);
    const long step = std::stol(fields[0]);
    sums[step][0] += std::stod(fields[12]);  // friction_force_N
    sums[step][1] += std::stod(fields[14]);  // friction_limit_N
    // The push on the box, body a or b (the ground's load columns are 0).
    sums[step][2] = std::stod(fields[16]) + std::stod(fields[18]);
    sliding[step] = sliding[step] || fields[15] == "sliding";
  }
  for (const long step : {40L, 100L, 140L}) {  // the push 1.3, 3.3, 4.6 N: friction holds
    INFO("step " << step);
    CHECK(std::abs(sums[step][0]) == Approx(sums[step][2]).epsilon(1e-6));
    CHECK(sums[step][1] == Approx(4.905).epsilon(1e-6));
    CHECK_FALSE(sliding[step]);
  }
  for (const long step : {160L, 200L}) {  // past 4.905 N: friction is at its limit, sliding
    INFO("step " << step);
    CHECK(std::abs(sums[step][0]) == Approx(4.905).epsilon(1e-6));
    CHECK(sums[step][2] > 4.905);
    CHECK(sliding[step]);
  }
}

TEST_CASE("the viewer of a pushed box plots energy and the push against friction",
          "[outputs][viewer]") {
  const Scratch scratch;
  REQUIRE(i2d("run " + kScenes + "pushed_box.toml --steps 60 --every 30 --frames " +
                  scratch.path.string(),
              scratch)
              .exitCode == 0);
  const fs::path directory = scratch.path / "pushed_box";
  const std::string page = readFile(directory / "index.html");
  CHECK(page.find("\"file\":\"pushed_box_energy.svg\"") != std::string::npos);
  CHECK(page.find("\"file\":\"pushed_box_forces.svg\"") != std::string::npos);
  CHECK(readFile(directory / "pushed_box_forces.svg").find("<svg") != std::string::npos);
  // The plotted data: while friction holds, the friction force is the push (2 N/s × t).
  std::istringstream data(readFile(directory / "pushed_box_plots.dat"));
  int rows = 0;
  for (std::string line; std::getline(data, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double step, time, kinetic, potential, total, contacts, penetration, push, friction;
    fields >> step >> time >> kinetic >> potential >> total >> contacts >> penetration >> push >>
        friction;
    if (step < 1) continue;
    CHECK(push == Approx(2.0 * (step - 1) / 60.0).margin(1e-6));
    CHECK(friction == Approx(push).margin(1e-6));
    ++rows;
  }
  CHECK(rows == 60);
}
