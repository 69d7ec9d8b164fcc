// `i2d run`: load the scene, apply the command line's overrides, step, record, summarise.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>

#include "commands.h"
#include "csv_writer.h"
#include "failures.h"
#include "impulse2d/scene_file.h"
#include "simulation_factory.h"
#include "summary.h"

namespace i2d {
namespace {

using impulse2d::Body;
using impulse2d::Scene;
using impulse2d::Simulation;

/// --solver, then each --set in order, then --steps and --dt: the most explicit option wins.
void applyOverrides(const RunOptions& options, Scene& scene) {
  if (options.solver) {
    const std::vector<std::string> known = impulse2d::sceneSolverNames();
    if (std::find(known.begin(), known.end(), *options.solver) == known.end()) {
      std::string names;
      for (const std::string& name : known) names += (names.empty() ? "" : ", ") + name;
      throw UsageError("unknown solver '" + *options.solver + "' (known: " + names + ")");
    }
    scene.solver = *options.solver;
  }
  for (const std::string& assignment : options.settings) {
    try {
      impulse2d::applySetting(scene, assignment);
    } catch (const impulse2d::SceneError& error) {
      throw UsageError(error.what());
    }
  }
  if (options.steps) scene.steps = *options.steps;
  if (options.dt) scene.world.dt = *options.dt;
}

bool isFinite(const Body& body) {
  return body.position.allFinite() && std::isfinite(body.angle) && body.velocity.allFinite() &&
         std::isfinite(body.angularVelocity);
}

/// Stops the run at the first body whose state overflowed, keeping the rows recorded so far.
void stopIfNonFinite(const Simulation& simulation, CsvWriter* csv) {
  for (const Body& body : simulation.bodies()) {
    if (body.isStatic() || isFinite(body)) continue;
    if (csv) csv->commit();
    throw RunFailure("body " + body.name + " became non-finite at step " +
                     std::to_string(simulation.stepCount()));
  }
}

bool isRecorded(long step, long lastStep, int every) {
  return step % every == 0 || step == lastStep;
}

/// Steps the simulation, recording into the CSV; returns the seconds spent stepping.
double runSteps(Simulation& simulation, long steps, int every, CsvWriter* csv) {
  const double dt = simulation.settings().dt;
  if (csv) csv->writeStep(0, 0.0, simulation.bodies());
  std::chrono::steady_clock::duration stepping{};
  for (long step = 1; step <= steps; ++step) {
    const auto begin = std::chrono::steady_clock::now();
    simulation.step();
    stepping += std::chrono::steady_clock::now() - begin;
    stopIfNonFinite(simulation, csv);
    if (csv && isRecorded(step, steps, every)) {
      csv->writeStep(step, double(step) * dt, simulation.bodies());
    }
  }
  return std::chrono::duration<double>(stepping).count();
}

}  // namespace

int runCommand(const RunOptions& options) {
  Scene scene = impulse2d::loadSceneFile(options.scenePath);
  applyOverrides(options, scene);
  if (options.framesDirectory) throw RunFailure("--frames is not built yet");
  std::unique_ptr<Simulation> simulation = makeSimulation(scene);
  std::unique_ptr<CsvWriter> csv;
  if (options.csvPath) csv = std::make_unique<CsvWriter>(*options.csvPath);

  RunSummary summary;
  summary.scene = scene.name;
  summary.solver = simulation->solverName();
  summary.steps = scene.steps;
  summary.dt = simulation->settings().dt;
  summary.start = measureEnergy(*simulation);
  summary.wallSeconds = runSteps(*simulation, scene.steps, options.every, csv.get());
  summary.end = measureEnergy(*simulation);
  summary.contactPoints = impulse2d::contactPointCount(*simulation);
  summary.largestPenetration = impulse2d::largestPenetration(*simulation);
  if (csv) {
    csv->commit();
    summary.csvPath = csv->path();
    summary.csvRows = csv->rowCount();
  }
  printSummary(std::cout, summary);
  return kSuccess;
}

}  // namespace i2d
