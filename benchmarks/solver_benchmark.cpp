// The cost and accuracy of every contact method and of Box2D 2.4.1, measured in one run (issue
// 7). Runs of the same scene step side by side, one step of each in turn, so the load of other
// programs on the machine falls on all of them alike; times are medians over the steps after
// warm-up. Prints Markdown tables (docs/performance.md shows them) and the verdict on the
// pyramid20 target.
//
//   solver_benchmark             the full tables (a few minutes)
//   solver_benchmark --quick     every table on shortened runs, in seconds (a smoke test)
//   solver_benchmark --speed [SCENE...]  every method at its defaults, sequential impulses also
//                                at 8+3 and under the box2d_2_4 preset, against Box2D 8+3 on
//                                pyramid20, pyramid40 and rain, each run as long as the targets'
//                                anchor: whole runs' time per step as ratios to b2World::Step
//                                alone (medians over rounds of runs in turn) against the targets,
//                                the median step beside them
//   solver_benchmark --callgrind [--quick]  instructions per step of every method and of Box2D
//                                (b2World::Step alone, and through the adapter) on stack10,
//                                pyramid20, pyramid40 and rain, each run under valgrind in turn
//                                and read with callgrind_annotate
//   solver_benchmark --cost-split [--quick] CSV  each method's and Box2D's instructions per step
//                                on pyramid20, pyramid40 and rain, split into finding contacts,
//                                preparing, solving velocities, solving positions and the rest:
//                                a Markdown table, and CSV for docs/charts/cost_split.gp
//   solver_benchmark --sweeps SCENE  sequential impulses stopping once converged, capped at 40,
//                                160 and 640 sweeps, on runs as long as --speed's: the mean
//                                sweeps per step in each second of the run, and how many steps
//                                reach the cap; then each run's settled drift beside Box2D's
//   solver_benchmark --callgrind SCENE SOLVER ITERATIONS WARMUP STEPS
//                                runs WARMUP steps of the shipped SCENE with SOLVER at ITERATIONS
//                                (0: its default), then STEPS steps inside measuredSteps(), for
//                                valgrind --tool=callgrind --toggle-collect='*measuredSteps*'
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include <unistd.h>

#include "impulse2d/box2d/box2d_simulation.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/world.h"
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

/// The speed targets, as a fraction of Box2D 2.4.1's time per step. Soft step's are Box2D
/// v3.1.1's scalar build against 2.4.1 (docs/performance.md), timed as whole runs of `steps`
/// steps, so every speed run has that length and is judged on its whole run's time per step;
/// NaN: no target on that scene.
struct SpeedTarget {
  std::string scene;
  long steps;
  double softStep;
  double sequentialAtDefaults;
};
const std::vector<SpeedTarget> kSpeedTargets = {
    {"pyramid20", 1000, 0.72, std::nan("")},
    {"pyramid40", 500, 0.60, 0.5},
    {"rain", 1000, 0.67, 0.5},
};
/// Sequential impulses at Box2D's own 8+3 iterations: at most this fraction of its time.
constexpr double kSpeedTargetAtBox2dIterations = 0.8;

SpeedTarget speedTargetOf(const std::string& sceneName) {
  for (const SpeedTarget& target : kSpeedTargets) {
    if (target.scene == sceneName) return target;
  }
  return {sceneName, 0, std::nan(""), std::nan("")};
}

/// "0.64× (≤ 0.60: not met)", or just the ratio where the scene has no target.
std::string ratioCell(double ratio, double target) {
  std::string text = cell(ratio, "%.2f×");
  if (std::isnan(target)) return text;
  return text + " (≤ " + cell(target, "%.2f") + ": " + (ratio <= target ? "met" : "not met") + ")";
}

/// The methods of the speed table, Box2D first; ratios are to it.
const std::vector<MethodRun> kSpeedMethods = {
    kStackMethods[0], kStackMethods[1], kStackMethods[2],
    kBox2d24Preset,   kStackMethods[3], kStackMethods[4],
};

/// Whole runs of every method, repeated in turn (A B C … A B C …) so that a change in the
/// machine's load falls on all of them alike, while each run keeps its own data in the caches
/// as a program of its own would: stepping the methods one step each instead leaves every
/// step to start from caches the others have filled. The ratio to Box2D is the median over the
/// rounds of the ratio within a round.
constexpr int kSpeedRounds = 3;
/// s of stepping a speed run may take (micro takes a tenth of a second a step on rain); the
/// median then covers the steps taken.
constexpr double kSpeedRunBudget = 10.0;

double medianOf(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

/// The rounds' figures of one scene: figures[round][method].
std::vector<std::vector<RunFigures>> measureRounds(const Scene& scene, long steps) {
  std::vector<std::vector<RunFigures>> rounds(kSpeedRounds);
  for (std::vector<RunFigures>& round : rounds) {
    for (const MethodRun& method : kSpeedMethods) {
      RunPlan plan = planFor(scene, method, Length{});
      if (steps > 0) plan.steps = steps;
      plan.warmupSteps = 0;
      plan.timeBudget = kSpeedRunBudget;
      MeasuredRun run(
          withPreset(withMethod(scene, method.solver, method.iterations), method.preset), plan);
      runToEnd(run);
      round.push_back(run.figures());
    }
  }
  return rounds;
}

/// One scene's row of the speed table: medians over the rounds.
void printSpeedRow(const std::string& sceneName,
                   const std::vector<std::vector<RunFigures>>& rounds) {
  const SpeedTarget target = speedTargetOf(sceneName);
  const auto medianOver = [&rounds](auto figureOfRound) {
    std::vector<double> values;
    for (const std::vector<RunFigures>& round : rounds) values.push_back(figureOfRound(round));
    return medianOf(values);
  };
  const double box2d = medianOver([](const auto& f) { return f[0].meanMicroseconds; });
  const double box2dMedian = medianOver([](const auto& f) { return f[0].medianMicroseconds; });
  const double wrapper = medianOver([](const auto& f) { return f[0].medianWholeStepMicroseconds; });
  std::printf("| %s (%ld) | %.0f | %.0f (+%.0f%%) |", sceneName.c_str(), rounds[0][0].stepsRun,
              box2d, wrapper, 100.0 * (wrapper / box2dMedian - 1.0));
  const double targets[] = {kSpeedTargetAtBox2dIterations, target.sequentialAtDefaults,
                            std::nan(""), target.softStep, std::nan("")};
  for (size_t i = 1; i < kSpeedMethods.size(); ++i) {
    const double ratio = medianOver(
        [i](const auto& f) { return f[i].medianMicroseconds / f[0].medianMicroseconds; });
    const double meanRatio =
        medianOver([i](const auto& f) { return f[i].meanMicroseconds / f[0].meanMicroseconds; });
    std::printf(" %s, median step %s |", ratioCell(meanRatio, targets[i - 1]).c_str(),
                cell(ratio, "%.2f×").c_str());
  }
  const std::vector<RunFigures>& first = rounds[0];
  std::printf(" %s |", cell(first[0].drift, "%.2e").c_str());
  for (size_t i = 1; i < first.size(); ++i)
    std::printf(" %s", cell(first[i].drift, "%.2e").c_str());
  std::printf(" |\n");
  std::fflush(stdout);
}

/// Every method at its defaults (and sequential impulses at Box2D's 8+3) against Box2D 2.4.1,
/// each run as long as the target's anchor was. Box2D's time is b2World::Step alone. Each cell
/// is the ratio of whole runs' time per step (the mean step, every step counted), judged against
/// the target, and beside it the ratio of median steps (a typical step). Instructions per step
/// come from the --callgrind mode.
void printSpeedTable(const std::vector<std::string>& sceneNames) {
  std::printf(
      "\n### Against Box2D 2.4.1: time per step / Box2D's b2World::Step (median over %d rounds "
      "of whole runs in turn): a whole run's time per step against the target, the median step "
      "beside it\n\n",
      kSpeedRounds);
  std::printf(
      "| scene (steps) | Box2D Step µs, whole run per step | Box2D through the adapter, median "
      "µs | sequential 8+3 | sequential "
      "defaults | sequential preset box2d_2_4 | soft step | micro | settled drift m, Box2D | "
      "settled drift m, same order |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- | "
      "--- |\n");
  for (const std::string& sceneName : sceneNames) {
    printSpeedRow(sceneName,
                  measureRounds(shippedScene(sceneName), speedTargetOf(sceneName).steps));
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

/// One row of the instruction table: a method on a scene, the steps callgrind skips and counts,
/// and the function whose calls it counts.
struct CallgrindRow {
  std::string scene;
  std::string label;
  std::string solver;
  int iterations;
  long warmup;
  long steps;
  /// The function whose inclusive cost within the measured steps is counted; empty: all of
  /// measuredSteps().
  std::string counted;
};

/// Box2D's own step, without the adapter: the fair figure to compare ours with.
const char* const kBox2dStep = "b2World::Step(";
const char* const kMeasuredSteps = "";

std::vector<CallgrindRow> callgrindRows(bool quick) {
  // pyramid20 counts steps 61-80; rain starts counting at 4 s, once its last circles have landed.
  const std::vector<std::pair<std::string, std::pair<long, long>>> scenes = {
      {"stack10", {60, 20}}, {"pyramid20", {60, 20}}, {"pyramid40", {60, 10}}, {"rain", {240, 10}}};
  std::vector<CallgrindRow> rows;
  for (const auto& [scene, lengths] : scenes) {
    const long warmup = quick ? 1 : lengths.first;
    const long steps = quick ? 1 : lengths.second;
    rows.push_back(
        {scene, "box2d 8+3, b2World::Step alone", "box2d", 8, warmup, steps, kBox2dStep});
    rows.push_back(
        {scene, "box2d 8+3, through the adapter", "box2d", 8, warmup, steps, kMeasuredSteps});
    rows.push_back({scene, "sequential 8+3", "sequential", 8, warmup, steps, kMeasuredSteps});
    rows.push_back({scene, "sequential (default)", "sequential", 0, warmup, steps, kMeasuredSteps});
    rows.push_back({scene, "soft step (default)", "soft_step", 0, warmup, steps, kMeasuredSteps});
    if (scene == "rain") continue;  // micro takes a tenth of a second a step as the circles land
    rows.push_back({scene, "micro (default)", "micro", 0, warmup, steps, kMeasuredSteps});
  }
  // The global reference costs seconds a step on the large scenes: counted on the small ones.
  rows.push_back({"stack10", "reference (default)", "reference", 0, quick ? 1 : 60, quick ? 1 : 20,
                  kMeasuredSteps});
  rows.push_back({"pyramid20", "reference (default)", "reference", 0, quick ? 1 : 10, quick ? 1 : 2,
                  kMeasuredSteps});
  return rows;
}

/// Every function callgrind counted, as callgrind_annotate names it ("PROGRAM TOTALS" for the
/// whole), with its inclusive instructions.
using InclusiveCosts = std::vector<std::pair<std::string, long long>>;

/// The inclusive cost of each function in callgrind's output file (read with callgrind_annotate);
/// empty if it could not be read.
InclusiveCosts inclusiveCosts(const std::string& output) {
  const std::string command =
      "callgrind_annotate --inclusive=yes --threshold=100 " + output + " 2>/dev/null";
  FILE* annotation = popen(command.c_str(), "r");
  if (!annotation) return {};
  InclusiveCosts costs;
  char line[4096];
  while (std::fgets(line, sizeof line, annotation)) {
    const std::string text = line;
    const size_t start = text.find_first_not_of(' ');
    if (start == std::string::npos || !std::isdigit(static_cast<unsigned char>(text[start]))) {
      continue;
    }
    const size_t end = text.find(' ', start);
    std::string digits;
    for (char c : text.substr(start, end - start)) {
      if (std::isdigit(static_cast<unsigned char>(c))) digits += c;
    }
    costs.emplace_back(text.substr(end), std::atoll(digits.c_str()));
  }
  pclose(annotation);
  return costs;
}

/// The cost of the first function whose name contains `name` ("" for the whole); -1 if none.
long long costOf(const InclusiveCosts& costs, const std::string& name) {
  const std::string wanted = name.empty() ? "PROGRAM TOTALS" : name;
  for (const auto& [function, cost] : costs) {
    if (function.find(wanted) != std::string::npos) return cost;
  }
  return -1;
}

/// Runs this program's --callgrind mode for the row under callgrind and returns the inclusive
/// cost of every function in the measured steps, or nothing if valgrind did not run.
InclusiveCosts measuredCosts(const CallgrindRow& row) {
  char output[] = "/tmp/solver_benchmark_callgrind_XXXXXX";
  const int file = mkstemp(output);
  if (file < 0) return {};
  close(file);
  const std::string command =
      "valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*measuredSteps*' "
      "--callgrind-out-file=" +
      std::string(output) + " /proc/" + std::to_string(getpid()) + "/exe --callgrind " + row.scene +
      " " + row.solver + " " + std::to_string(row.iterations) + " " + std::to_string(row.warmup) +
      " " + std::to_string(row.steps) + " >/dev/null 2>&1";
  const InclusiveCosts costs =
      std::system(command.c_str()) == 0 ? inclusiveCosts(output) : InclusiveCosts{};
  std::remove(output);
  return costs;
}

/// The instructions callgrind counted for the row, or -1 if valgrind did not run.
long long countInstructions(const CallgrindRow& row) {
  return costOf(measuredCosts(row), row.counted);
}

/// Instructions per step of every method and of Box2D, each run under callgrind in turn.
int printCallgrindTable(bool quick) {
  if (std::system("valgrind --version >/dev/null 2>&1") != 0) {
    std::printf("valgrind is not installed: no instruction counts.\n");
    return 0;
  }
  std::printf("| scene | method | warm-up steps | steps counted | instructions per step |\n");
  std::printf("| --- | --- | --- | --- | --- |\n");
  for (const CallgrindRow& row : callgrindRows(quick)) {
    const long long total = countInstructions(row);
    if (total < 0) {
      std::fprintf(stderr, "solver_benchmark: callgrind failed on %s %s\n", row.scene.c_str(),
                   row.label.c_str());
      return 1;
    }
    std::printf("| %s | %s | %ld | %ld | %lld |\n", row.scene.c_str(), row.label.c_str(),
                row.warmup, row.steps, total / row.steps);
    std::fflush(stdout);
  }
  return 0;
}

/// The stages a step's cost is split into (the chart's legend, in order). Debian's Box2D exports
/// no symbols for its island and contact solvers, so its solve stays one stage (b2World::Solve:
/// preparing, both solves and the integration; the broad phase it ends with is finding contacts).
const std::vector<std::string> kStages = {"finding contacts", "preparing", "solving velocities",
                                          "solving positions", "solving (not split)"};

/// Where a method spends a step: for each stage of kStages, the functions whose inclusive costs
/// add up to it ("-" before a name: subtracted, a stage nested in another's function). What the
/// named functions leave of the whole step is "the rest" (integration, sleeping, storing).
struct StageFunctions {
  std::string label;
  std::string solver;
  std::string whole;  ///< the function that is the whole step; empty: all of measuredSteps()
  std::vector<std::vector<std::string>> stages;
};

const std::vector<StageFunctions> kStageFunctions = {
    {"Box2D 2.4.1 (8+3)",
     "box2d",
     kBox2dStep,
     {{"b2ContactManager::Collide(", "b2ContactManager::FindNewContacts("},
      {},
      {},
      {},
      {"b2World::Solve(", "-b2ContactManager::FindNewContacts("}}},
    {"sequential (default)",
     "sequential",
     kMeasuredSteps,
     {{"World::findContacts("},
      {"SequentialImpulseSolver::prepare("},
      {"SequentialImpulseSolver::solveVelocities(", "-SequentialImpulseSolver::prepare("},
      {"impulse2d::correctPositions("},
      {}}},
    {"soft step (default)",
     "soft_step",
     kMeasuredSteps,
     {{"World::findContacts("},
      {"SoftStepSolver::prepareBodies(", "SoftStepSolver::prepareConstraints("},
      {"SoftStepSolver::warmStart(", "SoftStepSolver::solve(", "SoftStepSolver::applyRestitution("},
      {},
      {}}},
    {"micro (default)",
     "micro",
     kMeasuredSteps,
     {{"World::findContacts("},
      {"MicroCollisionSolver::prepare("},
      {"MicroCollisionSolver::solveVelocities(", "-MicroCollisionSolver::prepare("},
      {"MicroCollisionSolver::solvePositions("},
      {}}},
};

/// One stage's instructions: its functions' inclusive costs added (or subtracted). A function
/// callgrind did not count (inlined, renamed) is reported and counts as nothing.
long long stageCost(const InclusiveCosts& costs, const std::vector<std::string>& functions,
                    const std::string& where) {
  long long total = 0;
  for (const std::string& term : functions) {
    const bool subtract = term[0] == '-';
    const std::string name = subtract ? term.substr(1) : term;
    const long long cost = costOf(costs, name);
    if (cost < 0) {
      std::fprintf(stderr, "solver_benchmark: %s: no cost counted for %s\n", where.c_str(),
                   name.c_str());
      continue;
    }
    total += subtract ? -cost : cost;
  }
  return total;
}

/// Each method's instructions per step split into the stages of kStages and the rest, on the
/// scenes of the instruction table (micro not on rain): a Markdown table, and the same figures
/// in millions as CSV (scene, method, stages..., rest) for docs/charts/cost_split.gp.
int printCostSplit(bool quick, const std::string& csvPath) {
  if (std::system("valgrind --version >/dev/null 2>&1") != 0) {
    std::printf("valgrind is not installed: no cost split.\n");
    return 0;
  }
  FILE* csv = std::fopen(csvPath.c_str(), "w");
  if (!csv) {
    std::fprintf(stderr, "solver_benchmark: cannot write %s\n", csvPath.c_str());
    return 1;
  }
  std::fprintf(csv, "scene,method");
  std::printf("| scene | method | instructions per step |");
  for (const std::string& stage : kStages) {
    std::fprintf(csv, ",%s", stage.c_str());
    std::printf(" %s |", stage.c_str());
  }
  std::fprintf(csv, ",the rest\n");
  std::printf(" the rest |\n| --- | --- | --- |");
  for (size_t i = 0; i <= kStages.size(); ++i) std::printf(" --- |");
  std::printf("\n");
  for (const CallgrindRow& row : callgrindRows(quick)) {
    const bool box2dThroughAdapter = row.solver == "box2d" && row.counted == kMeasuredSteps;
    if (row.scene == "stack10" || box2dThroughAdapter) continue;
    const auto method = std::find_if(
        kStageFunctions.begin(), kStageFunctions.end(), [&row](const StageFunctions& method) {
          return method.solver == row.solver && (row.solver == "box2d" || row.iterations == 0);
        });
    if (method == kStageFunctions.end()) continue;
    const InclusiveCosts costs = measuredCosts(row);
    const long long whole = costOf(costs, method->whole);
    if (whole < 0) {
      std::fprintf(stderr, "solver_benchmark: callgrind failed on %s %s\n", row.scene.c_str(),
                   row.label.c_str());
      std::fclose(csv);
      return 1;
    }
    const std::string where = row.scene + " " + method->label;
    std::fprintf(csv, "%s,%s", row.scene.c_str(), method->label.c_str());
    std::printf("| %s | %s | %lld |", row.scene.c_str(), method->label.c_str(), whole / row.steps);
    long long rest = whole;
    for (const std::vector<std::string>& functions : method->stages) {
      const long long cost = stageCost(costs, functions, where);
      rest -= cost;
      std::fprintf(csv, ",%.4f", 1e-6 * cost / row.steps);
      std::printf(" %lld (%.0f%%) |", cost / row.steps, 100.0 * cost / whole);
    }
    std::fprintf(csv, ",%.4f\n", 1e-6 * rest / row.steps);
    std::printf(" %lld (%.0f%%) |\n", rest / row.steps, 100.0 * rest / whole);
    std::fflush(stdout);
  }
  std::fclose(csv);
  return 0;
}

/// The caps of --sweeps: the default, and four and sixteen times it.
const std::vector<int> kSweepCaps = {40, 160, 640};

/// A run of sequential impulses at their defaults but for the cap (the convergence test kept):
/// the sweeps each step made, and the run's figures.
struct CappedRun {
  std::vector<int> sweeps;
  RunFigures figures;
};

/// The length of --sweeps' runs: that of the speed targets where the scene has one, so the
/// figures are those of the runs --speed times.
long sweepRunSteps(const Scene& scene) {
  const long steps = speedTargetOf(scene.name).steps;
  return steps > 0 ? steps : scene.steps;
}

CappedRun runCapped(const std::string& sceneName, const std::string& solver, int cap) {
  Scene scene = withMethod(shippedScene(sceneName), solver, solver == "box2d" ? 8 : 0);
  if (solver == "sequential") {
    applySetting(scene, "solver." + iterationKey(solver) + "=" + std::to_string(cap));
  }
  RunPlan plan;
  plan.steps = sweepRunSteps(scene);
  plan.settledTime = settledTime(scene);
  MeasuredRun run(scene, plan);
  const auto* world = dynamic_cast<const World*>(&run.simulation());
  CappedRun capped;
  while (!run.done()) {
    run.step();
    capped.sweeps.push_back(world ? world->solver().lastReport().iterations : cap);
  }
  capped.figures = run.figures();
  return capped;
}

/// How many sweeps the scene's steps need: per second of the run, the mean sweeps per step and
/// the steps that reach the cap, for each cap of kSweepCaps; then each whole run's mean sweeps,
/// settled drift and deepest contact, beside Box2D 2.4.1's (8+3) on the same steps.
int printSweepsPerStep(const std::string& sceneName) {
  const Scene scene = shippedScene(sceneName);
  const long stepsPerSecond = std::lround(1.0 / scene.world.dt);
  std::vector<CappedRun> runs;
  for (int cap : kSweepCaps) runs.push_back(runCapped(sceneName, "sequential", cap));
  const long steps = static_cast<long>(runs[0].sweeps.size());
  std::printf("| %s, seconds |", sceneName.c_str());
  for (int cap : kSweepCaps) std::printf(" cap %d: mean sweeps, steps at the cap |", cap);
  std::printf("\n| --- |");
  for (size_t i = 0; i < kSweepCaps.size(); ++i) std::printf(" --- |");
  std::printf("\n");
  for (long first = 0; first < steps; first += stepsPerSecond) {
    const long last = std::min<long>(first + stepsPerSecond, steps);
    std::printf("| %.0f–%.0f |", first * scene.world.dt, last * scene.world.dt);
    for (size_t c = 0; c < kSweepCaps.size(); ++c) {
      long total = 0;
      long atCap = 0;
      for (long step = first; step < last; ++step) {
        total += runs[c].sweeps[step];
        atCap += runs[c].sweeps[step] >= kSweepCaps[c];
      }
      std::printf(" %.1f, %ld of %ld |", static_cast<double>(total) / (last - first), atCap,
                  last - first);
    }
    std::printf("\n");
  }
  const RunFigures box2d = runCapped(sceneName, "box2d", 8).figures;
  std::printf(
      "\n| %s, %ld steps, settled from %.0f s | mean sweeps | settled drift m | deepest "
      "contact m |\n| --- | --- | --- | --- |\n",
      sceneName.c_str(), steps, settledTime(scene));
  for (size_t c = 0; c < kSweepCaps.size(); ++c) {
    const std::vector<int>& sweeps = runs[c].sweeps;
    const double mean = std::accumulate(sweeps.begin(), sweeps.end(), 0.0) / sweeps.size();
    std::printf("| sequential, cap %d | %.1f | %.2e | %.2e |\n", kSweepCaps[c], mean,
                runs[c].figures.drift, runs[c].figures.largestPenetration);
  }
  std::printf("| Box2D 2.4.1, 8+3 | 8 | %.2e | %.2e |\n", box2d.drift, box2d.largestPenetration);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "--callgrind" && argc == 7) return callgrindRun(argv + 2);
  if (mode == "--callgrind" && argc <= 3) {
    return printCallgrindTable(argc == 3 && std::string(argv[2]) == "--quick");
  }
  if (mode == "--cost-split" && (argc == 3 || (argc == 4 && std::string(argv[2]) == "--quick"))) {
    return printCostSplit(argc == 4, argv[argc - 1]);
  }
  if (mode == "--sweeps" && argc == 3) return printSweepsPerStep(argv[2]);
  if (mode == "--speed") {
    const std::vector<std::string> only(argv + 2, argv + argc);
    printSpeedTable(only.empty() ? std::vector<std::string>{"pyramid20", "pyramid40", "rain"}
                                 : only);
    return 0;
  }
  if (!mode.empty() && mode != "--quick") {
    std::fprintf(stderr,
                 "usage: solver_benchmark [--quick | --speed [SCENE...] | --callgrind [--quick] | "
                 "--cost-split [--quick] CSV | --sweeps SCENE | --callgrind SCENE SOLVER "
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
