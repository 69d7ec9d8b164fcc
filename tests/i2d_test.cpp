// The i2d program as a user meets it: exit codes, the summary, the exact CSV, one-line errors,
// no half-written output file after any failure, and the frames, sheets, traces, comparison
// panels and Box2D agreement tables it writes (docs/i2d.md).
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "impulse2d/presets.h"
#include "impulse2d/render/contact_sheet.h"
#include "impulse2d/render/legend.h"
#include "impulse2d/render/panels.h"
#include "impulse2d/render/png.h"

namespace fs = std::filesystem;

namespace {

const std::string kBinary = IMPULSE2D_BINARY_DIR "/apps/i2d";
const std::string kScenes = IMPULSE2D_SOURCE_DIR "/demos/scenes/";
const std::string kHeader = "step,t,body,x,y,angle_rad,vx,vy,omega_rad_s";

/// A fresh directory under /tmp, removed with everything in it at the end of the test.
class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    std::string pattern = (fs::temp_directory_path() / "i2d_test.XXXXXX").string();
    path_ = mkdtemp(pattern.data());
  }
  ~TemporaryDirectory() { fs::remove_all(path_); }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  /// The names of the files in the directory.
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(path_)) {
      names.push_back(entry.path().filename().string());
    }
    return names;
  }

 private:
  fs::path path_;
};

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> readLines(const std::string& path) {
  std::istringstream text(readFile(path));
  std::vector<std::string> lines;
  for (std::string line; std::getline(text, line);) lines.push_back(line);
  return lines;
}

struct Outcome {
  int exitCode = -1;
  std::string out;
  std::string err;
};

/// Runs i2d with the arguments (a shell word list) and collects its exit code and output;
/// `environment` ("NAME=value ...") is set for i2d alone.
Outcome i2d(const std::string& arguments, const std::string& environment = "") {
  const TemporaryDirectory streams;
  const std::string command = environment + " " + kBinary + " " + arguments + " >" +
                              (streams / "out") + " 2>" + (streams / "err");
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(streams / "out"),
          readFile(streams / "err")};
}

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

/// A crate 0.5 m above the ground under the reference, at 20 steps a second: it falls for six
/// steps and lands in the seventh. Written into `directory`; returns the scene's path.
std::string writeDropScene(const TemporaryDirectory& directory) {
  const std::string scene = directory / "drop.toml";
  writeFile(scene,
            "[world]\ndt = 0.05\nsteps = 40\nsolver = \"reference\"\n"
            "[[body]]\nname = \"ground\"\ntype = \"static\"\nshape = \"box\"\nsize = [10, 1]\n"
            "position = [0, -0.5]\n"
            "[[body]]\nname = \"crate\"\nshape = \"box\"\nsize = [1, 1]\nposition = [0, 1.0]\n");
  return scene;
}

}  // namespace

TEST_CASE("i2d --help and each command's --help say what it does", "[i2d][help]") {
  const Outcome general = i2d("--help");
  CHECK(general.exitCode == 0);
  for (const char* topic :
       {"i2d run SCENE", "i2d compare SCENE", "i2d agree SCENE", "i2d check SCENE", "0  success",
        "1  failure", "2  bad command line", "3  invalid scene"}) {
    CHECK(general.out.find(topic) != std::string::npos);
  }
  const Outcome run = i2d("run --help");
  CHECK(run.exitCode == 0);
  for (const char* option : {"--solver", "--steps", "--dt", "--set", "--csv", "--every", "--frames",
                             "--video", "--trace-step", "--no-overlays", "--hide", "--show",
                             "_sheet.png", "step,t,body,x,y,angle_rad,vx,vy,omega_rad_s"}) {
    CHECK(run.out.find(option) != std::string::npos);
  }
  const Outcome compare = i2d("compare --help");
  for (const char* option : {"--solvers", "--panel", "--frames", "_compare_00000.png"}) {
    CHECK(compare.out.find(option) != std::string::npos);
  }
  CHECK(i2d("agree --help").out.find("usage: i2d agree SCENE") == 0);
  CHECK(i2d("check --help").out.find("usage: i2d check SCENE") == 0);
}

TEST_CASE("i2d presets lists each preset on one line; --help names them", "[i2d][preset]") {
  const Outcome outcome = i2d("presets");
  CHECK(outcome.exitCode == 0);
  const std::string help = i2d("--help").out;
  size_t lines = 0;
  for (const impulse2d::Preset& preset : impulse2d::presets()) {
    INFO(preset.name);
    const size_t line = outcome.out.find(preset.summary);
    REQUIRE(line != std::string::npos);
    const size_t lineStart = outcome.out.rfind('\n', line);
    const size_t name = outcome.out.rfind(preset.name, line);
    CHECK((lineStart == std::string::npos || name > lineStart));
    CHECK(help.find(preset.name) != std::string::npos);
    ++lines;
  }
  CHECK(static_cast<size_t>(std::count(outcome.out.begin(), outcome.out.end(), '\n')) == lines);
  CHECK(i2d("run " + kScenes + "stack.toml --solver sequential --preset book").err ==
        "error: unknown preset 'book' for solver 'sequential' (known: 'box2d_lite', 'box2d_2_4'; "
        "see i2d presets)\n");
}

TEST_CASE("i2d check --preset --set marks each value that differs from the published method",
          "[i2d][check][preset]") {
  const Outcome outcome = i2d("check " + kScenes +
                              "stack.toml --solver sequential --preset box2d_2_4 --set "
                              "solver.velocity_iterations=20");
  CHECK(outcome.exitCode == 0);
  CHECK(outcome.out.find("[solver] sequential (preset box2d_2_4)") != std::string::npos);
  CHECK(outcome.out.find("  velocity_iterations = 20  * published: 8\n") != std::string::npos);
  CHECK(outcome.out.find("  friction_first = true\n") != std::string::npos);
  // Without a preset, our default beside Box2D-Lite: the position pass is ours.
  const Outcome ours = i2d("check " + kScenes + "stack.toml --solver sequential");
  CHECK(ours.out.find("  position_iterations = 3  * published: 0\n") != std::string::npos);
}

TEST_CASE("i2d run writes each step's exact state to the CSV and prints the summary",
          "[i2d][run][csv]") {
  const TemporaryDirectory directory;
  const std::string csv = directory / "ball.csv";
  const Outcome outcome = i2d("run " + kScenes + "bouncing_ball.toml --steps 10 --csv " + csv);
  CHECK(outcome.exitCode == 0);
  CHECK(outcome.err.empty());
  for (const char* figure : {"steps", "simulated", "wall time", "µs per step", "contacts",
                             "penetration", "kinetic", "potential"}) {
    CHECK(outcome.out.find(figure) != std::string::npos);
  }
  const std::vector<std::string> lines = readLines(csv);
  REQUIRE(lines.size() == 1 + 11);  // the header, then steps 0..10 of the one dynamic body
  CHECK(lines[0] == kHeader);
  // The ball's bottom is 2 m up: in 10 steps it falls 0.15 m and touches nothing. Semi-implicit
  // Euler gives after n steps v = −g·n·dt and y = 2.5 − g·dt²·n(n + 1)/2; the CSV's numbers read
  // back as the doubles they were written from, so only the round-off of the sums remains.
  constexpr double kDt = 0.0166666667;  // the scene's dt
  constexpr double kG = 9.81;
  for (int n = 0; n <= 10; ++n) {
    INFO(lines[size_t(n) + 1]);
    std::istringstream row(lines[size_t(n) + 1]);
    std::vector<std::string> fields;
    for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
    REQUIRE(fields.size() == 9);
    CHECK(fields[0] == std::to_string(n));
    CHECK(std::stod(fields[1]) == Approx(n * kDt).epsilon(1e-12));
    CHECK(fields[2] == "ball");
    CHECK(fields[3] == "0");
    CHECK(std::stod(fields[4]) == Approx(2.5 - kG * kDt * kDt * n * (n + 1) / 2.0).epsilon(1e-12));
    CHECK(fields[5] == "0");
    CHECK(fields[6] == "0");
    CHECK(std::stod(fields[7]) == Approx(-kG * n * kDt).epsilon(1e-12).margin(1e-15));
    CHECK(fields[8] == "0");
  }
  CHECK(directory.files() == std::vector<std::string>{"ball.csv"});
}

TEST_CASE("run --every K records every K-th step, step 0 and the last", "[i2d][run][csv]") {
  const TemporaryDirectory directory;
  const std::string csv = directory / "pyramid.csv";
  const Outcome outcome = i2d("run " + kScenes + "pyramid.toml --steps=10 --every=4 --csv=" + csv);
  CHECK(outcome.exitCode == 0);
  const std::vector<std::string> lines = readLines(csv);
  REQUIRE(lines.size() == 1 + 55 * 4);  // steps 0, 4, 8 and 10 of the 55 boxes, not the ground
  CHECK(lines[1].rfind("0,0,box1,", 0) == 0);
  CHECK(lines[1 + 55].rfind("4,", 0) == 0);
  CHECK(lines[1 + 3 * 55].rfind("10,", 0) == 0);
}

TEST_CASE("run --solver, --dt and --set override the scene", "[i2d][run][set]") {
  const TemporaryDirectory directory;
  const std::string csv = directory / "ball.csv";
  const Outcome outcome = i2d("run " + kScenes + "bouncing_ball.toml --steps 1 --dt 0.5 " +
                              "--solver sequential --set solver.velocity_iterations=2 " +
                              "--set 'world.gravity=[0, -2]' --csv " + csv);
  CHECK(outcome.exitCode == 0);
  CHECK(outcome.out.find("solver sequential") != std::string::npos);
  // One step of semi-implicit Euler: v = g dt = -1, y = 2.5 + v dt = 2.
  CHECK(readLines(csv).at(2) == "1,0.5,ball,0,2,0,0,-1,0");
}

TEST_CASE("a bad command line is one error line and exit code 2", "[i2d][errors]") {
  const std::string scene = kScenes + "bouncing_ball.toml";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "error: no command given (see i2d --help)\n"},
      {"fly", "error: unknown command 'fly' (see i2d --help)\n"},
      {"--steps 3", "error: no command given before '--steps' (see i2d --help)\n"},
      {"run", "error: SCENE is required\n"},
      {"run " + scene + " --fast",
       "error: The following argument was not expected: --fast (see i2d run --help)\n"},
      {"presets " + scene,
       "error: The following argument was not expected: " + scene + " (see i2d presets --help)\n"},
      {"run " + scene + " --csv", "error: --csv: 1 required FILE missing\n"},
      {"run " + scene + " --steps -3",
       "error: --steps: must be an integer in [0, 10000000], not '-3'\n"},
      {"run " + scene + " --steps 2.5",
       "error: --steps: must be an integer in [0, 10000000], not '2.5'\n"},
      {"run " + scene + " --steps=ten",
       "error: --steps: must be an integer in [0, 10000000], not 'ten'\n"},
      {"run " + scene + " --dt 0", "error: --dt: must be in [1e-06, 1], not '0'\n"},
      {"run " + scene + " --dt nan", "error: --dt: must be in [1e-06, 1], not 'nan'\n"},
      {"run " + scene + " --every 0", "error: --every: Value 0 not in range 1 to 10000000\n"},
      {"run " + scene + " --solver fast",
       "error: --solver: fast not in {micro,sequential,reference,soft_step,box2d}\n"},
      {"run " + scene + " --set solver.velocity_iterations=2 --set dt=-1",
       "error: --set: needs section.key=value, such as solver.velocity_iterations=12, not "
       "'dt=-1'\n"},
      {"check " + scene + " " + scene,
       "error: The following argument was not expected: " + scene + " (see i2d check --help)\n"},
      {"run " + scene + " --csv a.csv --error-vs-reference b.csv",
       "error: --csv excludes --error-vs-reference\n"},
      {"run " + scene + " --frames f --trace-step 3 --contacts c.csv",
       "error: --contacts excludes --trace-step\n"},
  };
  for (const auto& [arguments, message] : cases) {
    INFO("i2d " << arguments);
    const Outcome outcome = i2d(arguments);
    CHECK(outcome.exitCode == 2);
    CHECK(outcome.err == message);
  }
}

TEST_CASE("an option given twice keeps its last value; each --set applies in order",
          "[i2d][options]") {
  const TemporaryDirectory directory;
  const std::string csv = directory / "ball.csv";
  const Outcome outcome = i2d("run " + kScenes + "bouncing_ball.toml --steps 5 --steps=1 " +
                              "--set world.dt=0.5 --set world.dt=0.125 --csv " + csv);
  CHECK(outcome.exitCode == 0);
  const std::vector<std::string> lines = readLines(csv);
  REQUIRE(lines.size() == 1 + 2);  // the header, steps 0 and 1
  CHECK(lines[2].rfind("1,0.125,ball,", 0) == 0);
}

TEST_CASE("the overlay switches apply in the order given", "[i2d][frames][options]") {
  const TemporaryDirectory directory;
  const auto frame = [&](const std::string& name, const std::string& switches) {
    REQUIRE(i2d("run " + kScenes + "resting_box.toml --steps 0 --frames " + (directory / name) +
                " " + switches)
                .exitCode == 0);
    return readFile(directory / (name + "/resting_box/resting_box_00000.png"));
  };
  const std::string bare = frame("bare", "--no-overlays");
  const std::string legendLast = frame("legend_last", "--no-overlays --show legend");
  const std::string legendFirst = frame("legend_first", "--show legend --no-overlays");
  CHECK(legendLast != bare);
  CHECK(legendFirst == bare);
}

TEST_CASE("an invalid scene is one located error, exit code 3, and no CSV", "[i2d][errors]") {
  const TemporaryDirectory directory;
  const std::string scene = directory / "typo.toml";
  writeFile(scene, "[[body]]\nshape = \"circle\"\nradius = 0.5\nfricton = 0.5\n");
  const Outcome outcome = i2d("run " + scene + " --csv " + (directory / "out.csv"));
  CHECK(outcome.exitCode == 3);
  CHECK(outcome.out.empty());
  CHECK(outcome.err.rfind("error: " + scene + ":4:1: unknown key 'fricton' in [[body]] (known: ",
                          0) == 0);
  CHECK(std::count(outcome.err.begin(), outcome.err.end(), '\n') == 1);
  CHECK(directory.files() == std::vector<std::string>{"typo.toml"});

  // A --set is a line of the scene: a value out of its range is refused as the file's would be.
  const Outcome outOfRange = i2d("run " + kScenes + "bouncing_ball.toml --set world.dt=-1");
  CHECK(outOfRange.exitCode == 3);
  CHECK(outOfRange.err == "error: --set:1:10: dt = -1: must be in [1e-06, 1]\n");

  const Outcome missing = i2d("check " + (directory / "none.toml"));
  CHECK(missing.exitCode == 3);
  CHECK(missing.err == "error: " + (directory / "none.toml") +
                           ": cannot read the file: No such file or directory\n");
}

TEST_CASE("a CSV that cannot be written fails with exit code 1 and leaves nothing", "[i2d][csv]") {
  const TemporaryDirectory directory;
  const std::string scene = kScenes + "bouncing_ball.toml --steps 5 --csv ";
  std::ofstream(directory / "file") << "in the way\n";
  const Outcome noDirectory = i2d("run " + scene + (directory / "file/out.csv"));
  CHECK(noDirectory.exitCode == 1);
  CHECK(noDirectory.err == "error: cannot create directory '" + (directory / "file") +
                               "' for --csv: Not a directory\n");

  fs::create_directory(directory / "taken");
  const Outcome isDirectory = i2d("run " + scene + (directory / "taken"));
  CHECK(isDirectory.exitCode == 1);
  CHECK(isDirectory.err == "error: cannot write " + (directory / "taken") + ": Is a directory\n");
  std::vector<std::string> files = directory.files();
  std::sort(files.begin(), files.end());
  CHECK(files == std::vector<std::string>{"file", "taken"});
}

TEST_CASE("a state that becomes non-finite stops the run, keeping the rows so far",
          "[i2d][errors][csv]") {
  // Gravity of -1e154 m/s² over 1 s steps on a disc of 0.5 m (0.785 kg): step 1 reaches
  // v = -1e154, y = -1e154 and energies near 1e308 J; step 2 overflows them to infinity.
  const TemporaryDirectory directory;
  const std::string scene = directory / "overflow.toml";
  writeFile(scene,
            "[world]\ngravity = [0, -1e154]\ndt = 1\nsteps = 10\nsolver = \"micro\"\n"
            "[[body]]\nname = \"rocket\"\nshape = \"circle\"\nradius = 0.5\n");
  const std::string csv = directory / "overflow.csv";
  const Outcome outcome = i2d("run " + scene + " --csv " + csv);
  CHECK(outcome.exitCode == 1);
  CHECK(outcome.err == "error: body rocket became non-finite at step 2 (solver micro)\n");
  const std::vector<std::string> lines = readLines(csv);
  REQUIRE(lines.size() == 3);
  CHECK(lines[0] == kHeader);
  CHECK(lines[2] == "1,1,rocket,0,-1e+154,0,0,-1e+154,0");
}

TEST_CASE("i2d check prints the solver, settings and bodies", "[i2d][check]") {
  const Outcome outcome = i2d("check " + kScenes + "bouncing_ball.toml");
  CHECK(outcome.exitCode == 0);
  for (const char* text : {"solver micro", "dt = ", "restitution_threshold = ",
                           "bodies 2 (1 static, 1 dynamic): 1 box 1 circle", "  ground: static box",
                           "  ball: dynamic circle radius 0.5 m"}) {
    INFO(text);
    CHECK(outcome.out.find(text) != std::string::npos);
  }
}

namespace {

/// The size of the PNG image at `path`, decoded in full (so a corrupt file fails here).
std::pair<int, int> pngSize(const std::string& path) {
  const impulse2d::render::Image image = impulse2d::render::readPng(path);
  return {image.width(), image.height()};
}

/// The names of the files in `directory` that start with `prefix`, sorted.
std::vector<std::string> filesStartingWith(const std::string& directory,
                                           const std::string& prefix) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

/// "step,t,body" of a CSV row.
std::string stepTimeAndBody(const std::string& row) {
  size_t end = 0;
  for (int field = 0; field < 3; ++field) end = row.find(',', end) + 1;
  return row.substr(0, end - 1);
}

}  // namespace

TEST_CASE("run --frames writes a frame every K-th step, the last, and a sheet", "[i2d][frames]") {
  const TemporaryDirectory directory;
  const Outcome outcome = i2d(
      "run " + kScenes + "bouncing_ball.toml --steps 11 --every 5 --frames " + (directory / ""));
  CHECK(outcome.exitCode == 0);
  CHECK(outcome.err.empty());
  const std::string frames = directory / "bouncing_ball";
  // Steps 0, 5, 10 and the last, 11: numbered without gaps.
  CHECK(filesStartingWith(frames, "bouncing_ball") ==
        std::vector<std::string>{"bouncing_ball_00000.png", "bouncing_ball_00001.png",
                                 "bouncing_ball_00002.png", "bouncing_ball_00003.png",
                                 "bouncing_ball_energy.svg", "bouncing_ball_plots.dat",
                                 "bouncing_ball_plots.gp", "bouncing_ball_sheet.png"});
  // The scene's [render] table asks for 800 x 600, the heads-up and legend strips included.
  CHECK(pngSize(frames + "/bouncing_ball_00003.png") == std::pair<int, int>(800, 600));
  const impulse2d::render::RenderSettings settings;
  const impulse2d::render::Camera camera =
      impulse2d::render::fitCamera({}, impulse2d::ViewDef{}, settings, 800, 600);
  const impulse2d::render::SheetLayout sheet = impulse2d::render::contactSheetLayout(
      impulse2d::render::evenlySpaced(4, settings.sheetThumbnails), camera.width, camera.height,
      settings);
  CHECK(pngSize(frames + "/bouncing_ball_sheet.png") ==
        std::pair<int, int>(sheet.width, sheet.height));
  CHECK(outcome.out.find("sheet        " + frames + "/bouncing_ball_sheet.png") !=
        std::string::npos);
}

TEST_CASE("a frame directory that cannot be made is one error line and exit code 1",
          "[i2d][frames][errors]") {
  const TemporaryDirectory directory;
  std::ofstream(directory / "file") << "in the way\n";
  const std::string blocked = directory / "file/frames";
  const Outcome outcome =
      i2d("run " + kScenes + "bouncing_ball.toml --steps 2 --frames " + blocked);
  CHECK(outcome.exitCode == 1);
  CHECK(outcome.out.empty());
  CHECK(outcome.err.rfind("error: ", 0) == 0);
  CHECK(outcome.err.find(blocked) != std::string::npos);
  CHECK(std::count(outcome.err.begin(), outcome.err.end(), '\n') == 1);
  CHECK(directory.files() == std::vector<std::string>{"file"});
}

TEST_CASE("run --video without ffmpeg on PATH is one error line and exit code 1", "[i2d][frames]") {
  // i2d runs with an empty directory as its PATH, whether or not this machine has ffmpeg.
  const TemporaryDirectory directory;
  const Outcome outcome = i2d(
      "run " + kScenes + "bouncing_ball.toml --steps 2 --video --frames " + (directory / "frames"),
      "PATH=" + (directory / ""));
  CHECK(outcome.exitCode == 1);
  CHECK(outcome.err.rfind("error: --video needs ffmpeg on PATH", 0) == 0);
  CHECK(std::count(outcome.err.begin(), outcome.err.end(), '\n') == 1);
}

TEST_CASE("run --solver box2d writes the same CSV header and rows as micro", "[i2d][box2d][csv]") {
  const TemporaryDirectory directory;
  const std::string scene = "run " + kScenes + "incline_friction.toml --steps 12 --every 5 ";
  REQUIRE(i2d(scene + "--csv " + (directory / "micro.csv")).exitCode == 0);
  const Outcome box2d = i2d(scene + "--solver box2d --csv " + (directory / "box2d.csv"));
  CHECK(box2d.exitCode == 0);
  CHECK(box2d.out.find("solver box2d") != std::string::npos);
  const std::vector<std::string> micro = readLines(directory / "micro.csv");
  const std::vector<std::string> reference = readLines(directory / "box2d.csv");
  REQUIRE(reference.size() == micro.size());
  CHECK(micro.size() == 1 + 2 * 4);  // steps 0, 5, 10, 12 of the two boxes
  CHECK(reference[0] == kHeader);
  // The same step, time and body on every row; only the states differ.
  for (size_t row = 1; row < micro.size(); ++row) {
    INFO("row " << row);
    CHECK(stepTimeAndBody(reference[row]) == stepTimeAndBody(micro[row]));
  }
}

TEST_CASE("run --trace-step writes one frame per solver event of that step", "[i2d][trace]") {
  const TemporaryDirectory directory;
  const std::string run = "run " + kScenes + "resting_box.toml --frames " + (directory / "");
  // The box lands in step 13: two corners, resolved one impulse at a time.
  const Outcome outcome = i2d(run + " --trace-step 13");
  CHECK(outcome.exitCode == 0);
  const std::vector<std::string> frames =
      filesStartingWith(directory / "resting_box", "resting_box_step00013_");
  REQUIRE(frames.size() >= 3);  // at least two events and the sheet
  CHECK(frames.back() == "resting_box_step00013_sheet.png");
  CHECK(outcome.out.find("step 13: " + std::to_string(frames.size() - 1) + " solver events") !=
        std::string::npos);

  const Outcome box2d = i2d(run + " --trace-step 13 --solver box2d");
  CHECK(box2d.exitCode == 1);
  CHECK(box2d.err.rfind("error: solver box2d reports no solver events", 0) == 0);
}

TEST_CASE("run --trace-step past the end of the run is refused with the run's length",
          "[i2d][trace]") {
  const TemporaryDirectory directory;
  const std::string frames = directory / "frames";
  const Outcome outcome =
      i2d("run " + kScenes + "resting_box.toml --steps 30 --trace-step 31 " + "--frames " + frames);
  CHECK(outcome.exitCode == 2);
  CHECK(outcome.err ==
        "error: --trace-step 31 is past the end of the run, which has 30 steps; trace a step "
        "from 1 to 30 or give more with --steps\n");
  CHECK_FALSE(fs::exists(frames));
}

TEST_CASE("compare writes the solvers' frames side by side, labelled, and a sheet",
          "[i2d][compare]") {
  const TemporaryDirectory directory;
  const Outcome outcome = i2d("compare " + kScenes +
                              "bouncing_ball.toml --solvers micro,box2d --steps 4 --every 2 "
                              "--frames " +
                              (directory / ""));
  CHECK(outcome.exitCode == 0);
  CHECK(outcome.out.find("panel        micro: solver micro") != std::string::npos);
  CHECK(outcome.out.find("panel        box2d: solver box2d") != std::string::npos);
  const std::string frames = directory / "bouncing_ball";
  CHECK(filesStartingWith(frames, "bouncing_ball_compare") ==
        std::vector<std::string>{
            "bouncing_ball_compare.html", "bouncing_ball_compare_00000.png",
            "bouncing_ball_compare_00001.png", "bouncing_ball_compare_00002.png",
            "bouncing_ball_compare_energy.svg", "bouncing_ball_compare_plots.dat",
            "bouncing_ball_compare_plots.gp", "bouncing_ball_compare_sheet.png"});
  // Two 800 x 600 panels side by side (the grid nearest 16:9), spacing around each, a label
  // bar above each.
  const impulse2d::render::RenderSettings settings;
  const double textSize = impulse2d::render::frameTextSize(settings, 600);
  CHECK(pngSize(frames + "/bouncing_ball_compare_00002.png") ==
        std::pair<int, int>(
            2 * 800 + 3 * settings.spacing,
            600 + impulse2d::render::panelLabelHeight(settings, textSize) + 2 * settings.spacing));
}

TEST_CASE("compare --solvers SOLVER:PRESET shows a preset beside our default", "[i2d][compare]") {
  const TemporaryDirectory directory;
  const Outcome outcome = i2d("compare " + kScenes +
                              "stack.toml --solvers sequential,sequential:box2d_2_4 --steps 2 "
                              "--every 2 --frames " +
                              (directory / ""));
  CHECK(outcome.exitCode == 0);
  CHECK(outcome.out.find("panel        sequential: solver sequential") != std::string::npos);
  CHECK(outcome.out.find("panel        sequential:box2d_2_4: solver sequential") !=
        std::string::npos);
  CHECK(i2d("compare " + kScenes + "stack.toml --solvers micro:box2d_2_4 --frames " +
            (directory / ""))
            .exitCode == 2);
}

TEST_CASE("compare --panel runs the scene once per set of changes", "[i2d][compare]") {
  const TemporaryDirectory directory;
  const Outcome outcome =
      i2d("compare " + kScenes + "jitter.toml --steps 30 --every 30 --frames " + (directory / "") +
          " --panel 'removal on: solver.remove_acceleration_velocity=true'"
          " --panel 'removal off: solver.remove_acceleration_velocity=false;"
          " solver.lower_restitution_at_low_speed=false'");
  CHECK(outcome.exitCode == 0);
  CHECK(outcome.out.find("panel        removal on: solver micro") != std::string::npos);
  CHECK(outcome.out.find("panel        removal off: solver micro") != std::string::npos);
  // Two frames, the sheet, the viewer page and its energy plot (SVG, data, script).
  CHECK(filesStartingWith(directory / "jitter", "jitter_compare").size() == 2 + 1 + 1 + 3);

  const Outcome badPanel = i2d("compare " + kScenes + "jitter.toml --frames " + (directory / "") +
                               " --panel 'off: solver.no_such_key=1'");
  CHECK(badPanel.exitCode == 3);  // an unknown key, as it would be in the scene file
  CHECK(badPanel.err.find("no_such_key") != std::string::npos);
}

TEST_CASE("compare runs panels of other time steps for the same time, frames at equal times",
          "[i2d][compare]") {
  // A ball falling freely for 30 steps of 1/60 s, beside the same at 1/240 s. Symplectic Euler
  // gives v = g t exactly at t = n dt, and y = y0 − g t (t + dt)/2: both panels end with the
  // kinetic energy ½ m g² t², and their potential energies differ by m g² t (dt₁ − dt₂)/2, so
  // ΔP / K = (dt₁ − dt₂)/t whatever the mass. Run for 30 steps each, the fine panel stopped at
  // a quarter of the time.
  const TemporaryDirectory directory;
  std::ofstream(directory / "fall.toml") << "[world]\ngravity = [0.0, -9.81]\ndt = 0.0166666667\n"
                                            "steps = 30\n\n[[body]]\nname = \"ball\"\n"
                                            "shape = \"circle\"\nradius = 0.5\n"
                                            "position = [0.0, 10.0]\n";
  const Outcome outcome =
      i2d("compare " + (directory / "fall.toml") + " --every 10 --frames " + (directory / "") +
          " --panel '60 Hz: world.dt=0.0166666667'" + " --panel '240 Hz: world.dt=0.00416666667'");
  REQUIRE(outcome.exitCode == 0);
  const auto energies = [&](const std::string& label) {
    const std::size_t at = outcome.out.find("panel        " + label + ": ");
    std::pair<long, std::pair<double, double>> figures{-1, {0.0, 0.0}};
    if (at == std::string::npos) return figures;
    std::sscanf(outcome.out.c_str() + outcome.out.find(", ", at) + 2,
                "%ld steps, kinetic %lf J and potential %lf J", &figures.first,
                &figures.second.first, &figures.second.second);
    return figures;
  };
  const auto [coarseSteps, coarse] = energies("60 Hz");
  const auto [fineSteps, fine] = energies("240 Hz");
  CHECK(coarseSteps == 30);
  CHECK(fineSteps == 120);
  // The summary prints 6 significant digits: K (9.44796 J) to 5e-6 J, so the two kinetic
  // energies agree to 1e-5 of themselves; ΔP (0.236 J, from two 67 J figures) to 1e-4 J, which
  // is 4e-4 of it.
  CHECK(fine.first == Approx(coarse.first).epsilon(1e-5));
  const double t = 30 * 0.0166666667;
  CHECK((fine.second - coarse.second) / coarse.first ==
        Approx((0.0166666667 - 0.00416666667) / t).epsilon(5e-4));

  // The fine panel's steps are held to the size limit of any run: 600 steps of 1/60 s at 1 µs.
  const Outcome tooFine = i2d("compare " + kScenes + "pyramid.toml --frames " + (directory / "") +
                              " --panel 'a: world.dt=0.0166666667' --panel 'b: world.dt=1e-6'");
  CHECK(tooFine.exitCode == 3);
  CHECK(tooFine.err.find("panel 'b' takes 10000000 steps of its dt for the first panel's time") !=
        std::string::npos);
}

TEST_CASE("compare stops at a reference solve that fails, naming the panel and the step",
          "[i2d][compare][reference]") {
  // One Lemke pivot cannot solve the crate's landing, nor can the active set that Lemke's
  // failure falls back to with no factorization.
  const TemporaryDirectory directory;
  const std::string scene = writeDropScene(directory);
  const Outcome outcome =
      i2d("compare " + scene + " --frames " + (directory / "") +
          " --panel 'exact: solver.max_pivots=1; solver.max_factorizations=0' --panel 'also: '");
  CHECK(outcome.exitCode == 1);
  CHECK(outcome.err.rfind("error: panel 'exact' at step ", 0) == 0);
  CHECK(outcome.err.find("reference solver: Lemke: pivot limit of 1 reached") != std::string::npos);
  CHECK(std::count(outcome.err.begin(), outcome.err.end(), '\n') == 1);
}

TEST_CASE("agree prints a table per dynamic body, a row per method", "[i2d][agree][box2d]") {
  const Outcome outcome = i2d("agree " + kScenes + "incline_friction.toml --steps 30");
  CHECK(outcome.exitCode == 0);
  for (const char* text : {"# Agreement with Box2D: incline_friction", "## holds", "## slides",
                           "| box2d |", "| micro |", "| sequential |", "| reference |"}) {
    INFO(text);
    CHECK(outcome.out.find(text) != std::string::npos);
  }
  const Outcome one = i2d("agree " + kScenes + "incline_friction.toml --steps 30 --solvers micro");
  CHECK(one.out.find("| sequential |") == std::string::npos);
  CHECK(i2d("agree " + kScenes + "stack.toml --solvers box2d").exitCode == 2);
}

TEST_CASE("frame options without --frames, and bad overlays, are usage errors",
          "[i2d][frames][errors]") {
  const std::string scene = kScenes + "bouncing_ball.toml";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"run " + scene + " --video", "error: --video requires --frames\n"},
      {"run " + scene + " --trace-step 3", "error: --trace-step requires --frames\n"},
      {"run " + scene + " --video=yes", "error: video was given a disallowed flag override\n"},
      {"compare " + scene + " --frames f", "error: i2d compare needs --solvers or --panel\n"},
      {"compare " + scene + " --solvers micro", "error: --frames is required\n"},
      {"compare " + scene + " --frames f --solvers micro --panel 'a: world.dt=0.01'",
       "error: --solvers excludes --panel\n"},
      {"run " + scene + " --hide legend,arrows",
       "error: --hide: arrows not in {all,contact_normals,contact_points,friction_gauges,"
       "friction_impulses,heads_up,legend,loads,normal_impulses,rotation_marks,"
       "sliding_velocities,velocities,weights}\n"},
      {"run " + scene + " --frames x --size 100x100",
       "error: --size: each side at least 160 pixels and at most 67108864 pixels in all, not "
       "'100x100'\n"},
      {"run " + scene + " --frames x --size 1280",
       "error: --size: needs WIDTHxHEIGHT in pixels (e.g. 1280x720), not '1280'\n"},
      {"run " + scene + " --frames x --size 1280x720x2",
       "error: --size: needs WIDTHxHEIGHT in pixels (e.g. 1280x720), not '1280x720x2'\n"},
      {"run " + scene + " --frames x --format gif", "error: --format: gif not in {pdf,png,svg}\n"},
      {"run " + scene + " --frames x --theme dark", "error: --theme: dark not in {screen,print}\n"},
  };
  for (const auto& [arguments, message] : cases) {
    INFO("i2d " << arguments);
    const Outcome outcome = i2d(arguments);
    CHECK(outcome.exitCode == 2);
    CHECK(outcome.err == message);
  }
}

TEST_CASE("a reference solve that fails ends the run with one error line and exit code 1",
          "[i2d][reference]") {
  const Outcome outcome =
      i2d("run " + kScenes + "stack.toml --solver reference --set solver.max_pivots=3" +
          " --set solver.max_factorizations=0");
  CHECK(outcome.exitCode == 1);
  CHECK(outcome.err.rfind("error: step 1 (t = 0.0166667 s): reference solver: Lemke: pivot limit "
                          "of 3 reached",
                          0) == 0);
  CHECK(std::count(outcome.err.begin(), outcome.err.end(), '\n') == 1);
}

TEST_CASE("a reference solve that fails names its step and keeps the rows before it",
          "[i2d][reference][csv]") {
  // One Lemke pivot cannot solve the crate's landing, nor can the active set with no
  // factorization, so the run stops at that step, as a body that overflows does.
  const TemporaryDirectory directory;
  const std::string scene = writeDropScene(directory);
  const std::string csv = directory / "drop.csv";
  const Outcome outcome = i2d("run " + scene + " --csv " + csv +
                              " --set solver.max_pivots=1 --set solver.max_factorizations=0");
  CHECK(outcome.exitCode == 1);
  REQUIRE(outcome.err.rfind("error: step ", 0) == 0);
  CHECK(outcome.err.find("reference solver: Lemke: pivot limit of 1 reached") != std::string::npos);
  CHECK(std::count(outcome.err.begin(), outcome.err.end(), '\n') == 1);
  const long failed = std::stol(outcome.err.substr(std::string("error: step ").size()));
  CHECK(failed > 1);  // the fall before the landing ran
  const std::vector<std::string> lines = readLines(csv);
  REQUIRE(lines.size() >= 2);
  CHECK(lines[0] == kHeader);
  CHECK(lines.back().rfind(std::to_string(failed - 1) + ",", 0) == 0);  // the step before
}

TEST_CASE("run --error-vs-reference writes one row per solve and summarises the errors",
          "[i2d][reference]") {
  const TemporaryDirectory directory;
  const std::string path = directory / "errors.csv";
  const Outcome outcome = i2d(
      "run " + kScenes + "stack.toml --solver sequential --steps 5 --error-vs-reference " + path);
  CHECK(outcome.exitCode == 0);
  const std::vector<std::string> lines = readLines(path);
  REQUIRE(lines.size() == 6);
  CHECK(lines[0] == "solve,t,points,impulse_error,velocity_error,violation,exact_answer");
  for (const char* line : {"impulse err  median", "velocity err median", "violation    median"}) {
    CHECK(outcome.out.find(line) != std::string::npos);
  }
  const Outcome both = i2d("run " + kScenes + "stack.toml --csv " + (directory / "t.csv") +
                           " --error-vs-reference " + path);
  CHECK(both.exitCode == 2);
}
