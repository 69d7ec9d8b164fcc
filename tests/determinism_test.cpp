// Determinism: the same scene, solver and settings give a bit-identical trajectory on every run,
// in this process and through the i2d program, so frame sequences and CSVs can be compared
// offline. What could break it, and what the build sets so it holds: docs/determinism.md.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "impulse2d/box2d/box2d_simulation.h"
#include "impulse2d/scene/scene_file.h"

namespace fs = std::filesystem;
using namespace impulse2d;

namespace {

/// At most this many steps per run: 1 s of simulated time, by which the bodies of every shipped
/// scene are in contact and each solver works at full load. It keeps the slowest case (the
/// micro-collision resolver on the 55-box pyramid, about 25 ms a step) to seconds, also under
/// the sanitizers.
constexpr int kMaxSteps = 60;

/// The solvers each scene is run with besides its own, on scenes of at most kMostBodiesForAll
/// dynamic bodies. On bigger ones (the benchmark pyramids, rain) only the scene's own solver runs:
/// the micro-collision resolver takes 0.2 s a step on 210 boxes. The reference solver (Lemke) runs
/// only where it is the scene's own: on big scenes it takes minutes a step.
const std::vector<std::string> kAlsoSolvers = {"micro", "sequential", "box2d"};
constexpr int kMostBodiesForAll = 60;

std::vector<fs::path> shippedScenes() {
  std::vector<fs::path> scenes;
  for (const auto& entry : fs::directory_iterator(IMPULSE2D_SOURCE_DIR "/demos/scenes")) {
    if (entry.path().extension() == ".toml") scenes.push_back(entry.path());
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

std::vector<std::string> solversFor(const Scene& scene) {
  std::vector<std::string> solvers = {scene.solver};
  const auto dynamic =
      std::count_if(scene.bodies.begin(), scene.bodies.end(),
                    [](const BodyDef& body) { return body.type != BodyType::Static; });
  if (dynamic > kMostBodiesForAll) return solvers;
  for (const std::string& solver : kAlsoSolvers) {
    if (solver != scene.solver) solvers.push_back(solver);
  }
  return solvers;
}

/// FNV-1a, 64 bits: a hash that changes with any bit of the trajectory.
std::uint64_t fnv1a(const std::string& bytes) {
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char byte : bytes) hash = (hash ^ byte) * 1099511628211ull;
  return hash;
}

void appendNumber(std::string& csv, double value) {
  char buffer[32];
  csv.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

/// The rows `i2d run --csv` writes for the current step (docs/i2d.md#the-csv).
void appendRows(std::string& csv, const Simulation& simulation) {
  for (const Body& body : simulation.bodies()) {
    if (body.isStatic()) continue;
    csv += std::to_string(simulation.stepCount()) + ',';
    appendNumber(csv, double(simulation.stepCount()) * simulation.settings().dt);
    csv += ',' + body.name;
    for (double value : {body.position.x(), body.position.y(), body.angle, body.velocity.x(),
                         body.velocity.y(), body.angularVelocity}) {
      csv += ',';
      appendNumber(csv, value);
    }
    csv += '\n';
  }
}

/// The trajectory CSV of the scene under the solver, built in this process.
std::string trajectory(Scene scene, const std::string& solver, int steps) {
  scene.solver = solver;
  const std::unique_ptr<Simulation> simulation = makeSimulation(scene);
  std::string csv = "step,t,body,x,y,angle_rad,vx,vy,omega_rad_s\n";
  appendRows(csv, *simulation);
  for (int step = 0; step < steps; ++step) {
    simulation->step();
    appendRows(csv, *simulation);
  }
  return csv;
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

/// The CSV `i2d run` writes for the scene under the solver.
std::string i2dTrajectory(const fs::path& scene, const std::string& solver, int steps) {
  const fs::path csv = fs::temp_directory_path() /
                       ("determinism_" + std::to_string(getpid()) + "_" + solver + ".csv");
  const std::string command = IMPULSE2D_BINARY_DIR "/apps/i2d run " + scene.string() +
                              " --solver " + solver + " --steps " + std::to_string(steps) +
                              " --csv " + csv.string() + " >/dev/null";
  const int status = std::system(command.c_str());
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  const std::string bytes = readFile(csv);
  fs::remove(csv);
  return bytes;
}

int cappedSteps(const Scene& scene) {
  return std::min(scene.steps, kMaxSteps);
}

}  // namespace

TEST_CASE("every shipped scene runs to the same bits twice in one process",
          "[determinism][scenes]") {
  REQUIRE(shippedScenes().size() >= 10);
  for (const fs::path& path : shippedScenes()) {
    const Scene scene = loadSceneFile(path.string());
    for (const std::string& solver : solversFor(scene)) {
      const std::string first = trajectory(scene, solver, cappedSteps(scene));
      const std::string second = trajectory(scene, solver, cappedSteps(scene));
      INFO(path.filename().string() << " under " << solver);
      CHECK(fnv1a(first) == fnv1a(second));
      std::cout << "figure: " << scene.name << " " << solver << " " << cappedSteps(scene)
                << " steps: trajectory FNV-1a " << std::hex << fnv1a(first) << std::dec << "\n";
    }
  }
}

TEST_CASE("i2d run writes the same CSV bytes every time, those of the in-process run",
          "[determinism][i2d]") {
  for (const fs::path& path : shippedScenes()) {
    const Scene scene = loadSceneFile(path.string());
    for (const std::string& solver : solversFor(scene)) {
      INFO(path.filename().string() << " under " << solver);
      const std::string first = i2dTrajectory(path, solver, cappedSteps(scene));
      const std::string second = i2dTrajectory(path, solver, cappedSteps(scene));
      CHECK(fnv1a(first) == fnv1a(second));
      CHECK(fnv1a(first) == fnv1a(trajectory(scene, solver, cappedSteps(scene))));
    }
  }
}
