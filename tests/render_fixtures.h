// Small fixtures for the rendering tests: a Simulation with bodies and contacts set by hand, so
// frames can be tested without any solver, and a fresh scratch directory per test.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "impulse2d/simulation.h"

namespace impulse2d::test {

/// A simulation that holds still: step() only counts, and reports `events` to an observer as a
/// solver would, so traces can be tested without one.
class FixedSimulation : public Simulation {
 public:
  std::vector<Body> bodyList;
  std::vector<Manifold> manifoldList;
  std::vector<SolverEvent> events;
  WorldSettings worldSettings;
  long steps = 0;

  void step() override {
    if (observer_ != nullptr) {
      for (const SolverEvent& event : events) {
        observer_->onSolverEvent(event, bodyList, manifoldList);
      }
    }
    ++steps;
  }
  const std::vector<Body>& bodies() const override { return bodyList; }
  const std::vector<Manifold>& manifolds() const override { return manifoldList; }
  std::string solverName() const override { return "fixed"; }
  const WorldSettings& settings() const override { return worldSettings; }
  long stepCount() const override { return steps; }
  void setObserver(SolverObserver* observer) override { observer_ = observer; }

 private:
  SolverObserver* observer_ = nullptr;
};

/// A 1 m box (density 1: 1 kg) resting on a static ground, their contact with two points.
inline FixedSimulation boxOnGround() {
  FixedSimulation simulation;
  simulation.bodyList.push_back(
      makeBody("ground", BodyType::Static, makeBox(10.0, 1.0), 1.0, Vec2(0.0, -0.5), 0.0));
  simulation.bodyList.push_back(
      makeBody("box", BodyType::Dynamic, makeBox(1.0, 1.0), 1.0, Vec2(0.0, 0.5), 0.0));
  Manifold manifold;
  manifold.bodyA = 0;
  manifold.bodyB = 1;
  manifold.pointCount = 2;
  for (int i = 0; i < 2; ++i) {
    manifold.points[i].point = Vec2(i == 0 ? -0.5 : 0.5, 0.0);
    manifold.points[i].normalImpulse = 0.08;
    manifold.points[i].friction = FrictionState::Static;
  }
  simulation.manifoldList.push_back(manifold);
  return simulation;
}

/// An empty directory under the build tree for one test, emptied if it exists.
inline std::filesystem::path scratchDirectory(const std::string& name) {
  const std::filesystem::path path =
      std::filesystem::path(IMPULSE2D_BINARY_DIR) / "render_test_output" / name;
  std::filesystem::remove_all(path);
  std::filesystem::create_directories(path);
  return path;
}

}  // namespace impulse2d::test
