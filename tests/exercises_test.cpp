// The answers of docs/exercises.md, each asserted against the lecture's formula with the
// tolerance the page states. The scenes are read out of the page itself, so the page and the
// test cannot drift apart.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <string>

#include "doc_blocks.h"
#include "i2d_process.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/world.h"
#include "solver_scenes.h"

using namespace impulse2d;

namespace {

constexpr double g = 9.81;
constexpr double kDegree = kPi / 180.0;

/// The scene saved as `name` in docs/exercises.md, with `from` replaced by `to` if given (the
/// page's "edit angle_deg to 32").
SceneFile exerciseScene(const std::string& name, const std::string& from = "",
                        const std::string& to = "") {
  std::string text = doc_blocks::namedBlock(doc_blocks::readBlocks("docs/exercises.md"), name);
  if (!from.empty()) {
    const size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
  }
  return parseScene(text, name);
}

int indexOf(const Scene& scene, const std::string& name) {
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].name == name) return int(i);
  }
  FAIL("no body " << name);
  return -1;
}

/// The total normal impulse of the contact between bodies a and b in the last step.
double contactImpulse(const Simulation& world, int a, int b) {
  return solvers::contactForce(world, a, b) * world.settings().dt;
}

double travelAfter(const Scene& scene, const std::string& body, int steps) {
  auto world = buildWorld(scene);
  solvers::runSteps(*world, steps);
  const int index = indexOf(scene, body);
  return (world->bodies()[index].position - scene.bodies[index].position).norm();
}

}  // namespace

TEST_CASE("exercise 1: a resting box is held by its weight, m g, at half its height",
          "[exercises][resting]") {
  const SceneFile scene = exerciseScene("resting.toml");
  auto world = buildWorld(scene);
  solvers::runSteps(*world, 60);
  for (int step = 60; step < 120; ++step) {
    world->step();
    CHECK(solvers::contactForce(*world, 0, 1) == Approx(2.0 * g).epsilon(0.01));
  }
  CHECK(std::abs(world->bodies()[1].position.y() - 0.5) < 0.005);
}

TEST_CASE("exercise 2: micro-collisions turn the resting force into m g dt an update",
          "[exercises][micro]") {
  SceneFile scene = exerciseScene("resting.toml");
  scene.solver = "micro";
  for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
    scene.world.dt = dt;
    auto world = buildWorld(scene);
    solvers::runSteps(*world, 60);
    INFO("dt " << dt);
    CHECK(contactImpulse(*world, 0, 1) == Approx(2.0 * g * dt).epsilon(0.01));
  }
}

TEST_CASE("exercise 3: without removing accelerative velocity a resting box hops at e g dt",
          "[exercises][acceleration]") {
  SceneFile scene = exerciseScene("hop.toml");
  const double dt = scene.world.dt;
  auto off = buildWorld(scene);
  off->step();
  CHECK(off->bodies()[1].velocity.y() == Approx(0.9 * g * dt).epsilon(0.02));
  scene.solverSettings.micro.removeAccelerationVelocity = true;
  auto on = buildWorld(scene);
  on->step();
  CHECK(std::abs(on->bodies()[1].velocity.y()) < 1e-9);
}

namespace {

/// The highest the ball's lowest point rises above the ground after it first lands.
double apexAfterLanding(const Scene& scene, int steps) {
  auto world = buildWorld(scene);
  const Body& ball = world->bodies()[1];
  bool landed = false;
  double apex = 0.0;
  for (int step = 0; step < steps; ++step) {
    const double before = ball.velocity.y();
    world->step();
    landed = landed || (before < 0.0 && ball.velocity.y() >= 0.0);
    if (landed) apex = std::max(apex, ball.position.y() - 0.5);
  }
  REQUIRE(landed);
  return apex;
}

}  // namespace

TEST_CASE("exercise 4: a ball bounces to e² h, and not at all under the velocity limit",
          "[exercises][restitution]") {
  const SceneFile high = exerciseScene("ball.toml");
  CHECK(apexAfterLanding(high, 120) == Approx(0.64 * 2.0).epsilon(0.03));
  const SceneFile low =
      exerciseScene("ball.toml", "position = [0.0, 2.5]", "position = [0.0, 0.502]");
  CHECK(apexAfterLanding(low, 120) < 0.0005);
}

TEST_CASE("exercise 5: static friction holds a box while tan θ ≤ μ", "[exercises][friction]") {
  // The two slopes lie either side of the friction angle atan 0.6 = 30.96°.
  REQUIRE(std::tan(30.0 * kDegree) < 0.6);
  REQUIRE(std::tan(32.0 * kDegree) > 0.6);
  CHECK(travelAfter(exerciseScene("incline.toml"), "box", 120) < 0.001);
  const SceneFile steeper = exerciseScene("incline.toml", "angle_deg = 30.0", "angle_deg = 32.0");
  CHECK(travelAfter(steeper, "box", 120) > 0.1);
}

TEST_CASE("exercise 6: a sliding box accelerates at g (sin θ − μ cos θ)", "[exercises][friction]") {
  const double mu = std::sqrt(0.6 * 0.1);
  const double a = g * (std::sin(30.0 * kDegree) - mu * std::cos(30.0 * kDegree));
  CHECK(travelAfter(exerciseScene("slide.toml"), "box", 120) ==
        Approx(a * 2.0 * 2.0 / 2.0).epsilon(0.01));
}

TEST_CASE("exercise 7: a push growing at 2 N/s overcomes μ m g at 2.45 s",
          "[exercises][friction]") {
  const SceneFile scene = loadSceneFile(IMPULSE2D_SOURCE_DIR "/demos/scenes/pushed_box.toml");
  const double start = 0.5 * 1.0 * g / 2.0;  // μ m g over the push's rate
  REQUIRE(start == Approx(2.4525));
  const int before = int(std::lround((start - 0.1) / scene.world.dt));
  const int after = int(std::lround((start + 0.3) / scene.world.dt));
  CHECK(travelAfter(scene, "box", before) < 1e-4);
  CHECK(travelAfter(scene, "box", after) > 1e-3);
}

TEST_CASE("exercise 8: under sequential impulses each contact carries the weight above it",
          "[exercises][sequential]") {
  const SceneFile scene = exerciseScene("tower.toml");
  auto world = buildWorld(scene);
  solvers::runSteps(*world, 60);
  for (int step = 60; step < 120; ++step) {
    world->step();
    for (int level = 0; level < 10; ++level) {
      INFO("contact under box " << level + 1 << ", step " << step);
      CHECK(solvers::contactForce(*world, level, level + 1) ==
            Approx((10 - level) * g).epsilon(0.02));
    }
  }
}

TEST_CASE("exercise 9: a 20-box tower stands with accumulated impulses, fails without",
          "[exercises][accumulation]") {
  SceneFile scene = exerciseScene("tower.toml", "count = 10", "count = 20");
  const double slopAllowance = 20 * scene.solverSettings.sequential.targets.allowedPenetration;
  CHECK(travelAfter(scene, "box20", 600) < slopAllowance);
  scene.solverSettings.sequential.impulses = ImpulseAccumulation::ClampedEach;
  CHECK(travelAfter(scene, "box20", 600) > slopAllowance);
}

TEST_CASE("exercise 10: warm started, 10 sweeps a step hold a 10-box tower, from zero it sinks",
          "[exercises][warm_starting]") {
  SceneFile scene = exerciseScene("tower.toml");
  scene.solverSettings.sequential.velocityIterations = 10;
  const double slopAllowance = 10 * scene.solverSettings.sequential.targets.allowedPenetration;
  CHECK(travelAfter(scene, "box10", 600) < slopAllowance);
  scene.solverSettings.sequential.impulses = ImpulseAccumulation::Accumulated;
  CHECK(travelAfter(scene, "box10", 600) > slopAllowance);
}

TEST_CASE("exercise 11: the penetration bias removes β of the overlap beyond the slop a step",
          "[exercises][bias]") {
  SceneFile scene = exerciseScene("sunk.toml");
  const auto depth = [](const Simulation& world) { return 0.5 - world.bodies()[1].position.y(); };
  auto world = buildWorld(scene);
  const ContactTargetSettings& targets = scene.solverSettings.sequential.targets;
  const double slop = targets.allowedPenetration;
  world->step();
  CHECK(depth(*world) == Approx(0.05 - targets.biasFactor * (0.05 - slop)).margin(0.0005));
  solvers::runSteps(*world, 119);
  CHECK(std::abs(depth(*world) - slop) < 1e-4);
  scene.solverSettings.sequential.targets.penetrationBias = false;
  auto unbiased = buildWorld(scene);
  solvers::runSteps(*unbiased, 120);
  CHECK(depth(*unbiased) > 0.049);
}

TEST_CASE("every i2d command the exercises give runs, on the page's scenes", "[exercises][docs]") {
  namespace fs = std::filesystem;
  const i2d_process::Scratch scratch;
  fs::create_directory_symlink(IMPULSE2D_BINARY_DIR, scratch.path / "build");
  fs::create_directory_symlink(IMPULSE2D_SOURCE_DIR "/demos", scratch.path / "demos");
  for (const doc_blocks::Block& block : doc_blocks::readBlocks("docs/exercises.md")) {
    if (!block.name.empty()) i2d_process::writeFile(scratch / block.name, block.text);
  }
  // The commands are inline code, `build/apps/i2d ...`, which may wrap over lines.
  const std::string page = i2d_process::readFile(IMPULSE2D_SOURCE_DIR "/docs/exercises.md");
  const std::regex command("`(build/apps/i2d [^`]*)`");
  int commands = 0;
  for (auto match = std::sregex_iterator(page.begin(), page.end(), command);
       match != std::sregex_iterator(); ++match) {
    const std::string line = std::regex_replace((*match)[1].str(), std::regex("\\s+"), " ");
    const std::string shell = "cd " + scratch.path.string() + " && " + line + " >/dev/null 2>&1";
    INFO(line);
    CHECK(std::system(shell.c_str()) == 0);
    ++commands;
  }
  CHECK(commands >= 10);
}
