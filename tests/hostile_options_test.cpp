// Command-line mistakes that used to pass silently or leave debris: a failed write leaves no
// temporary file, every output option creates the directories it needs the same way, a
// malformed --panel is refused, and bodies that start deep in each other are warned about.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "i2d_process.h"

using namespace i2d_process;
namespace fs = std::filesystem;

namespace {

// From the literal, not from kScenes: the order in which one file's dynamic initializers run
// against a header's inline variable is one clang and gcc take differently.
const std::string kBox = IMPULSE2D_SOURCE_DIR "/demos/scenes/resting_box.toml --steps 3";

/// A box placed 0.3 m inside the ground (its bottom face at y = -0.3).
const std::string kSunkBox = R"([world]
steps = 3
solver = "sequential"

[[body]]
name = "ground"
type = "static"
shape = "box"
size = [20.0, 1.0]
position = [0.0, -0.5]

[[body]]
name = "sunk"
shape = "box"
size = [1.0, 1.0]
position = [0.0, 0.2]
)";

}  // namespace

TEST_CASE("a failed write leaves no temporary file beside its target", "[outputs][errors]") {
  const Scratch scratch;
  fs::create_directory(scratch / "taken");
  const Outcome errors =
      i2d("run " + kBox + " --error-vs-reference " + (scratch / "taken"), scratch);
  CHECK(errors.exitCode == 1);
  CHECK(errors.err == "error: cannot write " + (scratch / "taken") + ": Is a directory\n");
  CHECK(scratch.entries() == std::vector<std::string>{"taken"});
  const Outcome csv = i2d("run " + kBox + " --csv " + (scratch / "taken"), scratch);
  CHECK(csv.exitCode == 1);
  CHECK(scratch.entries() == std::vector<std::string>{"taken"});
}

TEST_CASE("one file named twice, by --csv and --contacts, is refused before the run",
          "[outputs][errors]") {
  // Each would rename its temporary file over the other's: the second rename failed after the
  // run, leaving the file holding the contacts; two to standard output interleaved their rows.
  const Scratch scratch;
  writeFile(scratch / "old.csv", "an older run\n");
  fs::create_symlink(scratch / "old.csv", scratch / "link.csv");
  for (const auto& [csv, contacts] : std::vector<std::pair<std::string, std::string>>{
           {scratch / "old.csv", scratch / "link.csv"},
           {scratch / "new.csv", scratch.path.string() + "/./new.csv"},
           {"-", "/dev/stdout"}}) {
    const Outcome outcome =
        i2d("run " + kBox + " --csv " + csv + " --contacts " + contacts, scratch);
    INFO(csv << " and " << contacts);
    CHECK(outcome.exitCode == 2);
    CHECK(outcome.err ==
          "error: --csv and --contacts both write '" + contacts + "'; give each its own file\n");
  }
  CHECK(scratch.entries() == std::vector<std::string>{"link.csv", "old.csv"});
  const Outcome devices = i2d("run " + kBox + " --csv /dev/null --contacts /dev/null", scratch);
  CHECK(devices.exitCode == 0);
}

TEST_CASE("every output option creates the directories its path needs", "[outputs]") {
  const Scratch scratch;
  const Outcome run =
      i2d("run " + kBox + " --csv " + (scratch / "a/b/run.csv") + " --plots " + (scratch / "c/d") +
              " --frames " + (scratch / "e/f") + " --contacts " + (scratch / "m/n/contacts.csv"),
          scratch);
  CHECK(run.exitCode == 0);
  CHECK(fs::is_regular_file(scratch / "a/b/run.csv"));
  CHECK(fs::is_regular_file(scratch / "m/n/contacts.csv"));
  CHECK(fs::is_regular_file(scratch / "c/d/resting_box_kinetic.png"));
  CHECK(fs::is_regular_file(scratch / "e/f/resting_box/resting_box_00000.png"));
  const Outcome errors =
      i2d("run " + kBox + " --error-vs-reference " + (scratch / "g/h/errors.csv"), scratch);
  CHECK(errors.exitCode == 0);
  CHECK(fs::is_regular_file(scratch / "g/h/errors.csv"));
  const Outcome compare = i2d("compare " + kBox + " --solvers micro,sequential --frames " +
                                  (scratch / "i/j") + " --plots " + (scratch / "k/l"),
                              scratch);
  CHECK(compare.exitCode == 0);
  CHECK(fs::is_directory(scratch / "i/j/resting_box"));
  CHECK(fs::is_directory(scratch / "k/l"));

  writeFile(scratch / "file", "in the way\n");
  const Outcome blocked = i2d("run " + kBox + " --plots " + (scratch / "file/plots"), scratch);
  CHECK(blocked.exitCode == 1);
  CHECK(blocked.err == "error: cannot create directory '" + (scratch / "file/plots") +
                           "' for --plots: Not a directory\n");
}

TEST_CASE("a --panel missing its colon or an assignment's '=' is refused, exit 2",
          "[options][compare]") {
  const Scratch scratch;
  const std::string compare = "compare " + kBox + " --frames " + (scratch / "frames");
  const Outcome noColon = i2d(compare + " --panel 'on: solver.warm_starting=true'" +
                                  " --panel 'off solver.warm_starting=false'",
                              scratch);
  CHECK(noColon.exitCode == 2);
  CHECK(noColon.err ==
        "error: --panel: needs a colon after its label, 'LABEL: section.key=value; ...', not "
        "'off solver.warm_starting=false'\n");
  const Outcome noEquals = i2d(compare + " --panel 'off: solver.warm_starting'", scratch);
  CHECK(noEquals.exitCode == 2);
  CHECK(noEquals.err ==
        "error: --panel: needs section.key=value, such as solver.velocity_iterations=12, not "
        "'solver.warm_starting'\n");
  CHECK_FALSE(fs::exists(scratch / "frames"));
  const Outcome labelOnly = i2d(compare +
                                    " --panel 'defaults' --panel 'cold: "
                                    "solver.warm_starting=false'",
                                scratch);
  CHECK(labelOnly.exitCode == 0);  // a label alone still runs the defaults
}

TEST_CASE("check and run warn about bodies that start overlapping more than allowed",
          "[options][overlap]") {
  const Scratch scratch;
  const std::string scene = scratch / "sunk.toml";
  writeFile(scene, kSunkBox);
  const std::string warning =
      "warning: bodies ground and sunk start overlapping by 0.3 m, more than the allowed "
      "penetration of 0.005 m; the solver will push them apart\n";
  const Outcome check = i2d("check " + scene, scratch);
  CHECK(check.exitCode == 0);
  CHECK(check.err == warning);
  const Outcome run = i2d("run " + scene, scratch);
  CHECK(run.exitCode == 0);
  CHECK(run.err == warning);
  const Outcome resting = i2d("check " + kScenes + "resting_box.toml", scratch);
  CHECK(resting.err.empty());
}
