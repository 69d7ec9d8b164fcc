// The figures of stress runs (probes.h).
#include "probes.h"

#include <algorithm>
#include <cmath>

#include "impulse2d/box2d/box2d_simulation.h"

namespace impulse2d::stress {

void DisplacementProbe::observe(const Simulation& simulation) {
  if (simulation.stepCount() < from_) return;
  const std::vector<Body>& bodies = simulation.bodies();
  if (start_.empty()) {
    for (const Body& body : bodies) start_.push_back(body.position);
  }
  for (size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].isStatic()) continue;
    largest_ = std::max(largest_, (bodies[i].position - start_[i]).norm());
  }
}

void PenetrationProbe::observe(const Simulation& simulation) {
  if (simulation.stepCount() < from_) return;
  deepest_ = std::max(deepest_, largestPenetration(simulation));
}

void PlaceProbe::observe(const Simulation& simulation) {
  largest_ = 0.0;
  size_t next = 0;
  for (const Body& body : simulation.bodies()) {
    if (body.isStatic()) continue;
    largest_ = std::max(largest_, std::abs(body.position.x() - places_[next++].x()));
  }
}

void EnergyRiseProbe::observe(const Simulation& simulation) {
  if (simulation.stepCount() < from_) return;
  const double energy = kineticEnergy(simulation) + potentialEnergy(simulation);
  if (!started_) {
    started_ = true;
    start_ = energy;
    for (const Body& body : simulation.bodies()) {
      weight_ += body.mass * simulation.settings().gravity.norm();
    }
  }
  largest_ = std::max(largest_, (energy - start_) / weight_);
}

void WallProbe::observe(const Simulation& simulation) {
  largest_ = std::max(largest_, simulation.bodies()[ball_].position.x() - wallX_);
}

void CradleProbe::observe(const Simulation& simulation) {
  lastSpeed_ = simulation.bodies()[last_].velocity.x();
}

void RiseProbe::observe(const Simulation& simulation) {
  if (simulation.stepCount() < from_) return;
  const std::vector<Body>& bodies = simulation.bodies();
  if (heights_.empty()) {
    for (int body : bodies_) heights_.push_back(bodies[body].position.y());
  }
  for (size_t i = 0; i < bodies_.size(); ++i) {
    largest_ = std::max(largest_, bodies[bodies_[i]].position.y() - heights_[i]);
  }
}

namespace {

Scene movedBy(Scene scene, const Vec2& offset) {
  for (BodyDef& body : scene.bodies) body.position += offset;
  return scene;
}

}  // namespace

TwinProbe::TwinProbe(const Scene& scene, const Vec2& offset)
    : twin_(makeSimulation(movedBy(scene, -offset))), offset_(offset) {}

TwinProbe::~TwinProbe() = default;

void TwinProbe::observe(const Simulation& simulation) {
  while (twin_->stepCount() < simulation.stepCount()) twin_->step();
  const std::vector<Body>& bodies = simulation.bodies();
  for (size_t i = 0; i < bodies.size(); ++i) {
    const Vec2 moved = bodies[i].position - offset_;
    largest_ = std::max(largest_, (moved - twin_->bodies()[i].position).norm());
  }
}

}  // namespace impulse2d::stress
