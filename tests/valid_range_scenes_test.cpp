// The property behind the settings' ranges: any scene whose every number lies inside its valid
// range, however extreme (loads up to 1e308 N, stiffness and damping at their bounds), runs
// under every solver and command to a finite end or stops cleanly at the first non-finite body
// (NonFiniteState, exit 1), or at a reference solve without an exact answer; it never crashes,
// hangs or reports a non-finite figure. The scenes are written as scene files and read by the
// same reader as i2d's, from a fixed seed, so a failure names a scene that fails every run.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "i2d_process.h"
#include "impulse2d/box2d/agreement.h"
#include "impulse2d/box2d/box2d_simulation.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/scene/setting_ranges.h"
#include "impulse2d/solvers/error_vs_reference.h"
#include "impulse2d/solvers/reference_solver.h"
#include "impulse2d/world.h"

using namespace impulse2d;

namespace {

constexpr int kScenes = 60;
constexpr int kSteps = 20;
/// Counts are drawn no higher than this above their lowest value, so the test stays quick; their
/// upper bounds are the ranges test's concern.
constexpr double kCountSpan = 40.0;

/// A number drawn log-uniformly between a and b (both > 0).
double logUniform(std::mt19937& random, double a, double b) {
  return std::exp(std::uniform_real_distribution<double>(std::log(a), std::log(b))(random));
}

/// A value inside `range`: the bounds themselves a quarter of the time each, else spread over
/// the decades between them.
double insideRange(std::mt19937& random, const SettingRange& range, bool integer) {
  const double highest =
      integer ? std::min(range.highest, range.lowest + kCountSpan) : range.highest;
  const int pick = std::uniform_int_distribution<int>(0, 3)(random);
  if (pick == 0 && range.lowestIncluded) return range.lowest;
  if (pick == 1) return highest;
  const double lowest = range.lowest > 0.0 ? range.lowest : highest * 1e-9;
  const double value = logUniform(random, lowest, highest);
  return integer ? std::round(value) : value;
}

std::string number(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  const std::string written = text.str();
  const bool plain = written.find_first_of(".e") == std::string::npos;
  return plain ? written + ".0" : written;
}

/// A load or speed component: mostly zero or ordinary, one in ten anywhere up to the largest
/// double, so about half the runs overflow and half go the distance.
double extreme(std::mt19937& random) {
  const double sign = std::uniform_int_distribution<int>(0, 1)(random) ? 1.0 : -1.0;
  const int pick = std::uniform_int_distribution<int>(0, 9)(random);
  if (pick < 5) return 0.0;
  if (pick < 9) return sign * logUniform(random, 0.1, 100.0);
  return sign * logUniform(random, 1.0, 1e308);
}

std::string settingLines(std::mt19937& random, const std::string& scope,
                         const std::vector<SettingField>& fields) {
  std::string lines;
  std::bernoulli_distribution chosen(0.4);
  for (const SettingField& field : fields) {
    if (!chosen(random)) continue;
    const bool integer = std::holds_alternative<int*>(field.value);
    if (std::holds_alternative<bool*>(field.value)) {
      lines += field.name + " = " + (chosen(random) ? "true" : "false") + "\n";
    }
    if (const auto* choice = std::get_if<SettingChoice>(&field.value)) {
      const size_t pick =
          std::uniform_int_distribution<size_t>(0, choice->names.size() - 1)(random);
      lines += field.name + " = \"" + choice->names[pick] + "\"\n";
    }
    const std::optional<SettingRange> range = findSettingRange(scope, field.name);
    if (!range || field.name == "substeps") continue;  // substeps: drawn 1 to 4 below
    const double value = insideRange(random, *range, integer);
    lines += field.name + " = " + (integer ? std::to_string(long(value)) : number(value)) + "\n";
  }
  return lines;
}

std::string bodyLines(std::mt19937& random, int index) {
  std::uniform_real_distribution<double> place(-1.5, 1.5);
  std::ostringstream body;
  body << "[[body]]\nname = \"b" << index << "\"\n";
  if (std::bernoulli_distribution(0.5)(random)) {
    body << "shape = \"box\"\nsize = [" << number(logUniform(random, 0.1, 2.0)) << ", "
         << number(logUniform(random, 0.1, 2.0)) << "]\n";
  } else {
    body << "shape = \"circle\"\nradius = " << number(logUniform(random, 0.05, 1.0)) << "\n";
  }
  body << "position = [" << number(place(random)) << ", " << number(0.6 + place(random) + 1.5)
       << "]\ndensity = " << number(logUniform(random, 1e-3, 1e3))
       << "\nfriction = " << number(std::uniform_real_distribution<double>(0.0, 2.0)(random))
       << "\nrestitution = " << number(std::uniform_real_distribution<double>(0.0, 1.0)(random))
       << "\nforce = [" << number(extreme(random)) << ", " << number(extreme(random)) << "]\n"
       << "torque = " << number(extreme(random)) << "\nvelocity = [" << number(extreme(random))
       << ", " << number(extreme(random)) << "]\n";
  return body.str();
}

/// Scene `index` of the family: a floor, 1 to 5 bodies, random world and solver settings.
std::string randomScene(int index, const std::string& solver) {
  std::mt19937 random(9173u + unsigned(index));
  WorldSettings world;
  SolverSettings solvers;
  std::ostringstream scene;
  scene << "[world]\nsteps = " << kSteps << "\nsolver = \"" << solver
        << "\"\nsubsteps = " << std::uniform_int_distribution<int>(1, 4)(random) << "\n"
        << settingLines(random, "world", describe(world)) << "[solver]\n";
  if (solver == "micro" && std::bernoulli_distribution(0.3)(random))
    scene << "preset = \"lecture\"\n";
  if (solver == "soft_step")
    scene << "substeps = " << std::uniform_int_distribution<int>(1, 4)(random) << "\n";
  scene << settingLines(random, solver, solverSettingFields(solvers, solver))
        << "[[body]]\nname = \"floor\"\ntype = \"static\"\nshape = \"box\"\nsize = [8.0, 1.0]\n"
           "position = [0.0, -0.5]\n";
  const int bodies = std::uniform_int_distribution<int>(1, 5)(random);
  for (int i = 0; i < bodies; ++i) scene << bodyLines(random, i);
  return scene.str();
}

bool finiteFigures(const Simulation& simulation) {
  for (const Body& body : simulation.bodies()) {
    if (!hasFiniteState(body, simulation.settings().gravity)) return false;
  }
  return std::isfinite(kineticEnergy(simulation)) && std::isfinite(potentialEnergy(simulation)) &&
         std::isfinite(largestPenetration(simulation));
}

/// Runs the scene to its end; "" when it ends finite, else why it stopped cleanly. Anything
/// else (another exception, a non-finite figure after a step) fails the test.
std::string runToEnd(Simulation& simulation, long steps) {
  for (long step = 0; step < steps; ++step) {
    try {
      simulation.step();
    } catch (const NonFiniteState& stop) {
      return stop.what();
    } catch (const ReferenceSolveFailure& stop) {
      return stop.what();
    }
    REQUIRE(finiteFigures(simulation));
  }
  return "";
}

/// The scene under its solver: "" when it ends finite, else why it stopped cleanly (Box2D's
/// floats may refuse a starting speed that a double holds).
std::string runScene(const SceneFile& scene) {
  std::unique_ptr<Simulation> simulation;
  try {
    simulation = makeSimulation(scene);
  } catch (const NonFiniteState& stop) {
    return stop.what();
  }
  return runToEnd(*simulation, scene.steps);
}

}  // namespace

TEST_CASE("scenes inside the valid ranges end finite or stop cleanly under every solver",
          "[ranges][property]") {
  int stopped = 0;
  for (int index = 0; index < kScenes; ++index) {
    for (const std::string& solver : simulationNames()) {
      const std::string text = randomScene(index, solver);
      INFO("scene " << index << ", solver " << solver << ":\n" << text);
      const SceneFile scene = parseScene(text, "random.toml");
      stopped += !runScene(scene).empty();
      if (solver == kBox2dName) continue;
      impulse2d::World watched(scene.world, makeWatchedSolver(scene.solver, scene.solverSettings));
      for (const Body& body : buildBodies(scene)) watched.addBody(body);
      runToEnd(watched, scene.steps);
    }
  }
  // Loads up to 1e308 N overflow some runs and not others: both ends are exercised.
  const int runs = kScenes * int(simulationNames().size());
  INFO(stopped << " of " << runs << " runs stopped");
  CHECK(stopped >= runs / 5);
  CHECK(stopped <= runs * 4 / 5);
}

TEST_CASE("agree measures scenes inside the valid ranges to finite figures or stops",
          "[ranges][property][agree]") {
  int measured = 0;
  int stopped = 0;
  for (int index = 0; index < kScenes; index += 3) {
    const SceneFile scene = parseScene(randomScene(index, "micro"), "random.toml");
    INFO("scene " << index);
    try {
      const Agreement agreement = measureAgreement(scene, solverNames());
      const std::string table = agreementTable(agreement);
      CHECK(table.find("inf") == std::string::npos);
      CHECK(table.find("nan") == std::string::npos);
      ++measured;
    } catch (const NonFiniteState&) {
      ++stopped;  // a body overflowed: agree stops with exit 1
    }
  }
  // Both outcomes are exercised, as in the runs above: a table is checked for finite figures.
  INFO(measured << " scenes measured, " << stopped << " stopped");
  CHECK(measured > 0);
  CHECK(stopped > 0);
}

TEST_CASE("i2d's commands on scenes inside the valid ranges exit 0 or 1, never non-finite",
          "[ranges][property][i2d]") {
  using namespace i2d_process;
  const Scratch scratch;
  for (int index = 0; index < 6; ++index) {
    const std::string scene = scratch / ("random" + std::to_string(index) + ".toml");
    writeFile(scene, randomScene(index, "reference"));
    INFO("scene " << index << ":\n" << readFile(scene));
    const Outcome run = i2d("run " + scene + " --csv " + (scratch / "run.csv"), scratch);
    CHECK((run.exitCode == 0 || run.exitCode == 1));
    const std::string rows = readFile(scratch / "run.csv");
    CHECK(rows.find("inf") == std::string::npos);
    CHECK(rows.find("nan") == std::string::npos);
    CHECK(run.out.find("inf") == std::string::npos);
    const Outcome agree = i2d("agree " + scene, scratch);
    CHECK((agree.exitCode == 0 || agree.exitCode == 1));
    CHECK(agree.out.find("inf") == std::string::npos);
    const Outcome errors =
        i2d("run " + scene + " --error-vs-reference " + (scratch / "errors.csv"), scratch);
    CHECK((errors.exitCode == 0 || errors.exitCode == 1));
    CHECK(errors.out.find("inf") == std::string::npos);
  }
}
