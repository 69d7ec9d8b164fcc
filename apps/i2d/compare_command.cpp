// `i2d compare`: the same scene run side by side, once per solver or once per set of --set
// changes, drawn as labelled panels with one camera, every K-th step, and a contact sheet. The
// first panel is the clock: every panel runs for its steps × dt, and a panel with another time
// step takes the steps that time needs, each frame showing it at the step nearest the frame's
// time.
#include <cmath>
#include <iostream>
#include <memory>

#include "commands.h"
#include "failures.h"
#include "frame_output.h"
#include "impulse2d/box2d/box2d_simulation.h"
#include "impulse2d/render/panels.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/scene/setting_ranges.h"
#include "impulse2d/solvers/reference_solver.h"
#include "output_directories.h"
#include "plots.h"
#include "scene_setup.h"

namespace i2d {
namespace {

using impulse2d::SceneFile;
using impulse2d::Simulation;
using namespace impulse2d::render;

/// One panel's run: its scene, its simulation, the states its frames show and its figures.
struct PanelRun {
  std::string label;
  SceneFile scene;
  std::unique_ptr<Simulation> simulation;
  std::vector<FrameState> states;
  std::vector<StepFigures> figures;
};

/// The panel's scene: the file, then --solver or the panel's solver (and its preset), the common
/// --sets, the panel's own --sets, then --steps and --dt.
SceneFile panelScene(const SceneFile& file, const SceneOptions& common, const PanelOption& panel) {
  SceneOptions options = common;
  if (panel.solver) {
    options.solver = panel.solver;
    options.preset = panel.preset;
  }
  options.settings.insert(options.settings.end(), panel.settings.begin(), panel.settings.end());
  SceneFile scene = file;
  applyOverrides(options, scene);
  impulse2d::checkSceneSize(scene, common.scenePath);
  return scene;
}

/// The panels side by side make one image: its pixels are refused before anything is drawn.
void checkPanelPixels(const SceneFile& file, const CompareOptions& options) {
  const FrameSize size = options.frames.size.value_or(FrameSize{file.view.width, file.view.height});
  const std::string refused =
      impulse2d::checkFramePixels(size.width, size.height, int(options.panels.size()));
  if (!refused.empty()) throw impulse2d::SceneError(options.scene.scenePath, refused);
}

/// A panel whose time step differs from the first panel's runs for the first panel's time: its
/// steps are that time over its dt, checked against the scene's size limit like any steps.
void matchFirstPanelTime(const SceneFile& first, const std::string& label, SceneFile& scene,
                         const std::string& path) {
  if (scene.world.dt == first.world.dt) {
    scene.steps = first.steps;
    return;
  }
  scene.steps = std::lround(double(first.steps) * first.world.dt / scene.world.dt);
  try {
    impulse2d::checkSceneSize(scene, path);
  } catch (const impulse2d::SceneError& error) {
    throw impulse2d::SceneError(
        path, "panel '" + label + "' takes " + std::to_string(scene.steps) +
                  " steps of its dt for the first panel's time: " + error.message());
  }
}

std::vector<PanelRun> startPanels(const CompareOptions& options) {
  const SceneFile file = impulse2d::loadSceneFile(options.scene.scenePath);
  checkPanelPixels(file, options);
  std::vector<PanelRun> runs;
  for (const PanelOption& panel : options.panels) {
    PanelRun run{panel.label, panelScene(file, options.scene, panel), nullptr, {}, {}};
    if (!runs.empty()) {
      matchFirstPanelTime(runs.front().scene, run.label, run.scene, options.scene.scenePath);
    }
    run.simulation = impulse2d::makeSimulation(run.scene);
    runs.push_back(std::move(run));
  }
  return runs;
}

void stepPanel(PanelRun& run) {
  try {
    run.simulation->step();
  } catch (const impulse2d::NonFiniteState& failure) {
    throw RunFailure("panel '" + run.label + "': " + failure.what());
  } catch (const impulse2d::ReferenceSolveFailure& failure) {
    throw RunFailure("panel '" + run.label + "' at " +
                     stepAndTime(run.simulation->stepCount() + 1, run.simulation->settings().dt) +
                     ": " + failure.what());
  }
}

/// Every panel to the step whose time is nearest `time`: the first panel one step, a panel of a
/// finer time step several, a coarser one none until its next step is nearer.
void stepPanels(std::vector<PanelRun>& runs, double time) {
  for (PanelRun& run : runs) {
    const double dt = run.simulation->settings().dt;
    while ((double(run.simulation->stepCount()) + 0.5) * dt <= time) stepPanel(run);
  }
}

void measurePanels(std::vector<PanelRun>& runs) {
  for (PanelRun& run : runs) run.figures.push_back(measureStep(*run.simulation));
}

/// The viewer's table: each panel's total energy, contact points and largest penetration.
FigureTable panelTable(const std::vector<PanelRun>& runs, const std::vector<long>& frameSteps) {
  FigureTable table;
  for (const PanelRun& run : runs) {
    for (const char* figure :
         {" total energy (J)", " contact points", " largest penetration (m)"}) {
      table.columns.push_back(run.label + figure);
    }
  }
  for (const long step : frameSteps) {
    std::vector<double> row;
    for (const PanelRun& run : runs) {
      const FigureTable one = figureTable(run.figures, {step});
      if (one.rows.empty()) continue;
      row.insert(row.end(), {one.rows[0][3], one.rows[0][4], one.rows[0][5]});
    }
    table.rows.push_back(row);
  }
  return table;
}

std::vector<std::string> plotPanels(const std::string& directory, const std::string& name,
                                    const std::vector<PanelRun>& runs) {
  std::vector<PlotSeries> series;
  for (const PanelRun& run : runs) series.push_back({run.label, run.figures});
  return writeRunPlots(directory, name, series);
}

/// Keeps each panel's state for its frame, and shows it to the camera they share.
void keepPanels(std::vector<PanelRun>& runs, RunCamera& camera, const RenderSettings& settings) {
  for (PanelRun& run : runs) {
    run.states.push_back(captureFrame(*run.simulation, run.scene.name, settings));
    camera.add(run.states.back().bodies);
  }
}

/// Draws the kept states through the shared camera, the panels of each step side by side.
void writePanels(std::vector<PanelRun>& runs, const std::vector<long>& steps,
                 const RunCamera& camera, FrameWriter& writer, const RenderSettings& settings) {
  std::vector<FrameRenderer> renderers;
  for (const PanelRun& run : runs) {
    renderers.emplace_back(camera.cameraFor(run.states.front().bodies), run.scene.name, settings);
  }
  for (std::size_t k = 0; k < steps.size(); ++k) {
    std::vector<Frame> frames;
    for (std::size_t p = 0; p < runs.size(); ++p) {
      renderers[p].setCamera(camera.cameraFor(runs[p].states[k].bodies));
      frames.push_back(renderers[p].draw(runs[p].states[k]));
      runs[p].states[k] = FrameState{};  // drawn: its frame keeps what a sheet needs
    }
    std::vector<Panel> panels;
    for (std::size_t p = 0; p < runs.size(); ++p) panels.push_back({&frames[p], runs[p].label});
    writer.write(steps[k], composePanels(panels, settings));
  }
}

void printPanelSummary(const std::vector<PanelRun>& runs) {
  for (const PanelRun& run : runs) {
    const Simulation& simulation = *run.simulation;
    std::cout << "panel        " << run.label << ": solver " << simulation.solverName() << ", "
              << simulation.stepCount() << " steps, kinetic "
              << impulse2d::kineticEnergy(simulation) << " J and potential "
              << impulse2d::potentialEnergy(simulation) << " J at end, largest penetration "
              << impulse2d::largestPenetration(simulation) << " m\n";
  }
}

}  // namespace

int compareCommand(const CompareOptions& options) {
  checkVideoPossible(options.frames);
  const RenderSettings settings = renderSettings(options.frames);
  std::vector<PanelRun> runs = startPanels(options);
  // --set changes no body: one camera for all panels, fitted to them all.
  RunCamera camera = runCamera(runs.front().scene, options.frames, settings);
  createOutputDirectory(options.frames.directory, "--frames");
  createOutputDirectory(options.plots, "--plots");
  if (options.plots) preparePlotDirectory(*options.plots);
  const SceneFile& first = runs.front().scene;
  FrameWriter writer(*options.frames.directory, first.name, options.every,
                     comparePrefix(first.name), settings, options.frames.format);
  std::cout << "scene        " << first.name << " (" << runs.size() << " panels, " << first.steps
            << " steps)\n";
  std::vector<long> steps;
  for (long step = 0; step <= first.steps; ++step) {
    if (step > 0) stepPanels(runs, double(step) * first.world.dt);
    measurePanels(runs);
    if (!isRecorded(step, first.steps, options.every)) continue;
    keepPanels(runs, camera, settings);
    steps.push_back(step);
  }
  writePanels(runs, steps, camera, writer, settings);
  writer.writeContactSheet();
  printPanelSummary(runs);
  std::cout << viewLine(camera.shown()) << "\n";
  for (const std::string& line : describeFrames(writer)) std::cout << line << "\n";
  std::vector<PlotSeries> series;
  for (const PanelRun& run : runs) series.push_back({run.label, run.figures});
  const std::vector<ViewerPlot> plots = writeViewerPlots(
      writer.directory(), writer.prefix(), series, hasLoads(*runs.front().simulation));
  for (const std::string& line :
       writeFrameExtras(options.frames, writer, first.name, 1.0 / (first.world.dt * options.every),
                        panelTable(runs, writer.steps()), plots, first.world.dt)) {
    std::cout << line << "\n";
  }
  if (options.plots) {
    for (const std::string& line : plotPanels(*options.plots, comparePrefix(first.name), runs)) {
      std::cout << line << "\n";
    }
  }
  return kSuccess;
}

}  // namespace i2d
