// `i2d run`: load the scene, apply the command line's overrides, step, record, summarise; or,
// with --trace-step, draw one frame per solver event of one step.
#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>

#include "commands.h"
#include "csv_writer.h"
#include "failures.h"
#include "frame_output.h"
#include "impulse2d/box2d/box2d_simulation.h"
#include "impulse2d/render/trace.h"
#include "impulse2d/solvers/reference_solver.h"
#include "output_directories.h"
#include "plots.h"
#include "scene_setup.h"
#include "summary.h"

namespace i2d {
namespace {

using impulse2d::Body;
using impulse2d::SceneFile;
using impulse2d::Simulation;

/// What a run writes as it goes: the CSV, the frames and the figures of every step (for the
/// plots and the viewer), each when asked for.
struct Recorders {
  /// Fitted to every recorded state, for the frames and the summary's view line.
  std::unique_ptr<impulse2d::render::RunCamera> camera;
  std::unique_ptr<CsvWriter> csv;
  std::unique_ptr<CsvWriter> contacts;
  std::unique_ptr<FrameRecorder> frames;
  std::optional<std::string> plots;
  std::vector<StepFigures> figures;
  std::string scene;
  std::string solver;
  int every = 1;

  void record(const Simulation& simulation, long lastStep) {
    const long step = simulation.stepCount();
    const double time = double(step) * simulation.settings().dt;
    if (isRecorded(step, lastStep, every)) camera->add(simulation.bodies());
    if (csv && isRecorded(step, lastStep, every)) csv->writeStep(step, time, simulation.bodies());
    if (contacts && isRecorded(step, lastStep, every)) {
      // A world with substeps holds its last substep's impulses, taken over dt / substeps.
      const double impulseTime =
          simulation.settings().dt / std::max(1, simulation.settings().substeps);
      contacts->writeContacts(step, time, impulseTime, simulation.bodies(), simulation.manifolds());
    }
    if (frames || plots) figures.push_back(measureStep(simulation));
    if (frames) frames->record(simulation, lastStep);
  }
  /// Commits the CSV, writes the sheet, viewer and animation, and the plots; returns their
  /// summary lines.
  std::vector<std::string> finish(double dt) {
    if (csv) csv->commit();
    std::vector<std::string> lines{viewLine(camera->shown())};
    if (frames) {
      for (const std::string& line : frames->finish(*camera, dt, figures)) lines.push_back(line);
    }
    if (contacts) {
      contacts->commit();
      lines.push_back("contacts     " + contacts->path() + " (" +
                      std::to_string(contacts->rowCount()) + " rows)");
    }
    if (plots) {
      for (const std::string& line : writeRunPlots(*plots, scene, {{solver, figures}})) {
        lines.push_back(line);
      }
    }
    return lines;
  }
};

/// One step; a body that overflows (NonFiniteState) or a reference solve without an exact answer
/// stops the run there, naming the step and keeping what was recorded before it.
void stepOrStop(Simulation& simulation, Recorders& recorders) {
  try {
    simulation.step();
  } catch (const impulse2d::NonFiniteState& failure) {
    recorders.finish(simulation.settings().dt);
    throw RunFailure(failure.what());
  } catch (const impulse2d::ReferenceSolveFailure& failure) {
    recorders.finish(simulation.settings().dt);
    throw RunFailure(stepAndTime(simulation.stepCount() + 1, simulation.settings().dt) + ": " +
                     failure.what());
  }
}

/// Steps the simulation, recording as it goes; returns the seconds spent stepping.
double runSteps(Simulation& simulation, long steps, Recorders& recorders) {
  recorders.record(simulation, steps);
  std::chrono::steady_clock::duration stepping{};
  for (long step = 1; step <= steps; ++step) {
    const auto begin = std::chrono::steady_clock::now();
    stepOrStop(simulation, recorders);
    stepping += std::chrono::steady_clock::now() - begin;
    recorders.record(simulation, steps);
  }
  return std::chrono::duration<double>(stepping).count();
}

Recorders openRecorders(const RunOptions& options, const SceneFile& scene) {
  checkVideoPossible(options.frames);
  createOutputDirectory(directoryOf(options.csvPath), "--csv");
  createOutputDirectory(directoryOf(options.contactsPath), "--contacts");
  if (options.plots) preparePlotDirectory(*options.plots);
  Recorders recorders;
  recorders.every = options.every;
  recorders.plots = options.plots;
  recorders.scene = scene.name;
  recorders.solver = scene.solver;
  recorders.camera = std::make_unique<impulse2d::render::RunCamera>(
      runCamera(scene, options.frames, renderSettings(options.frames)));
  if (options.frames.directory) {
    recorders.frames = std::make_unique<FrameRecorder>(options.frames, scene, options.every);
  }
  if (options.csvPath) recorders.csv = std::make_unique<CsvWriter>(*options.csvPath);
  if (options.contactsPath) {
    recorders.contacts =
        std::make_unique<CsvWriter>(*options.contactsPath, CsvWriter::kContactsHeader);
  }
  return recorders;
}

/// --plots with --trace-step: the step run again with a log of its solver events, plotted.
std::string plotTracedStep(const RunOptions& options, const SceneFile& scene) {
  preparePlotDirectory(*options.plots);
  std::unique_ptr<Simulation> simulation = impulse2d::makeSimulation(scene);
  while (simulation->stepCount() < *options.traceStep - 1) simulation->step();
  EventLog events;
  simulation->setObserver(&events);
  simulation->step();
  simulation->setObserver(nullptr);
  return writeTracePlot(*options.plots, scene.name, *options.traceStep, events);
}

/// --trace-step N must name a step of the run, before anything is written.
void checkTraceStepInRun(long step, long steps) {
  if (step <= steps) return;
  throw UsageError("--trace-step " + std::to_string(step) +
                   " is past the end of the run, which has " + std::to_string(steps) +
                   " steps; trace a step from 1 to " + std::to_string(steps) +
                   " or give more with --steps");
}

/// --trace-step N: runs to step N and draws each solver event of it, then its sheet.
int traceCommand(const RunOptions& options, const SceneFile& scene, Simulation& simulation) {
  if (simulation.solverName() == impulse2d::kBox2dName) {
    throw RunFailure(
        "solver box2d reports no solver events, so it cannot be traced; trace "
        "micro, sequential or reference");
  }
  const long step = *options.traceStep;
  if (options.plots) preparePlotDirectory(*options.plots);
  impulse2d::render::RenderSettings settings = renderSettings(options.frames);
  settings.headsUpLines = settings.traceHeadsUpLines;
  const impulse2d::render::FrameRenderer renderer(sceneCamera(scene, options.frames, settings),
                                                  scene.name, settings);
  const impulse2d::render::FrameWriter trace = impulse2d::render::traceStep(
      simulation, step, renderer, *options.frames.directory, options.frames.format);
  if (trace.frameCount() == 0) {
    throw RunFailure("step " + std::to_string(step) +
                     " resolved no contacts, so it has no solver events to draw; trace a step "
                     "with contacts");
  }
  std::cout << "scene        " << scene.name << " (solver " << simulation.solverName() << ")\n"
            << "trace        step " << step << ": " << trace.frameCount() << " solver events\n";
  for (const std::string& line : describeFrames(trace)) std::cout << line << "\n";
  std::cout << "viewer       "
            << impulse2d::render::writeViewer(trace, scene.name, {}, 4.0).string() << "\n";
  if (options.plots) std::cout << plotTracedStep(options, scene) << "\n";
  return kSuccess;
}

}  // namespace

int runCommand(const RunOptions& options) {
  if (options.errorVsReferencePath) return errorVsReferenceRun(options);
  const SceneFile scene = loadScene(options.scene);
  warnAboutStartingOverlaps(scene, std::cerr);
  if (options.traceStep) checkTraceStepInRun(*options.traceStep, scene.steps);
  createOutputDirectory(options.frames.directory, "--frames");
  createOutputDirectory(options.plots, "--plots");
  std::unique_ptr<Simulation> simulation = impulse2d::makeSimulation(scene);
  if (options.traceStep) return traceCommand(options, scene, *simulation);
  Recorders recorders = openRecorders(options, scene);

  RunSummary summary;
  summary.scene = scene.name;
  summary.solver = simulation->solverName();
  summary.steps = scene.steps;
  summary.dt = simulation->settings().dt;
  summary.start = measureEnergy(*simulation);
  summary.wallSeconds = runSteps(*simulation, scene.steps, recorders);
  summary.end = measureEnergy(*simulation);
  summary.contactPoints = impulse2d::contactPointCount(*simulation);
  summary.penetrationAtEnd = impulse2d::deepestOverlap(simulation->bodies());
  summary.outputs = recorders.finish(summary.dt);
  if (recorders.csv) {
    summary.csvPath = recorders.csv->path();
    summary.csvRows = recorders.csv->rowCount();
  }
  printSummary(std::cout, summary);
  return kSuccess;
}

}  // namespace i2d
