// The sweep behind docs/charts/ (issue 7): every method × its iterations (1 to 64) × time step
// (1/30 to 1/240 s) on four scenes, each with one error of its own, and the cost per step of
// each method's defaults on pyramids of 10 to about 5000 boxes. A progress bar goes to stderr,
// the points to OUTDIR/sweep.csv, pareto.csv and scaling.csv (docs/charts/*.gp draw them), and the
// tables to stdout as Markdown (docs/performance.md).
//
//   sweep OUTDIR            the full sweep (about ten minutes)
//   sweep --quick OUTDIR    one iteration count and one time step per method, in seconds
//
// Every point plotted is measured; a point whose run would not fit its time budget is written
// with status "over budget" (or "skipped" when a cheaper point already was) and never plotted.
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

struct Grid {
  std::vector<std::string> solvers;
  std::vector<int> iterations;
  std::vector<int> stepsPerSecond;
  /// s of stepping one point may take; a run that reaches it stops and is not plotted.
  double pointBudget;
};

Grid sweepGrid(bool quick) {
  if (quick) return {{"micro", "sequential", "reference", "soft_step", "box2d"}, {8}, {60}, 5.0};
  return {{"micro", "sequential", "reference", "soft_step", "box2d"},
          {1, 2, 4, 8, 16, 32, 64},
          {30, 60, 120, 240},
          10.0};
}

/// The points of the sweep in the order they run: cheap ones first within each method, so a
/// point over budget lets the dearer ones behind it be skipped.
std::vector<SweepPoint> sweepPoints(const Grid& grid) {
  std::vector<SweepPoint> points;
  for (size_t panel = 0; panel < kPanels.size(); ++panel) {
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
  const bool quick = argc == 3 && std::string(argv[1]) == "--quick";
  if (argc != 2 && !quick) {
    std::fprintf(stderr, "usage: sweep [--quick] OUTDIR\n");
    return 2;
  }
  const std::string outputDirectory = argv[argc - 1];
  const std::string problem = outputDirectoryProblem(outputDirectory);
  if (!problem.empty()) {
    std::fprintf(stderr, "sweep: error: OUTDIR %s\nusage: sweep [--quick] OUTDIR\n",
                 problem.c_str());
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  const Grid grid = sweepGrid(quick);
  std::vector<SweepPoint> points = sweepPoints(grid);
  const std::vector<int> rows = quick ? std::vector<int>{4, 9, 14} : scalingFamilyRows();
  std::vector<ScalingPoint> scaling = scalingPoints(rows);
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
  printScalingTable(scaling);
  return 0;
}
