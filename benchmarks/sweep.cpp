// The sweep behind docs/charts/: every method × its iterations (1 to 64) × time step
// (1/30 to 1/240 s) on four scenes, each with one error of its own, and the cost per step of
// each method's defaults on pyramids of 10 to about 5000 boxes. A progress bar goes to stderr,
// the points to OUTDIR/sweep.csv, pareto.csv and scaling.csv (docs/charts/*.gp draw them), and the
// tables to stdout as Markdown (docs/performance.md).
//
//   sweep OUTDIR            the full sweep (about 13 minutes on 2 cores)
//   sweep --quick OUTDIR    one iteration count and one time step per method, in seconds
//   sweep --methods micro --scenes pyramid40,rain OUTDIR
//                           only those methods on those panels (comma-separated lists, either
//                           may be left out), without the scaling family: a quicker look at a
//                           few panels; its CSVs are not the charts'
//
// Every point plotted is measured; a point whose run would not fit its time budget is written
// with status "over budget" (or "skipped" when a cheaper point already was) and never plotted.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "measures/benchmark_scenes.h"
#include "measures/measured_run.h"
#include "measures/output_directory.h"
#include "measures/progress_bar.h"
#include "measures/scaling.h"
#include "measures/sweep_points.h"

using namespace impulse2d;
using namespace benchmarks;

namespace {

/// A scene of the sweep and the one error it is judged by.
struct Panel {
  std::string scene;
  std::string errorName;
  double runTime;  ///< s simulated
  std::function<double(const RunFigures&)> error;
  /// The reference solves this scene: the active set does the pyramids (pyramid40 at about
  /// 0.4 s a step, so its points run out of budget); rain's impacts defeat both the active set
  /// and Lemke (docs/global-reference.md).
  bool referenceAffordable;
};

const std::vector<Panel> kPanels = {
    {"stack20", "contact-force error (RMS relative) 1-4 s", 4.0,
     [](const RunFigures& f) { return f.stackForceError; }, true},
    {"pyramid20", "settled drift 1-4 s (m)", 4.0, [](const RunFigures& f) { return f.drift; },
     true},
    {"pyramid40", "settled drift 1-4 s (m)", 4.0, [](const RunFigures& f) { return f.drift; },
     true},
    {"rain", "largest penetration at rest 4-6 s (m)", 6.0,
     [](const RunFigures& f) { return f.largestPenetration; }, false},
};

const std::vector<std::string> kMethods = {"micro", "sequential", "reference", "soft_step",
                                           "box2d"};

struct Grid {
  std::vector<std::string> solvers;
  std::vector<int> iterations;
  std::vector<int> stepsPerSecond;
  /// s of stepping one point may take; a run that reaches it stops and is not plotted.
  double pointBudget;
};

Grid sweepGrid(bool quick, const std::vector<std::string>& methods) {
  if (quick) return {methods, {8}, {60}, 5.0};
  return {methods, {1, 2, 4, 8, 16, 32, 64}, {30, 60, 120, 240}, 10.0};
}

/// What the command line asks for: the methods and panels to run (all by default).
struct Options {
  bool quick = false;
  std::vector<std::string> methods = kMethods;
  std::vector<std::string> scenes;  ///< empty: every panel
  bool chosen = false;              ///< --methods or --scenes given: no scaling family
  std::string outputDirectory;
};

std::vector<std::string> splitList(const std::string& list) {
  std::vector<std::string> items;
  std::string::size_type start = 0;
  for (;;) {
    const std::string::size_type comma = list.find(',', start);
    items.push_back(list.substr(start, comma - start));
    if (comma == std::string::npos) return items;
    start = comma + 1;
  }
}

/// The items of `list` that are not among `known`, joined for an error message.
std::string unknownItems(const std::vector<std::string>& list,
                         const std::vector<std::string>& known) {
  std::string unknown;
  for (const std::string& item : list) {
    if (std::find(known.begin(), known.end(), item) != known.end()) continue;
    unknown += (unknown.empty() ? "'" : ", '") + item + "'";
  }
  return unknown;
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

/// Reads the options before OUTDIR; returns what is wrong with them, or an empty string.
std::string parseOptions(int argc, char** argv, Options& options) {
  if (argc < 2) return "OUTDIR is missing";
  std::vector<std::string> panelScenes;
  for (const Panel& panel : kPanels) panelScenes.push_back(panel.scene);
  for (int i = 1; i < argc - 1; ++i) {
    const std::string option = argv[i];
    if (option == "--quick") {
      options.quick = true;
      continue;
    }
    if (option != "--methods" && option != "--scenes") return "unknown option '" + option + "'";
    if (i + 1 >= argc - 1) return option + " needs a comma-separated list before OUTDIR";
    const std::vector<std::string> list = splitList(argv[++i]);
    const std::vector<std::string>& known = option == "--methods" ? kMethods : panelScenes;
    const std::string unknown = unknownItems(list, known);
    if (!unknown.empty()) {
      return option + ": unknown " + unknown + " (choose from " + joined(known) + ")";
    }
    (option == "--methods" ? options.methods : options.scenes) = list;
    options.chosen = true;
  }
  options.outputDirectory = argv[argc - 1];
  const std::string problem = outputDirectoryProblem(options.outputDirectory);
  return problem.empty() ? "" : "OUTDIR " + problem;
}

/// The points of the sweep in the order they run: cheap ones first within each method, so a
/// point over budget lets the dearer ones behind it be skipped.
std::vector<SweepPoint> sweepPoints(const Grid& grid, const std::vector<std::string>& scenes) {
  std::vector<SweepPoint> points;
  for (size_t panel = 0; panel < kPanels.size(); ++panel) {
    if (!scenes.empty() &&
        std::find(scenes.begin(), scenes.end(), kPanels[panel].scene) == scenes.end()) {
      continue;
    }
    for (const std::string& solver : grid.solvers) {
      const bool reference = solver == "reference";
      if (reference && !kPanels[panel].referenceAffordable) continue;
      for (int stepsPerSecond : grid.stepsPerSecond) {
        for (int iterations : grid.iterations) {
          points.push_back({kPanels[panel].scene, kPanels[panel].errorName, solver,
                            reference ? 0 : iterations, stepsPerSecond});
          if (reference) break;  // no iteration knob: one point per time step
        }
      }
    }
  }
  return points;
}

/// Whether a method's cost per simulated second grows with its iterations and its step rate, so
/// that a point over budget makes the dearer ones behind it over budget too. Not micro's: its
/// knob is a cap, not a count, and a cap too low to hold a pile leaves the penetration phase at
/// its own cap every step (pyramid40 at 120 Hz: 2 impulses a point 36 ms a step, 16 1.7 ms);
/// on rain its smaller steps are cheaper per simulated second (32 a point: 1.5 s of CPU per
/// simulated second at 30 Hz, 0.9 s at 120 Hz). Every micro point is measured.
bool costIsMonotone(const std::string& solver) {
  return solver != "micro";
}

/// A point at least as dear as one already over budget: same scene and method, no fewer
/// iterations, no larger time step, for a method whose cost is monotone in both.
bool dearerThanOverBudget(const SweepPoint& point, const std::vector<SweepPoint>& done) {
  if (!costIsMonotone(point.solver)) return false;
  for (const SweepPoint& other : done) {
    if (other.status == kOverBudget && other.scene == point.scene && other.solver == point.solver &&
        point.iterations >= other.iterations && point.stepsPerSecond >= other.stepsPerSecond) {
      return true;
    }
  }
  return false;
}

void measurePoint(SweepPoint& point, const Panel& panel, double budget) {
  Scene scene = withMethod(shippedScene(panel.scene), point.solver, point.iterations);
  scene.world.dt = 1.0 / point.stepsPerSecond;
  RunPlan plan;
  plan.steps = std::lround(panel.runTime * point.stepsPerSecond);
  plan.settledTime = settledTime(scene);
  plan.timeBudget = budget;
  MeasuredRun run(scene, plan);
  const std::string failure = runToEnd(run);
  if (!failure.empty()) {
    std::fprintf(stderr, "\n%s: %s\n", describe(point).c_str(), failure.c_str());
    point.status = kFailed;
    return;
  }
  const RunFigures figures = run.figures();
  point.microsecondsPerStep = figures.medianMicroseconds;
  point.error = panel.error(figures);
  point.status = figures.completed ? kMeasured : kOverBudget;
}

const Panel& panelOf(const SweepPoint& point) {
  for (const Panel& panel : kPanels) {
    if (panel.scene == point.scene) return panel;
  }
  throw std::logic_error("no panel for " + point.scene);
}

void runSweep(std::vector<SweepPoint>& points, double budget, ProgressBar& progress) {
  std::vector<SweepPoint> done;
  for (SweepPoint& point : points) {
    progress.show(describe(point));
    if (dearerThanOverBudget(point, done)) {
      point.status = kSkipped;
    } else {
      measurePoint(point, panelOf(point), budget);
    }
    done.push_back(point);
    progress.advance();
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  const std::string problem = parseOptions(argc, argv, options);
  if (!problem.empty()) {
    std::fprintf(stderr,
                 "sweep: error: %s\nusage: sweep [--quick] [--methods LIST] [--scenes LIST] "
                 "OUTDIR\n",
                 problem.c_str());
    return 2;
  }
  const std::string& outputDirectory = options.outputDirectory;
  const auto start = std::chrono::steady_clock::now();
  const Grid grid = sweepGrid(options.quick, options.methods);
  std::vector<SweepPoint> points = sweepPoints(grid, options.scenes);
  const std::vector<int> rows = options.quick ? std::vector<int>{4, 9, 14} : scalingFamilyRows();
  std::vector<ScalingPoint> scaling;
  if (!options.chosen) scaling = scalingPoints(rows);
  ProgressBar progress(points.size() + scaling.size());
  runSweep(points, grid.pointBudget, progress);
  measureScaling(scaling, progress);
  markParetoFront(points);
  try {
    writeSweepCsv(outputDirectory + "/sweep.csv", points);
    writeParetoCsv(outputDirectory + "/pareto.csv", points);
    writeScalingCsv(outputDirectory + "/scaling.csv", scaling);
  } catch (const std::runtime_error& failure) {
    std::fprintf(stderr, "sweep: error: %s\n", failure.what());
    return 1;
  }
  const double minutes =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 60.0;
  printSweepTables(points, minutes);
  if (!scaling.empty()) printScalingTable(scaling);
  return 0;
}
