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
    largest_ = std::max(largest_, std::abs(bodies[i].position.x() - start_[i].x()));
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

namespace impulse2d::stress {

void StructureWatch::observe(const Simulation& simulation) {
  const std::vector<Body>& bodies = simulation.bodies();
  const double energy = kineticEnergy(simulation) + potentialEnergy(simulation);
  if (start_.empty()) {
    for (size_t i = 0; i < bodies.size(); ++i) {
      start_.push_back(bodies[i].position);
      weight_ += bodies[i].mass * simulation.settings().gravity.norm();
      const bool higher = bodies[i].position.y() > bodies[top_].position.y();
      if (!bodies[i].isStatic() && (bodies[top_].isStatic() || higher)) top_ = i;
    }
  }
  const Vec2 topMoved = bodies[top_].position - start_[top_];
  figures_.sway = std::max(figures_.sway, std::abs(topMoved.x()));
  figures_.sink = std::max(figures_.sink, -topMoved.y());
  double displacement = 0.0;
  for (size_t i = 0; i < bodies.size(); ++i) {
    if (!bodies[i].isStatic())
      displacement = std::max(displacement, std::abs(bodies[i].position.x() - start_[i].x()));
  }
  displacement_ = windowStarted_ ? std::max(displacement_, displacement) : displacement;
  energy_ = windowStarted_ ? std::max(energy_, energy / weight_) : energy / weight_;
  windowStarted_ = true;
  ended_ = simulation.stepCount() > 0 && simulation.stepCount() % window_ == 0;
  if (ended_) endWindow(double(window_) * simulation.settings().dt);
}

void StructureWatch::endWindow(double seconds) {
  if (windows_ >= 2) {
    const double growth = displacement_ - largestDisplacement_;
    figures_.creep = std::max(0.0, growth) / seconds;
    figures_.drift = displacement_;
    figures_.bounded =
        growth <= kDisplacementTolerance && energy_ - largestEnergy_ <= kEnergyTolerance;
  }
  if (windows_ >= 1) {
    largestDisplacement_ = std::max(largestDisplacement_, displacement_);
    largestEnergy_ = windows_ == 1 ? energy_ : std::max(largestEnergy_, energy_);
  }
  ++windows_;
  windowStarted_ = false;
}

}  // namespace impulse2d::stress
