// A full disk: CSV rows, frames and contact sheets whose writing fails give one clear error (exit
// 1 from i2d) and never leave a half-written file under the final name. Linux's /dev/full fails
// every write with ENOSPC; a symbolic link from the temporary file's name to it makes any file
// "on a full disk". A CSV named by a link, a device or a pipe is written where the name leads,
// never renamed over it. (A missing directory is tested in i2d_test.cpp and
// frame_writer_test.cpp.)
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <string>
#include <vector>

#include "i2d_process.h"
#include "impulse2d/render/frame_writer.h"
#include "impulse2d/render/png.h"

namespace fs = std::filesystem;
using namespace i2d_process;
using namespace impulse2d::render;
using impulse2d::Vec2;

namespace {

const std::string kFullDisk = "/dev/full";
const std::string kNoSpace = "No space left on device";

/// Makes writing to `path` fail as on a full disk.
void onFullDisk(const fs::path& path) {
  fs::create_symlink(kFullDisk, path);
}

Image greyImage() {
  return Image(64, 48, Color{128, 128, 128, 255});
}

/// A frame whose picture is one grey rectangle.
Frame greyFrame() {
  Frame frame;
  frame.picture = Picture(64, 48);
  frame.sceneSize = Vec2(64.0, 48.0);
  frame.caption = "grey";
  Drawing(frame.picture).rectangle(Vec2::Zero(), Vec2(64.0, 48.0), Color{128, 128, 128, 255});
  return frame;
}

}  // namespace

TEST_CASE("a CSV on a full disk is one error line, exit code 1, and no file", "[disk][csv]") {
  REQUIRE(fs::exists(kFullDisk));
  // One step fits in the stream's buffer, so the error shows when the file is closed; the whole
  // run does not, so it shows while rows are written.
  for (const std::string steps : {"1", "360"}) {
    const Scratch directory;
    const std::string csv = directory / "ball.csv";
    onFullDisk(csv + ".tmp");
    const Outcome outcome =
        i2d("run " + kScenes + "bouncing_ball.toml --steps " + steps + " --csv " + csv, directory);
    INFO(steps << " steps");
    CHECK(outcome.exitCode == 1);
    CHECK(outcome.err == "error: cannot write " + csv + ".tmp: " + kNoSpace + "\n");
    CHECK(fs::is_empty(directory.path));
  }
}

TEST_CASE("a PNG on a full disk throws naming the cause and leaves no file", "[disk][png]") {
  REQUIRE(fs::exists(kFullDisk));
  const Scratch directory;
  const fs::path png = directory / "frame.png";
  onFullDisk(directory / "frame.png.tmp");
  CHECK_THROWS_WITH(writePng(png, greyImage()), Catch::Contains(kNoSpace));
  CHECK(fs::is_empty(directory.path));
}

TEST_CASE("a frame on a full disk is not counted and leaves no file", "[disk][frames]") {
  REQUIRE(fs::exists(kFullDisk));
  const Scratch directory;
  FrameWriter frames(directory.path, "scene");
  onFullDisk(frames.framePath(0).string() + ".tmp");
  CHECK_THROWS_WITH(frames.write(0, greyFrame()), Catch::Contains(kNoSpace));
  CHECK(frames.frameCount() == 0);
  CHECK(fs::is_empty(frames.directory()));
}

TEST_CASE("i2d run --frames on a full disk is one error line, exit code 1, and no sheet",
          "[disk][frames]") {
  REQUIRE(fs::exists(kFullDisk));
  const Scratch directory;
  const fs::path scene = directory.path / "bouncing_ball";
  fs::create_directory(scene);
  onFullDisk(scene / "bouncing_ball_sheet.png.tmp");
  const Outcome outcome =
      i2d("run " + kScenes + "bouncing_ball.toml --steps 2 --frames " + directory.path.string(),
          directory);
  CHECK(outcome.exitCode == 1);
  CHECK(outcome.err == "error: cannot write image '" +
                           (scene / "bouncing_ball_sheet.png.tmp").string() + "': " + kNoSpace +
                           "\n");
  CHECK_FALSE(fs::exists(scene / "bouncing_ball_sheet.png"));
  CHECK_FALSE(fs::is_symlink(scene / "bouncing_ball_sheet.png.tmp"));
}

TEST_CASE("a CSV through a link to a full device is the device's error, and the link stays",
          "[disk][csv]") {
  // Written in place, as a device must be: a rename over the link would hide the full disk.
  REQUIRE(fs::exists(kFullDisk));
  const Scratch directory;
  const std::string csv = directory / "ball.csv";
  fs::create_symlink(kFullDisk, csv);
  const Outcome outcome =
      i2d("run " + kScenes + "bouncing_ball.toml --steps 1 --csv " + csv, directory);
  CHECK(outcome.exitCode == 1);
  CHECK(outcome.err == "error: cannot write " + csv + ": " + kNoSpace + "\n");
  CHECK(fs::is_symlink(csv));
  CHECK(fs::is_character_file(kFullDisk));
}

TEST_CASE("a CSV written to a named pipe reaches its reader, and the pipe stays a pipe",
          "[disk][csv]") {
  const Scratch directory;
  const std::string pipe = directory / "ball.pipe";
  REQUIRE(mkfifo(pipe.c_str(), 0600) == 0);
  // Opened first without blocking, so i2d's open finds a reader; one step of rows fits in the
  // pipe's buffer, so i2d finishes before anything is read.
  const int reader = open(pipe.c_str(), O_RDONLY | O_NONBLOCK);
  REQUIRE(reader >= 0);
  const Outcome outcome =
      i2d("run " + kScenes + "bouncing_ball.toml --steps 1 --csv " + pipe, directory);
  std::string received(4096, '\0');
  const ssize_t count = read(reader, received.data(), received.size());
  close(reader);
  received.resize(std::size_t(std::max<ssize_t>(count, 0)));
  CHECK(outcome.exitCode == 0);
  CHECK(fs::is_fifo(pipe));
  CHECK(received.rfind("step,t,body,", 0) == 0);
  CHECK(lineCount(received) == 3);  // the header, then steps 0 and 1 of the one ball
}

TEST_CASE("a CSV through a link replaces the file it names, and the link stays", "[disk][csv]") {
  const Scratch directory;
  const std::string file = directory / "ball.csv";
  const std::string link = directory / "latest.csv";
  writeFile(file, "an older run\n");
  fs::create_symlink(file, link);
  const Outcome outcome =
      i2d("run " + kScenes + "bouncing_ball.toml --steps 1 --csv " + link, directory);
  CHECK(outcome.exitCode == 0);
  CHECK(fs::is_symlink(link));
  CHECK(readFile(file).rfind("step,t,body,", 0) == 0);
}

TEST_CASE("a CSV to standard output comes before the summary", "[disk][csv]") {
  const Scratch directory;
  for (const std::string name : {"-", "/dev/stdout"}) {
    const Outcome outcome =
        i2d("run " + kScenes + "bouncing_ball.toml --steps 1 --csv " + name, directory);
    INFO("--csv " << name << ":\n" << outcome.out);
    CHECK(outcome.exitCode == 0);
    CHECK(outcome.out.rfind("step,t,body,x,y,angle_rad,vx,vy,omega_rad_s\n0,0,ball,", 0) == 0);
    CHECK(outcome.out.find("\nscene        bouncing_ball") != std::string::npos);
  }
  CHECK(fs::is_symlink("/dev/stdout"));
}

TEST_CASE("i2d's own output on a full disk is one error line and exit code 1", "[disk]") {
  REQUIRE(fs::exists(kFullDisk));
  const Scratch directory;
  for (const std::string& command :
       std::vector<std::string>{"check " + kScenes + "stack.toml", "presets", "--help",
                                "run " + kScenes + "bouncing_ball.toml --steps 2"}) {
    const Outcome outcome = i2d(command, directory, kFullDisk);
    INFO("i2d " << command);
    CHECK(outcome.exitCode == 1);
    CHECK(outcome.err == "error: cannot write standard output: " + kNoSpace + "\n");
  }
}

TEST_CASE("an interrupted run removes its temporary CSV and ends as the signal says",
          "[disk][csv]") {
  // Ctrl-C during a long run left rain.csv.tmp, as large as the rows so far.
  const Scratch directory;
  const std::string csv = directory / "rain.csv";
  const std::string scene = kScenes + "rain.toml";
  const pid_t child = fork();
  if (child == 0) {
    std::signal(SIGINT, SIG_DFL);  // as at a terminal, whatever the test's caller ignores
    const int quiet = open("/dev/null", O_WRONLY);
    dup2(quiet, 1);
    dup2(quiet, 2);
    execl(kBinary.c_str(), "i2d", "run", scene.c_str(), "--steps", "20000", "--every", "1000",
          "--csv", csv.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  // The signal must find the temporary file open: wait for it to appear, however slow the build,
  // unless the run ends first. It is opened before the first of 20,000 steps, which take
  // seconds, so the run is still going when the signal follows.
  int status = 0;
  bool ended = false;
  while (!fs::exists(csv + ".tmp") && !ended) {
    ended = waitpid(child, &status, WNOHANG) == child;
    usleep(1000);
  }
  if (!ended) {
    kill(child, SIGINT);
    waitpid(child, &status, 0);
  }
  REQUIRE_FALSE(ended);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGINT);
  CHECK(fs::is_empty(directory.path));
}
