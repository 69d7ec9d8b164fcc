// A state that overflows: a load or speed beyond what a double holds stops every solver and every
// command at the first non-finite body, with one line naming the body, the step and the solver;
// nothing pivots on NaN, and no command reports a non-finite figure.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <memory>

#include "i2d_process.h"
#include "impulse2d/box2d/box2d_simulation.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/solvers/lcp.h"

using namespace i2d_process;

namespace {

/// A plank balanced on the tip of a static wedge, pushed by 1e308 N up and sideways: its speed
/// overflows in the first step. Before the world stopped such a step, the reference's Lemke
/// pivoted on the NaN velocities of the tipping contact and crashed (a segmentation fault).
const std::string kOverflowingPlank = R"([world]
steps = 5
solver = "reference"

[[body]]
name = "fulcrum"
type = "static"
shape = "polygon"
vertices = [[-0.4, 0.0], [0.4, 0.0], [0.0, 1.0]]

[[body]]
name = "plank"
shape = "box"
size = [5.0, 0.1]
position = [0.0, 1.05]
force = [1e308, 1e308]
)";

/// Gravity of -1e154 m/s² over 1 s steps on a disc of 0.5 m (0.785 kg) above a floor: step 1
/// leaves energies near 1e308 J, step 2 overflows them.
const std::string kRocket = R"([world]
gravity = [0, -1e154]
dt = 1
steps = 10
solver = "micro"

[[body]]
name = "rocket"
shape = "circle"
radius = 0.5
)";

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

TEST_CASE("Lemke refuses a problem that is not finite instead of pivoting on NaN",
          "[non-finite][lcp]") {
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(2, 2);
  Eigen::MatrixXd overflowed = identity;
  overflowed(0, 1) = kInfinity;
  const Eigen::VectorXd closing = Eigen::Vector2d(-1.0, -1.0);
  for (const impulse2d::RatioTest test :
       {impulse2d::RatioTest::Lexicographic, impulse2d::RatioTest::Harris}) {
    const impulse2d::LemkePath path{Eigen::VectorXd::Ones(2), test};
    for (const Eigen::VectorXd& q : {Eigen::VectorXd(Eigen::Vector2d(kNaN, -1.0)),
                                     Eigen::VectorXd(Eigen::Vector2d(-kInfinity, -1.0))}) {
      const impulse2d::LcpSolution solution =
          impulse2d::solveLemke(identity, q, path, impulse2d::LemkeSettings{});
      CHECK_FALSE(solution.solved);
      CHECK(solution.failure.find("not finite") != std::string::npos);
    }
    const impulse2d::LcpSolution solution =
        impulse2d::solveLemke(overflowed, closing, path, impulse2d::LemkeSettings{});
    CHECK_FALSE(solution.solved);
  }
}

TEST_CASE("every solver stops the step at the first overflowed body, naming it and the step",
          "[non-finite][world]") {
  impulse2d::SceneFile scene = impulse2d::parseScene(kOverflowingPlank, "plank.toml");
  for (const std::string& solver : impulse2d::simulationNames()) {
    INFO(solver);
    scene.solver = solver;
    std::unique_ptr<impulse2d::Simulation> simulation = impulse2d::makeSimulation(scene);
    CHECK_THROWS_MATCHES(
        simulation->step(), impulse2d::NonFiniteState,
        Catch::Message("body plank became non-finite at step 1 (solver " + solver + ")"));
  }
}

TEST_CASE("every command ends an overflowing run with exit 1 and one line, never a crash",
          "[non-finite][i2d]") {
  const Scratch scratch;
  const std::string scene = scratch / "plank.toml";
  writeFile(scene, kOverflowingPlank);
  const std::string line = "body plank became non-finite at step 1 (solver ";
  for (const std::string solver : {"micro", "sequential", "reference", "soft_step", "box2d"}) {
    INFO(solver);
    const Outcome run = i2d("run " + scene + " --solver " + solver, scratch);
    CHECK(run.exitCode == 1);
    CHECK(run.err == "error: " + line + solver + ")\n");
  }
  for (const std::string solver : {"micro", "sequential", "reference"}) {
    INFO(solver);
    const Outcome measured = i2d("run " + scene + " --solver " + solver + " --error-vs-reference " +
                                     (scratch / "errors.csv"),
                                 scratch);
    CHECK(measured.exitCode == 1);
    CHECK(measured.err == "error: " + line + solver + ")\n");
  }
  const Outcome agree = i2d("agree " + scene, scratch);
  CHECK(agree.exitCode == 1);
  CHECK(agree.err == "error: " + line + "box2d)\n");
  const Outcome compare = i2d(
      "compare " + scene + " --solvers reference,micro --frames " + (scratch / "frames"), scratch);
  CHECK(compare.exitCode == 1);
  CHECK(compare.err == "error: panel 'reference': " + line + "reference)\n");
}

TEST_CASE("agree fails on a load whose energy overflows instead of printing inf",
          "[non-finite][i2d][agree]") {
  // 1e300 N on a 1 kg box: after one step v = 1.7e298 m/s, finite, but ½ m v² is not.
  const Scratch scratch;
  const std::string scene = scratch / "pushed.toml";
  writeFile(scene,
            "[world]\nsteps = 20\n[[body]]\nname = \"ground\"\ntype = \"static\"\nshape = "
            "\"box\"\nsize = [20.0, 1.0]\nposition = [0.0, -0.5]\n[[body]]\nname = \"box\"\n"
            "shape = \"box\"\nsize = [1.0, 1.0]\nposition = [0.0, 0.5]\nforce = [1e300, 1e300]\n");
  for (const std::string solvers : {"micro", "reference,soft_step"}) {
    INFO(solvers);
    const Outcome agree = i2d("agree " + scene + " --solvers " + solvers, scratch);
    CHECK(agree.exitCode == 1);
    CHECK(agree.out.find("inf") == std::string::npos);
    CHECK(lineCount(agree.err) == 1);
  }
  const Outcome run = i2d("run " + scene + " --solver micro", scratch);
  CHECK(run.exitCode == 1);
  CHECK(run.err == "error: body box became non-finite at step 1 (solver micro)\n");
}

TEST_CASE("the rows and plots written before the overflow are kept, and finite",
          "[non-finite][i2d][outputs]") {
  const Scratch scratch;
  const std::string scene = scratch / "rocket.toml";
  writeFile(scene, kRocket);
  const Outcome plotted = i2d("run " + scene + " --plots " + (scratch / "plots"), scratch);
  CHECK(plotted.exitCode == 1);
  // gnuplot may warn about a flat plot on stderr before i2d's own line
  const std::string stopped = "error: body rocket became non-finite at step 2 (solver micro)\n";
  CHECK(plotted.err.size() >= stopped.size());
  CHECK(plotted.err.compare(plotted.err.size() - stopped.size(), stopped.size(), stopped) == 0);
  const std::string figures = readFile(scratch / "plots/rocket_figures.dat");
  REQUIRE_FALSE(figures.empty());
  CHECK(figures.find("inf") == std::string::npos);
  CHECK(figures.find("nan") == std::string::npos);

  const Outcome measured =
      i2d("run " + scene + " --error-vs-reference " + (scratch / "errors.csv"), scratch);
  CHECK(measured.exitCode == 1);
  CHECK(measured.err == "error: body rocket became non-finite at step 2 (solver micro)\n");
  const std::string errors = readFile(scratch / "errors.csv");
  CHECK(lineCount(errors) == 2);  // the header and the solve of step 1
  CHECK(errors.rfind("solve,t,points,", 0) == 0);
}

TEST_CASE("a static body holds no energy, however far away it stands", "[non-finite][energy]") {
  // g·x overflows for a ground 1e308 m below: −m g·x with m = 0 was 0 · ∞ = NaN, and a run
  // printed "potential -nan J" with exit 0 (found by the scene_loader fuzzer).
  const impulse2d::SceneFile scene = impulse2d::parseScene(R"([world]
steps = 3

[[body]]
name = "far ground"
type = "static"
shape = "box"
size = [20.0, 1.0]
position = [0.0, -1e308]

[[body]]
name = "ball"
shape = "circle"
radius = 0.5
position = [0.0, 2.0]
)",
                                                           "far_ground.toml");
  for (const std::string& solver : impulse2d::solverNames()) {
    INFO(solver);
    impulse2d::SceneFile run = scene;
    run.solver = solver;
    std::unique_ptr<impulse2d::Simulation> simulation = impulse2d::makeSimulation(run);
    for (int step = 0; step < 3; ++step) simulation->step();
    const impulse2d::Body& ground = simulation->bodies().front();
    CHECK(ground.potentialEnergy(simulation->settings().gravity) == 0.0);
    CHECK(ground.kineticEnergy() == 0.0);
    // The world's potential energy is the ball's alone: m g y, with y near its 2 m start.
    const impulse2d::Body& ball = simulation->bodies().back();
    CHECK(ball.position.y() == Approx(2.0).margin(0.02));
    CHECK(impulse2d::potentialEnergy(*simulation) == Approx(ball.mass * 9.81 * ball.position.y()));
  }
  // Box2D keeps floats: a ground beyond a float's range is refused before the first step.
  impulse2d::SceneFile box2d = scene;
  box2d.solver = "box2d";
  CHECK_THROWS_AS(impulse2d::makeSimulation(box2d), impulse2d::NonFiniteState);
}
