// The points of the speed-versus-accuracy sweep: what each measured, which lie on the Pareto
// front of its scene, and how they are written (CSV for gnuplot, Markdown for the docs).
#pragma once

#include <string>
#include <vector>

namespace benchmarks {

inline const std::string kMeasured = "measured";
/// The run reached its time budget before its last step: not plotted.
inline const std::string kOverBudget = "over budget";
/// A cheaper point of the same scene and method was over budget, so this one was not run.
inline const std::string kSkipped = "skipped";
/// The method could not solve a step of the run (the reference says why); not plotted.
inline const std::string kFailed = "failed";

struct SweepPoint {
  std::string scene;
  std::string errorName;
  std::string solver;
  int iterations = 0;  ///< the method's own knob; 0 for reference, which has none
  int stepsPerSecond = 60;
  std::string status = kSkipped;
  double microsecondsPerStep = 0.0;  ///< median after warm-up
  double error = 0.0;                ///< the scene's error (errorName)
  bool pareto = false;

  /// ms of computation per simulated second: the cost of a point whatever its time step.
  double costPerSimulatedSecond() const { return microsecondsPerStep * stepsPerSecond / 1000.0; }
  bool plotted() const;
};

/// "pyramid20 sequential 8 it 1/60 s", for the progress bar.
std::string describe(const SweepPoint& point);

/// Marks the measured points no other point of their scene beats in both cost and error.
void markParetoFront(std::vector<SweepPoint>& points);

void writeSweepCsv(const std::string& path, const std::vector<SweepPoint>& points);

/// The Pareto front of each scene, cheapest first, scene after scene, so gnuplot can draw each
/// front as one line.
void writeParetoCsv(const std::string& path, const std::vector<SweepPoint>& points);

/// Per scene: the Pareto front, each method's most accurate point and how many of its points
/// were not measured; then the sweep's run time.
void printSweepTables(const std::vector<SweepPoint>& points, double minutes);

}  // namespace benchmarks
