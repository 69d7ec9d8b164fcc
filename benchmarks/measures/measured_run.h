// One simulation run with its cost and accuracy measured step by step: the time of every step
// after warm-up, the settled drift, the largest penetration, the energy gained at rest and, for a
// stack, the error of the contact forces. Several runs can be stepped in turn (one step of each),
// so every run sees the same load from the other programs on the machine.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "impulse2d/scene/scene.h"
#include "impulse2d/simulation.h"

namespace benchmarks {

/// How long to run and from when the figures count.
struct RunPlan {
  long steps = 600;
  /// Steps whose time is not counted: contacts appear and warm starts fill in.
  long warmupSteps = 10;
  /// s. Drift, penetration, energy gain and force error count from this time on, once the scene
  /// has settled (settledTime() of benchmark_scenes.h).
  double settledTime = 1.0;
  /// s. The run stops early once it has spent this much (0: no limit); the figures then cover
  /// the steps taken, and completed() says so.
  double timeBudget = 0.0;
};

/// What a run measured. Figures that need the settled part of a run are NaN without one.
struct RunFigures {
  long stepsRun = 0;
  bool completed = false;  ///< ran plan.steps (not stopped by the time budget)
  /// µs per step, after warm-up; NaN if no step was timed. For Box2D, the time inside
  /// b2World::Step alone (Box2dSimulation::engineStepMicroseconds), so its cost is not inflated
  /// by the adapter that converts its bodies and contacts into ours.
  double medianMicroseconds = 0.0;
  /// µs per step, the mean over the same steps: what a whole run costs a step. A method whose
  /// steps differ in cost (sequential impulses sweep until converged) has a mean above its median.
  double meanMicroseconds = 0.0;
  /// µs per step of the whole Simulation::step() call, adapter included; for our own methods
  /// the same as medianMicroseconds.
  double medianWholeStepMicroseconds = 0.0;
  double drift = 0.0;               ///< m, largest displacement of a body since settledTime
  double largestPenetration = 0.0;  ///< m, deepest contact since settledTime
  double energyGain = 0.0;  ///< J, largest rise of kinetic + potential energy since settledTime
  /// Root mean square over the settled steps and the dynamic bodies of (support − weight) /
  /// weight, support being the upward contact force on a body from below and weight that of the
  /// body and every body above it: the contact-force error of a resting column.
  double stackForceError = 0.0;
  int contactPoints = 0;  ///< in the last step
};

class MeasuredRun {
 public:
  MeasuredRun(const impulse2d::Scene& scene, const RunPlan& plan);

  /// Steps once and updates the figures; does nothing once done().
  void step();
  bool done() const;
  RunFigures figures() const;
  const impulse2d::Simulation& simulation() const { return *simulation_; }

 private:
  void recordSettledState();
  void measureSettledStep();
  double stackForceErrorSquared() const;

  RunPlan plan_;
  long settledStep_;
  std::unique_ptr<impulse2d::Simulation> simulation_;
  std::chrono::steady_clock::duration spent_{};
  std::vector<double> stepMicroseconds_;
  std::vector<double> wholeStepMicroseconds_;
  std::vector<impulse2d::Vec2> settledPositions_;
  double settledEnergy_ = 0.0;
  double drift_ = 0.0;
  double largestPenetration_ = 0.0;
  double energyGain_ = 0.0;
  double forceErrorSquaredSum_ = 0.0;
  long settledSteps_ = 0;
};

/// Steps every run in turn, one step each, until all are done.
void runSideBySide(std::vector<MeasuredRun>& runs);

/// Steps the run until it is done. Returns why the method stopped it (a step it could not solve,
/// as the reference reports), or an empty string when it ran to its end.
std::string runToEnd(MeasuredRun& run);

}  // namespace benchmarks
