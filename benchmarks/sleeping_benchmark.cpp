// What modelling only what a scene needs buys (docs/sleeping.md):
//   1. a settled 20-row pyramid under sequential impulses, awake (sleeping = false) against
//      asleep: median µs per step and their ratio (target: asleep ≤ 5% of awake);
//   2. the micro-collision resolver's cost against contact points on pyramids of 5..30 rows,
//      with the fitted exponent of time ∝ points^k (and of impulses, to show the cost per
//      impulse stays flat: the worst-first heap does not rescan);
//   3. a 5050-box pyramid: µs per step, and the share of it the broad and narrow phase take.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "impulse2d/scene/scene.h"

using namespace impulse2d;
using Clock = std::chrono::steady_clock;

namespace {

constexpr int sleepRows = 20;
constexpr double settleSeconds = 3.0;
constexpr int timedSteps = 200;
constexpr int microRows[] = {5, 10, 15, 20, 25, 30};
constexpr int microWarmUpSteps = 3;
constexpr int microTimedSteps = 7;
constexpr int largeRows = 100;  // 100 + 99 + ... + 1 = 5050 boxes
constexpr int largeTimedSteps = 10;

Scene pyramidScene(const std::string& solver, int rows, bool sleeping) {
  Scene scene;
  scene.solver = solver;
  scene.world.sleep = sleeping ? Sleep::KeepSpeedingUpAwake : Sleep::Off;
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.shape = makeBox(2.0 * rows + 20.0, 1.0);
  ground.position = Vec2(0.0, -0.5);
  scene.bodies.push_back(ground);
  BodyDef box;
  box.shape = makeBox(1.0, 1.0);
  box.friction = 0.6;
  addPyramid(scene, rows, Vec2(1.0, 1.0), Vec2::Zero(), box);
  return scene;
}

double microseconds(Clock::duration duration) {
  return std::chrono::duration<double, std::micro>(duration).count();
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

/// µs of each of `count` calls of `work`.
std::vector<double> timesOf(int count, const std::function<void()>& work) {
  std::vector<double> times;
  for (int i = 0; i < count; ++i) {
    const Clock::time_point start = Clock::now();
    work();
    times.push_back(microseconds(Clock::now() - start));
  }
  return times;
}

double medianMicroseconds(int count, const std::function<void()>& work) {
  return median(timesOf(count, work));
}

/// The fastest call: on a shared machine the least disturbed one.
double fastestMicroseconds(int count, const std::function<void()>& work) {
  const std::vector<double> times = timesOf(count, work);
  return *std::min_element(times.begin(), times.end());
}

/// Median µs per step of the 20-row pyramid after it has settled.
double settledStepTime(bool sleeping) {
  auto world = buildWorld(pyramidScene("sequential", sleepRows, sleeping));
  const int settleSteps = int(std::lround(settleSeconds / world->settings().dt));
  for (int i = 0; i < settleSteps; ++i) world->step();
  std::printf("  sleeping = %-5s awake bodies after %.0f s: %d\n", sleeping ? "true" : "false",
              settleSeconds, world->lastStepStatistics().awakeBodies);
  return medianMicroseconds(timedSteps, [&] { world->step(); });
}

void sleepingRatio() {
  std::printf("1. settled %d-row pyramid, sequential impulses (default iterations)\n", sleepRows);
  const double awake = settledStepTime(false);
  const double asleep = settledStepTime(true);
  std::printf("  awake  %10.1f us/step (median of %d)\n", awake, timedSteps);
  std::printf("  asleep %10.1f us/step\n", asleep);
  std::printf("  ratio  %10.2f %%  (target <= 5 %%)\n", 100.0 * asleep / awake);
}

/// Least-squares slope of log y against log x.
double fittedExponent(const std::vector<double>& x, const std::vector<double>& y) {
  double meanX = 0.0, meanY = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    meanX += std::log(x[i]) / double(x.size());
    meanY += std::log(y[i]) / double(x.size());
  }
  double covariance = 0.0, variance = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    covariance += (std::log(x[i]) - meanX) * (std::log(y[i]) - meanY);
    variance += (std::log(x[i]) - meanX) * (std::log(x[i]) - meanX);
  }
  return covariance / variance;
}

void microExponent() {
  std::printf("2. micro-collision resolver on resting pyramids (awake, fastest of %d steps)\n",
              microTimedSteps);
  std::printf("  rows  points  impulses/step    ms/step  us/impulse\n");
  std::vector<double> points, impulses, times;
  for (int rows : microRows) {
    auto world = buildWorld(pyramidScene("micro", rows, false));
    for (int i = 0; i < microWarmUpSteps; ++i) world->step();
    double iterations = 0.0;
    const double time = fastestMicroseconds(microTimedSteps, [&] {
      world->step();
      iterations += world->solver().lastReport().iterations / double(microTimedSteps);
    });
    points.push_back(contactPointCount(*world));
    impulses.push_back(iterations);
    times.push_back(time);
    std::printf("  %4d  %6.0f  %13.0f  %9.2f  %10.3f\n", rows, points.back(), iterations,
                time / 1000.0, time / iterations);
  }
  std::printf("  fitted exponent: time ~ points^%.2f, impulses ~ points^%.2f\n",
              fittedExponent(points, times), fittedExponent(points, impulses));
}

void largePyramid() {
  auto world = buildWorld(pyramidScene("sequential", largeRows, false));
  world->step();
  std::printf("3. %zu-body pyramid, sequential impulses, awake\n", world->bodies().size());
  const double step = medianMicroseconds(largeTimedSteps, [&] { world->step(); });
  const double contacts = medianMicroseconds(largeTimedSteps, [&] { world->findContacts(); });
  std::printf("  step %.0f us, of which broad + narrow phase %.0f us (%.1f %%), %zu manifolds\n",
              step, contacts, 100.0 * contacts / step, world->manifolds().size());
}

}  // namespace

int main() {
  sleepingRatio();
  microExponent();
  largePyramid();
  return 0;
}
