// Sweep points: Pareto front, CSV and Markdown (sweep_points.h).
#include "sweep_points.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace benchmarks {

namespace {

const std::vector<std::string> kSolverOrder = {"micro", "sequential", "reference", "soft_step",
                                               "box2d"};

std::vector<std::string> scenesOf(const std::vector<SweepPoint>& points) {
  std::vector<std::string> scenes;
  for (const SweepPoint& point : points) {
    if (std::find(scenes.begin(), scenes.end(), point.scene) == scenes.end()) {
      scenes.push_back(point.scene);
    }
  }
  return scenes;
}

/// `a` is at least as good as `b` in cost and error, and better in one.
bool dominates(const SweepPoint& a, const SweepPoint& b) {
  const double costA = a.costPerSimulatedSecond(), costB = b.costPerSimulatedSecond();
  return costA <= costB && a.error <= b.error && (costA < costB || a.error < b.error);
}

std::string iterationsText(const SweepPoint& point) {
  return point.solver == "reference" ? "—" : std::to_string(point.iterations);
}

void printPointRow(const SweepPoint& point) {
  std::printf("| %s | %s | 1/%d | %.1f | %.0f | %.2e |\n", point.solver.c_str(),
              iterationsText(point).c_str(), point.stepsPerSecond, point.costPerSimulatedSecond(),
              point.microsecondsPerStep, point.error);
}

/// The scene's Pareto front, cheapest first.
std::vector<SweepPoint> paretoFront(const std::vector<SweepPoint>& points,
                                    const std::string& scene) {
  std::vector<SweepPoint> front;
  for (const SweepPoint& point : points) {
    if (point.scene == scene && point.pareto) front.push_back(point);
  }
  std::sort(front.begin(), front.end(), [](const SweepPoint& a, const SweepPoint& b) {
    return a.costPerSimulatedSecond() < b.costPerSimulatedSecond();
  });
  return front;
}

void printParetoFront(const std::vector<SweepPoint>& points, const std::string& scene) {
  const std::vector<SweepPoint> front = paretoFront(points, scene);
  std::printf("Pareto front, cheapest first:\n\n");
  std::printf("| method | iterations | dt (s) | ms per simulated s | µs per step | error |\n");
  std::printf("| --- | --- | --- | --- | --- | --- |\n");
  for (const SweepPoint& point : front) printPointRow(point);
}

void printMostAccurate(const std::vector<SweepPoint>& points, const std::string& scene) {
  std::printf("\nEach method's most accurate point, and its points not measured (over the %s):\n\n",
              "time budget, dearer than one that was, or failed");
  std::printf(
      "| method | iterations | dt (s) | ms per simulated s | µs per step | error | "
      "not measured |\n| --- | --- | --- | --- | --- | --- | --- |\n");
  for (const std::string& solver : kSolverOrder) {
    const SweepPoint* best = nullptr;
    int notMeasured = 0, total = 0;
    for (const SweepPoint& point : points) {
      if (point.scene != scene || point.solver != solver) continue;
      ++total;
      if (!point.plotted()) ++notMeasured;
      if (point.plotted() && (!best || point.error < best->error)) best = &point;
    }
    if (total == 0) continue;
    if (!best) {
      std::printf("| %s | — | — | — | — | — | %d of %d |\n", solver.c_str(), notMeasured, total);
      continue;
    }
    std::printf("| %s | %s | 1/%d | %.1f | %.0f | %.2e | %d of %d |\n", solver.c_str(),
                iterationsText(*best).c_str(), best->stepsPerSecond, best->costPerSimulatedSecond(),
                best->microsecondsPerStep, best->error, notMeasured, total);
  }
}

}  // namespace

bool SweepPoint::plotted() const {
  return status == kMeasured && std::isfinite(error);
}

std::string describe(const SweepPoint& point) {
  return point.scene + " " + point.solver + " " + iterationsText(point) + " it 1/" +
         std::to_string(point.stepsPerSecond) + " s";
}

void markParetoFront(std::vector<SweepPoint>& points) {
  for (SweepPoint& point : points) {
    point.pareto =
        point.plotted() &&
        std::none_of(points.begin(), points.end(), [&point](const SweepPoint& other) {
          return other.plotted() && other.scene == point.scene && dominates(other, point);
        });
  }
}

// No field holds a comma (error names and statuses are written without), so gnuplot reads the
// file as it is.
void writeSweepCsv(const std::string& path, const std::vector<SweepPoint>& points) {
  std::ofstream file(path);
  file << "scene,error_name,method,iterations,dt,us_per_step,ms_per_simulated_s,error,status,"
          "pareto\n";
  for (const SweepPoint& p : points) {
    file << p.scene << "," << p.errorName << "," << p.solver << "," << p.iterations << ","
         << 1.0 / p.stepsPerSecond << "," << p.microsecondsPerStep << ","
         << p.costPerSimulatedSecond() << "," << p.error << "," << p.status << ","
         << (p.pareto ? 1 : 0) << "\n";
  }
  if (!file) throw std::runtime_error("cannot write " + path);
}

void writeParetoCsv(const std::string& path, const std::vector<SweepPoint>& points) {
  std::ofstream file(path);
  file << "scene,method,iterations,dt,ms_per_simulated_s,error\n";
  for (const std::string& scene : scenesOf(points)) {
    for (const SweepPoint& p : paretoFront(points, scene)) {
      file << p.scene << "," << p.solver << "," << p.iterations << "," << 1.0 / p.stepsPerSecond
           << "," << p.costPerSimulatedSecond() << "," << p.error << "\n";
    }
  }
  if (!file) throw std::runtime_error("cannot write " + path);
}

void printSweepTables(const std::vector<SweepPoint>& points, double minutes) {
  for (const std::string& scene : scenesOf(points)) {
    const auto first = std::find_if(points.begin(), points.end(),
                                    [&scene](const SweepPoint& p) { return p.scene == scene; });
    std::printf("\n### %s: %s\n\n", scene.c_str(), first->errorName.c_str());
    printParetoFront(points, scene);
    printMostAccurate(points, scene);
  }
  std::printf("\nThe sweep ran %zu points in %.1f minutes.\n", points.size(), minutes);
}

}  // namespace benchmarks
