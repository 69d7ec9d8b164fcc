// The cost and accuracy of every contact method and of Box2D 2.4.1, measured in one run (issue
// 7). Runs of the same scene step side by side, one step of each in turn, so the load of other
// programs on the machine falls on all of them alike; times are medians over the steps after
// warm-up. Prints Markdown tables (docs/performance.md shows them) and the verdict on the
// pyramid20 target.
//
//   solver_benchmark             the full tables (a few minutes)
//   solver_benchmark --quick     every table on shortened runs, in seconds (a smoke test)
//   solver_benchmark --speed [SCENE...]  sequential impulses at 8+3, at their defaults and under
//                                the box2d_2_4 preset against Box2D 8+3 on pyramid20, pyramid40,
//                                rain and stack20: time ratios (medians, same run) and accuracy
//   solver_benchmark --callgrind SCENE SOLVER ITERATIONS WARMUP STEPS
//                                runs WARMUP steps of the shipped SCENE with SOLVER at ITERATIONS
//                                (0: its default), then STEPS steps inside measuredSteps(), for
//                                valgrind --tool=callgrind --toggle-collect='*measuredSteps*'
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "impulse2d/box2d/box2d_simulation.h"
#include "measures/analytic_checks.h"
#include "measures/benchmark_scenes.h"
#include "measures/measured_run.h"

using namespace impulse2d;
using namespace benchmarks;

namespace {

/// The target: sequential impulses at most this fraction of Box2D's time per step...
constexpr double kTargetTimeRatio = 0.5;
/// ...with a settled drift no larger than this (m).
constexpr double kTargetDrift = 0.001;
/// s. Micro and reference are slow on big scenes: their pyramid drift is measured to this time.
constexpr double kShortRunTime = 4.0;

/// One row of a table: a method with its iterations, and how long it runs.
struct MethodRun {
  std::string label;
  std::string solver;
  int iterations = 0;    ///< 0: the method's default
  double runTime = 0.0;  ///< s; 0: the scene's own steps
  std::string preset;    ///< the solver's preset (presets.h); empty: our defaults
};

/// The method as published by Box2D 2.4.1 on our sequential impulses (8 + 3 iterations).
const MethodRun kBox2d24Preset = {"sequential preset box2d_2_4", "sequential", 0, 0.0, "box2d_2_4"};

/// How the whole benchmark is shortened by --quick.
struct Length {
  bool quick = false;
  /// Steps of a run in --quick, whatever it asks for...
  long quickSteps = 90;
  /// ...and at most this many seconds of stepping (micro is slow on the pyramids).
  double quickTimeBudget = 1.0;
};

const std::vector<MethodRun> kPyramidMethods = {
    {"box2d 8+3 iterations", "box2d", 8, 0.0, ""},
    {"sequential 8 iterations + position pass", "sequential", 8, 0.0, ""},
    {"sequential 16 iterations + position pass", "sequential", 16, 0.0, ""},
    {"sequential ≤ 40 sweeps, stop once converged (default) + position pass", "sequential", 0, 0.0,
     ""},
    {"soft step 4 substeps (default)", "soft_step", 0, 0.0, ""},
    {"micro ≤ 200 per contact, more while progressing (default)", "micro", 0, kShortRunTime, ""},
    {"reference (active set)", "reference", 0, kShortRunTime, ""},
};

const std::vector<MethodRun> kStackMethods = {
    {"box2d 8+3", "box2d", 8, 0.0, ""},
    {"sequential 8", "sequential", 8, 0.0, ""},
    {"sequential ≤ 40, converged (default)", "sequential", 0, 0.0, ""},
    {"soft step 4 substeps (default)", "soft_step", 0, 0.0, ""},
    {"micro ≤ 200 per contact, more while progressing (default)", "micro", 0, 0.0, ""},
    {"reference", "reference", 0, 0.0, ""},
};

RunPlan planFor(const Scene& scene, const MethodRun& method, const Length& length) {
  RunPlan plan;
  plan.steps = method.runTime > 0.0 ? std::lround(method.runTime / scene.world.dt) : scene.steps;
  plan.settledTime = settledTime(scene);
  if (length.quick) {
    plan.steps = std::min(plan.steps, length.quickSteps);
    plan.timeBudget = length.quickTimeBudget;
    plan.settledTime = std::min(plan.settledTime, 1.0);
  }
  return plan;
}

std::string cell(double value, const char* format) {
  if (std::isnan(value)) return "—";
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

/// Runs the methods on the scene side by side and returns their figures in the same order.
std::vector<RunFigures> measure(const Scene& scene, const std::vector<MethodRun>& methods,
                                const Length& length) {
  std::vector<MeasuredRun> runs;
  for (const MethodRun& method : methods) {
    runs.emplace_back(
        withPreset(withMethod(scene, method.solver, method.iterations), method.preset),
        planFor(scene, method, length));
  }
  runSideBySide(runs);
  std::vector<RunFigures> figures;
  for (const MeasuredRun& run : runs) figures.push_back(run.figures());
  return figures;
}

void printFigureTable(const Scene& scene, const std::vector<MethodRun>& methods,
                      const std::vector<RunFigures>& figures, bool forces) {
  std::printf("\n### %s (%zu bodies, sleeping off)\n\n", scene.name.c_str(), scene.bodies.size());
  std::printf(
      "| method | steps | µs per step | settled drift (m) | largest penetration at rest (m) | "
      "energy gained at rest (J) |%s\n| --- | --- | --- | --- | --- | --- |%s\n",
      forces ? " contact-force error |" : "", forces ? " --- |" : "");
  for (size_t i = 0; i < methods.size(); ++i) {
    const RunFigures& f = figures[i];
    std::printf("| %s | %ld | %s | %s | %s | %s |", methods[i].label.c_str(), f.stepsRun,
                cell(f.medianMicroseconds, "%.0f").c_str(), cell(f.drift, "%.2e").c_str(),
                cell(f.largestPenetration, "%.2e").c_str(), cell(f.energyGain, "%.2e").c_str());
    if (forces) std::printf(" %s |", cell(f.stackForceError, "%.2e").c_str());
    std::printf("\n");
  }
}

std::vector<RunFigures> measureAndPrint(const std::string& sceneName,
                                        const std::vector<MethodRun>& methods, const Length& length,
                                        bool forces) {
  const Scene scene = shippedScene(sceneName);
  std::vector<RunFigures> figures = measure(scene, methods, length);
  printFigureTable(scene, methods, figures, forces);
  return figures;
}

/// One row of the verdict: a sequential-impulse run of the pyramid table against Box2D's.
void printTargetRow(const MethodRun& method, const RunFigures& sequential,
                    const RunFigures& box2d) {
  const double ratio = sequential.medianMicroseconds / box2d.medianMicroseconds;
  std::printf("| %s | %.2f× (%.0f / %.0f µs) | %s | %.2e m (Box2D %.2e m) | %s |\n",
              method.label.c_str(), ratio, sequential.medianMicroseconds, box2d.medianMicroseconds,
              ratio <= kTargetTimeRatio ? "yes" : "no", sequential.drift, box2d.drift,
              sequential.drift <= kTargetDrift ? "yes" : "no");
}

/// Every sequential-impulse row of the pyramid table against the Box2D row. The target
/// is the one at 8 iterations; those at 16 and 20 show what meeting the drift target costs.
void printTargetVerdict(const std::vector<RunFigures>& pyramid) {
  std::printf("\n### Target on pyramid20: sequential impulses against Box2D 8+3, same run\n\n");
  std::printf(
      "| sequential | time per step / Box2D's | ≤ %.1f× | settled drift 1-10 s | ≤ %.0e m |\n",
      kTargetTimeRatio, kTargetDrift);
  std::printf("| --- | --- | --- | --- | --- |\n");
  const RunFigures* box2d = nullptr;
  for (size_t i = 0; i < kPyramidMethods.size(); ++i) {
    if (kPyramidMethods[i].solver == "box2d") box2d = &pyramid[i];
  }
  for (size_t i = 0; i < kPyramidMethods.size(); ++i) {
    if (kPyramidMethods[i].solver == "sequential") {
      printTargetRow(kPyramidMethods[i], pyramid[i], *box2d);
    }
  }
}

/// Soft step's target: no more than Box2D's time per step, settled drift ≤ 1 mm.
void printSoftStepVerdict(const std::vector<RunFigures>& pyramid) {
  std::printf("\n### Target on pyramid20: soft step against Box2D 8+3, same run\n\n");
  std::printf(
      "| soft step | time per step / Box2D's | ≤ 1.0× | settled drift 1-10 s | ≤ %.0e m |\n",
      kTargetDrift);
  std::printf("| --- | --- | --- | --- | --- |\n");
  const RunFigures* box2d = nullptr;
  for (size_t i = 0; i < kPyramidMethods.size(); ++i) {
    if (kPyramidMethods[i].solver == "box2d") box2d = &pyramid[i];
  }
  for (size_t i = 0; i < kPyramidMethods.size(); ++i) {
    if (kPyramidMethods[i].solver != "soft_step") continue;
    const double ratio = pyramid[i].medianMicroseconds / box2d->medianMicroseconds;
    std::printf("| %s | %.2f× (%.0f / %.0f µs) | %s | %.2e m (Box2D %.2e m) | %s |\n",
                kPyramidMethods[i].label.c_str(), ratio, pyramid[i].medianMicroseconds,
                box2d->medianMicroseconds, ratio <= 1.0 ? "yes" : "no", pyramid[i].drift,
                box2d->drift, pyramid[i].drift <= kTargetDrift ? "yes" : "no");
  }
}

void printAnalyticTable(const std::vector<std::string>& solvers) {
  std::vector<std::vector<AnalyticCheck>> checks;
  for (const std::string& solver : solvers) checks.push_back(analyticChecks(solver));
  std::printf("\n### Analytic answers (shipped lecture scenes, each method's defaults)\n\n");
  std::printf("| scene | quantity | analytic |");
  for (const std::string& solver : solvers) std::printf(" %s |", solver.c_str());
  std::printf("\n| --- | --- | --- |");
  for (size_t i = 0; i < solvers.size(); ++i) std::printf(" --- |");
  for (size_t row = 0; row < checks[0].size(); ++row) {
    const AnalyticCheck& check = checks[0][row];
    std::printf("\n| %s | %s | %.4f |", check.scene.c_str(), check.quantity.c_str(),
                check.expected);
    for (const std::vector<AnalyticCheck>& method : checks) {
      std::printf(" %.4f (error %+.1e) |", method[row].measured,
                  method[row].measured - check.expected);
    }
  }
  std::printf("\n");
}

/// Sequential impulses' targets: time per step / Box2D's at 8+3 iterations, and at the defaults.
constexpr double kSpeedTargetAtBox2dIterations = 0.8;
constexpr double kSpeedTargetAtDefaults = 1.0;

/// One scene's row of the speed table: Box2D 8+3, sequential 8+3, sequential at its defaults,
/// sequential under the box2d_2_4 preset.
void printSpeedRow(const std::string& sceneName, const std::vector<RunFigures>& f) {
  const double atBox2dIterations = f[1].medianMicroseconds / f[0].medianMicroseconds;
  const double atDefaults = f[2].medianMicroseconds / f[0].medianMicroseconds;
  const double asBox2d = f[3].medianMicroseconds / f[0].medianMicroseconds;
  std::printf("| %s | %.0f | %.2f× (%s) | %.2f× (%s) | %.2f× |", sceneName.c_str(),
              f[0].medianMicroseconds, atBox2dIterations,
              atBox2dIterations <= kSpeedTargetAtBox2dIterations ? "met" : "not met", atDefaults,
              atDefaults <= kSpeedTargetAtDefaults ? "met" : "not met", asBox2d);
  for (auto figure :
       {&RunFigures::drift, &RunFigures::largestPenetration, &RunFigures::stackForceError}) {
    std::printf(" %s / %s / %s / %s |", cell(f[0].*figure, "%.2e").c_str(),
                cell(f[1].*figure, "%.2e").c_str(), cell(f[2].*figure, "%.2e").c_str(),
                cell(f[3].*figure, "%.2e").c_str());
  }
  std::printf("\n");
}

/// Sequential impulses against Box2D 2.4.1 in one alternating run per scene.
/// Instructions per step come from the --callgrind mode (docs/sequential-impulses.md).
void printSpeedTable(const std::vector<std::string>& sceneNames) {
  const std::vector<MethodRun> methods = {kStackMethods[0], kStackMethods[1], kStackMethods[2],
                                          kBox2d24Preset};
  std::printf("\n### Sequential impulses against Box2D 2.4.1 (medians, same run)\n\n");
  std::printf(
      "| scene | Box2D 8+3 µs | sequential 8+3 / Box2D (≤ %.1f×) | sequential defaults / Box2D "
      "(≤ %.1f×) | preset box2d_2_4 / Box2D | settled drift m (Box2D / 8+3 / defaults / "
      "box2d_2_4) | largest penetration m | stack force error |\n| --- | --- | --- | --- | --- | "
      "--- | --- | --- |\n",
      kSpeedTargetAtBox2dIterations, kSpeedTargetAtDefaults);
  for (const std::string& sceneName : sceneNames) {
    const Scene scene = shippedScene(sceneName);
    printSpeedRow(sceneName, measure(scene, methods, Length{}));
  }
}

/// Kept out of line so callgrind can count exactly these steps (--toggle-collect).
__attribute__((noinline)) void measuredSteps(Simulation& simulation, long steps) {
  for (long i = 0; i < steps; ++i) simulation.step();
}

int callgrindRun(char** arguments) {
  const Scene scene = withMethod(shippedScene(arguments[0]), arguments[1], std::atoi(arguments[2]));
  std::unique_ptr<Simulation> simulation = makeSimulation(scene);
  for (long i = 0, warmup = std::atol(arguments[3]); i < warmup; ++i) simulation->step();
  measuredSteps(*simulation, std::atol(arguments[4]));
  std::printf("%s %s: %d contact points\n", arguments[0], arguments[1],
              contactPointCount(*simulation));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "--callgrind" && argc == 7) return callgrindRun(argv + 2);
  if (mode == "--speed") {
    const std::vector<std::string> only(argv + 2, argv + argc);
    printSpeedTable(only.empty()
                        ? std::vector<std::string>{"pyramid20", "pyramid40", "rain", "stack20"}
                        : only);
    return 0;
  }
  if (!mode.empty() && mode != "--quick") {
    std::fprintf(stderr,
                 "usage: solver_benchmark [--quick | --speed [SCENE...] | --callgrind SCENE SOLVER "
                 "ITERATIONS WARMUP STEPS]\n");
    return 2;
  }
  const Length length{mode == "--quick"};
  std::printf("## Cost and accuracy, every method and Box2D in one run%s\n",
              length.quick ? " (--quick: shortened runs, figures not meaningful)" : "");
  const std::vector<RunFigures> pyramid =
      measureAndPrint("pyramid20", kPyramidMethods, length, false);
  measureAndPrint("stack10", kStackMethods, length, true);
  measureAndPrint("stack20", kStackMethods, length, true);
  measureAndPrint("pyramid40",
                  {kPyramidMethods[0], kPyramidMethods[1], kPyramidMethods[3], kPyramidMethods[4],
                   kPyramidMethods[6]},
                  length, false);
  measureAndPrint(
      "rain",
      {kStackMethods[0], kStackMethods[1], kStackMethods[2], kStackMethods[3], kStackMethods[4]},
      length, false);
  printAnalyticTable({"box2d", "sequential", "micro", "reference", "soft_step"});
  printTargetVerdict(pyramid);
  printSoftStepVerdict(pyramid);
  return 0;
}
