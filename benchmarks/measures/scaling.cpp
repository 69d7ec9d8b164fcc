// The scaling family (scaling.h).
#include "scaling.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "benchmark_scenes.h"
#include "measured_run.h"

using namespace impulse2d;

namespace benchmarks {

namespace {

const std::vector<std::string> kScalingSolvers = {"micro", "sequential", "reference", "soft_step",
                                                  "box2d"};

/// s of stepping one size may take.
constexpr double kSizeBudget = 10.0;
/// Steps whose time is not counted, then steps measured at most.
constexpr long kScalingWarmup = 3;
constexpr long kScalingSteps = 20;

ScalingPoint measureSize(ScalingPoint point) {
  RunPlan plan;
  plan.warmupSteps = kScalingWarmup;
  plan.steps = kScalingWarmup + kScalingSteps;
  plan.timeBudget = kSizeBudget;
  MeasuredRun run(withMethod(pyramidScene(point.rows), point.solver, 0), plan);
  point.failure = runToEnd(run);
  if (!point.failure.empty()) return point;
  const RunFigures figures = run.figures();
  point.stepsMeasured = std::max(0L, figures.stepsRun - kScalingWarmup);
  point.measured = point.stepsMeasured > 0;
  point.microsecondsPerStep = figures.medianMicroseconds;
  point.contactPoints = figures.contactPoints;
  return point;
}

/// Whether the size after `previous` can be afforded (see measureScaling).
bool affordable(const ScalingPoint& previous, const ScalingPoint& next) {
  if (previous.solver != next.solver) return true;
  if (!previous.measured) return false;
  const double growth = std::pow(double(next.boxes) / previous.boxes, 3.0);
  const double stepSeconds = previous.microsecondsPerStep * 1e-6 * growth;
  return stepSeconds * (kScalingWarmup + 1) <= kSizeBudget;
}

}  // namespace

std::vector<ScalingPoint> scalingPoints(const std::vector<int>& rows) {
  std::vector<ScalingPoint> points;
  for (const std::string& solver : kScalingSolvers) {
    for (int row : rows) {
      ScalingPoint point;
      point.solver = solver;
      point.rows = row;
      point.boxes = pyramidBoxes(row);
      points.push_back(point);
    }
  }
  return points;
}

void measureScaling(std::vector<ScalingPoint>& points, ProgressBar& progress) {
  for (size_t i = 0; i < points.size(); ++i) {
    progress.show("scaling " + points[i].solver + " " + std::to_string(points[i].boxes) + " boxes");
    if (i == 0 || affordable(points[i - 1], points[i])) points[i] = measureSize(points[i]);
    progress.advance();
  }
}

double fittedExponent(const std::vector<ScalingPoint>& points, const std::string& solver,
                      int maximumBoxes) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const ScalingPoint& point : points) {
    if (point.solver != solver || !point.measured || point.boxes < kFitMinimumBoxes ||
        point.boxes > maximumBoxes) {
      continue;
    }
    const double x = std::log(point.boxes), y = std::log(point.microsecondsPerStep);
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  if (n < 2) return std::numeric_limits<double>::quiet_NaN();
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

void writeScalingCsv(const std::string& path, const std::vector<ScalingPoint>& points) {
  std::ofstream file(path);
  file << "method,rows,boxes,contact_points,us_per_step,steps_measured,fitted_exponent\n";
  for (const ScalingPoint& p : points) {
    if (!p.measured) continue;
    file << p.solver << "," << p.rows << "," << p.boxes << "," << p.contactPoints << ","
         << p.microsecondsPerStep << "," << p.stepsMeasured << ","
         << fittedExponent(points, p.solver) << "\n";
  }
  if (!file) throw std::runtime_error("cannot write " + path);
}

void printScalingTable(const std::vector<ScalingPoint>& points) {
  std::printf("\n### Cost per step against boxes (pyramids, each method's defaults)\n\n| boxes |");
  for (const std::string& solver : kScalingSolvers) std::printf(" %s (µs) |", solver.c_str());
  std::printf("\n| --- |");
  for (size_t i = 0; i < kScalingSolvers.size(); ++i) std::printf(" --- |");
  for (const ScalingPoint& row : points) {
    if (row.solver != kScalingSolvers.front()) break;
    std::printf("\n| %d |", row.boxes);
    for (const ScalingPoint& p : points) {
      if (p.boxes != row.boxes) continue;
      if (p.measured) std::printf(" %.0f |", p.microsecondsPerStep);
      if (!p.measured) std::printf(p.failure.empty() ? " — |" : " failed |");
    }
  }
  std::printf("\n| fitted exponent (≥ %d boxes) |", kFitMinimumBoxes);
  for (const std::string& solver : kScalingSolvers) {
    std::printf(" %.2f |", fittedExponent(points, solver));
  }
  std::printf("\n| fitted exponent (%d to %d boxes: 9 to 40 rows) |", kFitMinimumBoxes,
              kRangeMaximumBoxes);
  for (const std::string& solver : kScalingSolvers) {
    std::printf(" %.2f |", fittedExponent(points, solver, kRangeMaximumBoxes));
  }
  std::printf("\n");
  for (const ScalingPoint& p : points) {
    if (!p.failure.empty())
      std::printf("\n%s on %d boxes failed: %s\n", p.solver.c_str(), p.boxes, p.failure.c_str());
  }
}

}  // namespace benchmarks
