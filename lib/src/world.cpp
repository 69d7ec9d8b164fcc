// The world's step: contacts, velocities, the solver, positions (order in world.h).
#include "impulse2d/world.h"

#include <algorithm>

#include "impulse2d/collide.h"

namespace impulse2d {

World::World(const WorldSettings& settings, std::unique_ptr<ContactSolver> solver)
    : settings_(settings), solver_(std::move(solver)) {}

int World::addBody(Body body) {
  body.updateCache();
  bodies_.push_back(std::move(body));
  sweepOrder_.push_back(int(bodies_.size()) - 1);
  return int(bodies_.size()) - 1;
}

void World::step() {
  findContacts();
  integrateVelocities();
  const StepContext context{bodies_, manifolds_, settings_.dt, observer_};
  solver_->solveVelocities(context);
  integratePositions();
  solver_->solvePositions(context);
  ++stepCount_;
}

void World::findContacts() {
  previousManifolds_.swap(manifolds_);
  manifolds_.clear();
  findCandidatePairs();
  for (const auto& [a, b] : candidatePairs_) {
    Manifold manifold;
    manifold.bodyA = a;
    manifold.bodyB = b;
    if (collide(bodies_[a], bodies_[b], settings_.contactMargin, manifold) == 0) continue;
    manifold.friction = mixFriction(bodies_[a].friction, bodies_[b].friction);
    manifold.restitution = mixRestitution(bodies_[a].restitution, bodies_[b].restitution);
    manifolds_.push_back(manifold);
  }
  carryOverImpulses(previousManifolds_);
}

// Sort and sweep along x: bodies sorted by the left edge of their bounds (insertion sort, nearly
// linear because the order hardly changes between steps); each body is paired with the ones whose
// left edge lies before its right edge, then the y extents are compared. Pairs of two static
// bodies are skipped. Pairs come out sorted by (A, B), so impulses carry over by a merge walk.
void World::findCandidatePairs() {
  const double margin = settings_.contactMargin;
  auto left = [this](int i) { return bodies_[i].bounds.lower.x(); };
  for (size_t i = 1; i < sweepOrder_.size(); ++i) {
    const int body = sweepOrder_[i];
    size_t j = i;
    for (; j > 0 && left(sweepOrder_[j - 1]) > left(body); --j) sweepOrder_[j] = sweepOrder_[j - 1];
    sweepOrder_[j] = body;
  }
  candidatePairs_.clear();
  for (size_t i = 0; i < sweepOrder_.size(); ++i) {
    const Body& first = bodies_[sweepOrder_[i]];
    for (size_t j = i + 1; j < sweepOrder_.size(); ++j) {
      const Body& second = bodies_[sweepOrder_[j]];
      if (second.bounds.lower.x() > first.bounds.upper.x() + margin) break;
      if (first.isStatic() && second.isStatic()) continue;
      if (second.bounds.lower.y() > first.bounds.upper.y() + margin ||
          first.bounds.lower.y() > second.bounds.upper.y() + margin) {
        continue;
      }
      candidatePairs_.emplace_back(std::min(sweepOrder_[i], sweepOrder_[j]),
                                   std::max(sweepOrder_[i], sweepOrder_[j]));
    }
  }
  std::sort(candidatePairs_.begin(), candidatePairs_.end());
}

void World::carryOverImpulses(std::vector<Manifold>& previous) {
  auto key = [](const Manifold& m) { return std::make_pair(m.bodyA, m.bodyB); };
  auto old = previous.begin();
  for (Manifold& manifold : manifolds_) {
    while (old != previous.end() && key(*old) < key(manifold)) ++old;
    if (old == previous.end() || key(*old) != key(manifold)) continue;
    for (int i = 0; i < manifold.pointCount; ++i) {
      ContactPoint& point = manifold.points[i];
      for (int j = 0; j < old->pointCount; ++j) {
        if (old->points[j].id != point.id) continue;
        point.normalImpulse = old->points[j].normalImpulse;
        point.tangentImpulse = old->points[j].tangentImpulse;
      }
    }
  }
}

void World::integrateVelocities() {
  for (Body& body : bodies_) {
    if (body.isStatic()) continue;
    body.lastAcceleration = settings_.gravity + body.inverseMass * body.force;
    body.velocity += settings_.dt * body.lastAcceleration;
    body.angularVelocity += settings_.dt * body.inverseInertia * body.torque;
    body.force.setZero();
    body.torque = 0.0;
  }
}

void World::integratePositions() {
  for (Body& body : bodies_) {
    if (body.isStatic()) continue;
    body.position += settings_.dt * body.velocity;
    body.angle += settings_.dt * body.angularVelocity;
    body.updateCache();
  }
}

}  // namespace impulse2d
