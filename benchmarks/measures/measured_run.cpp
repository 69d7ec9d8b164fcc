// Runs measured step by step (measured_run.h).
#include "measured_run.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "impulse2d/box2d/box2d_simulation.h"

using namespace impulse2d;
using Clock = std::chrono::steady_clock;

namespace benchmarks {

namespace {

double mechanicalEnergy(const Simulation& simulation) {
  return kineticEnergy(simulation) + potentialEnergy(simulation);
}

/// The upward contact force on each body (N): the vertical part of every normal and friction
/// impulse pushing it up, divided by the step.
std::vector<double> supportForces(const Simulation& simulation) {
  std::vector<double> support(simulation.bodies().size(), 0.0);
  const double dt = simulation.settings().dt;
  for (const Manifold& manifold : simulation.manifolds()) {
    Vec2 impulseOnB = Vec2::Zero();
    for (int i = 0; i < manifold.pointCount; ++i) {
      const ContactPoint& point = manifold.points[i];
      impulseOnB +=
          point.normalImpulse * manifold.normal + point.tangentImpulse * manifold.tangent();
    }
    support[manifold.bodyB] += std::max(0.0, impulseOnB.y()) / dt;
    support[manifold.bodyA] += std::max(0.0, -impulseOnB.y()) / dt;
  }
  return support;
}

/// The weight (N) each body carries in a resting column: its own and that of every dynamic body
/// at its height or above (static bodies carry nothing here). One sort by height, then the
/// masses summed from the top down, so a large scene costs n log n between steps, not n².
std::vector<double> weightsCarried(const Simulation& simulation) {
  const std::vector<Body>& bodies = simulation.bodies();
  std::vector<int> byHeight;
  for (int i = 0; i < static_cast<int>(bodies.size()); ++i) {
    if (!bodies[i].isStatic()) byHeight.push_back(i);
  }
  std::sort(byHeight.begin(), byHeight.end(),
            [&bodies](int a, int b) { return bodies[a].position.y() > bodies[b].position.y(); });
  std::vector<double> weights(bodies.size(), 0.0);
  const double gravity = std::abs(simulation.settings().gravity.y());
  double massAbove = 0.0;
  for (std::size_t first = 0; first < byHeight.size();) {
    // Bodies at one height carry each other: the whole level's mass counts for each.
    std::size_t last = first;
    const double height = bodies[byHeight[first]].position.y();
    while (last < byHeight.size() && bodies[byHeight[last]].position.y() == height) {
      massAbove += bodies[byHeight[last++]].mass;
    }
    for (; first < last; ++first) weights[byHeight[first]] = massAbove * gravity;
  }
  return weights;
}

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

}  // namespace

MeasuredRun::MeasuredRun(const Scene& scene, const RunPlan& plan)
    : plan_(plan),
      settledStep_(std::lround(plan.settledTime / scene.world.dt)),
      simulation_(makeSimulation(scene)) {
  if (settledStep_ == 0) recordSettledState();
}

bool MeasuredRun::done() const {
  const bool overBudget =
      plan_.timeBudget > 0.0 && std::chrono::duration<double>(spent_).count() > plan_.timeBudget;
  return simulation_->stepCount() >= plan_.steps || overBudget;
}

void MeasuredRun::step() {
  if (done()) return;
  const Clock::time_point start = Clock::now();
  simulation_->step();
  const Clock::duration elapsed = Clock::now() - start;
  spent_ += elapsed;
  const long step = simulation_->stepCount();
  if (step > plan_.warmupSteps) {
    const double whole = std::chrono::duration<double, std::micro>(elapsed).count();
    const auto* box2d = dynamic_cast<const Box2dSimulation*>(simulation_.get());
    stepMicroseconds_.push_back(box2d ? box2d->engineStepMicroseconds() : whole);
    wholeStepMicroseconds_.push_back(whole);
  }
  if (step == settledStep_) recordSettledState();
  if (step > settledStep_) measureSettledStep();
}

void MeasuredRun::recordSettledState() {
  settledPositions_.clear();
  for (const Body& body : simulation_->bodies()) settledPositions_.push_back(body.position);
  settledEnergy_ = mechanicalEnergy(*simulation_);
}

void MeasuredRun::measureSettledStep() {
  const std::vector<Body>& bodies = simulation_->bodies();
  for (size_t i = 0; i < bodies.size(); ++i) {
    drift_ = std::max(drift_, (bodies[i].position - settledPositions_[i]).norm());
  }
  largestPenetration_ = std::max(largestPenetration_, largestPenetration(*simulation_));
  energyGain_ = std::max(energyGain_, mechanicalEnergy(*simulation_) - settledEnergy_);
  forceErrorSquaredSum_ += stackForceErrorSquared();
  ++settledSteps_;
}

double MeasuredRun::stackForceErrorSquared() const {
  const std::vector<double> support = supportForces(*simulation_);
  const std::vector<double> weights = weightsCarried(*simulation_);
  double sum = 0.0;
  int count = 0;
  for (size_t i = 0; i < support.size(); ++i) {
    const Body& body = simulation_->bodies()[i];
    if (body.isStatic()) continue;
    const double weight = weights[i];
    sum += std::pow((support[i] - weight) / weight, 2);
    ++count;
  }
  return count > 0 ? sum / count : 0.0;
}

RunFigures MeasuredRun::figures() const {
  const double notMeasured = std::numeric_limits<double>::quiet_NaN();
  const bool settled = settledSteps_ > 0;
  RunFigures figures;
  figures.stepsRun = simulation_->stepCount();
  figures.completed = figures.stepsRun >= plan_.steps;
  figures.medianMicroseconds = stepMicroseconds_.empty() ? notMeasured : median(stepMicroseconds_);
  figures.meanMicroseconds =
      stepMicroseconds_.empty()
          ? notMeasured
          : std::accumulate(stepMicroseconds_.begin(), stepMicroseconds_.end(), 0.0) /
                double(stepMicroseconds_.size());
  figures.medianWholeStepMicroseconds =
      wholeStepMicroseconds_.empty() ? notMeasured : median(wholeStepMicroseconds_);
  figures.drift = settled ? drift_ : notMeasured;
  figures.largestPenetration = settled ? largestPenetration_ : notMeasured;
  figures.energyGain = settled ? energyGain_ : notMeasured;
  figures.stackForceError =
      settled ? std::sqrt(forceErrorSquaredSum_ / settledSteps_) : notMeasured;
  figures.contactPoints = contactPointCount(*simulation_);
  return figures;
}

void runSideBySide(std::vector<MeasuredRun>& runs) {
  const auto allDone = [&runs] {
    return std::all_of(runs.begin(), runs.end(), [](const MeasuredRun& run) { return run.done(); });
  };
  while (!allDone()) {
    for (MeasuredRun& run : runs) run.step();
  }
}

std::string runToEnd(MeasuredRun& run) {
  try {
    while (!run.done()) run.step();
  } catch (const std::runtime_error& stopped) {
    return stopped.what();
  }
  return "";
}

}  // namespace benchmarks
