// The world's step: contacts, islands, velocities, the solver, positions, sleep (order in
// world.h).
#include "impulse2d/world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "impulse2d/collide.h"

namespace impulse2d {
namespace {

std::pair<int, int> keyOf(const Manifold& manifold) {
  return {manifold.bodyA, manifold.bodyB};
}

/// Impulses of the last step at points with the same feature id (warm starting).
void carryOverImpulses(const Manifold& previous, Manifold& manifold) {
  for (int i = 0; i < manifold.pointCount; ++i) {
    ContactPoint& point = manifold.points[i];
    for (int j = 0; j < previous.pointCount; ++j) {
      if (previous.points[j].id != point.id) continue;
      point.normalImpulse = previous.points[j].normalImpulse;
      point.tangentImpulse = previous.points[j].tangentImpulse;
      point.substepNormalImpulse = previous.points[j].substepNormalImpulse;
      point.substepTangentImpulse = previous.points[j].substepTangentImpulse;
      point.bounced = previous.points[j].bounced;
      point.exactState = previous.points[j].exactState;
      point.carried = true;
    }
  }
}

/// A sleeping body has zero velocity and no force: any it has now, the user gave it.
bool disturbed(const Body& body) {
  return body.velocity != Vec2::Zero() || body.angularVelocity != 0.0 ||
         body.force != Vec2::Zero() || body.torque != 0.0;
}

/// Freezes a body of a resting island: zero velocity, so its contacts stay as they are.
void fallAsleep(Body& body) {
  body.asleep = true;
  body.velocity.setZero();
  body.angularVelocity = 0.0;
  body.force.setZero();
  body.torque = 0.0;
}

// How far B may move before its manifold is found anew. Within the found distance a one-point
// manifold (a vertex or a circle on a face) is found anew before any point of B has moved as far
// as the distance it was found within, so a vertex that was not in it, such as the next vertex of
// a polygon pivoting on one, cannot have reached A's surface unseen. A two-point manifold holds
// both ends of an edge on the face: the next vertex of that polygon reaches the face only by
// turning through the exterior angle there (72° for a regular pentagon, 45° for an octagon),
// beyond the largest turn (11.5°) that finds it anew, so it keeps v3's recycle distance. Only a
// corner flatter than the largest turn, on an irregular polygon, could still land unseen.
double recycleDistance(const ContactRecycling& limits, const Manifold& old) {
  if (!limits.withinFoundDistance || old.pointCount == 2) return limits.distance;
  return std::min(limits.distance, old.found.distance);
}

// m. How far B's centre has moved relative to A's since the manifold was found: in A's frame (v3),
// or in the world's, where the recycled normal and arms are kept, so that a pair turning together
// by θ at a distance d counts as moving d θ.
double offsetMoved(const ContactRecycling& limits, const Body& a, const Body& b,
                   const FoundPose& found) {
  if (!limits.inWorldFrame) return (a.toLocal(b.position) - found.relativePosition).norm();
  return (b.position - a.position - rotation(found.angleA) * found.relativePosition).norm();
}

}  // namespace

World::World(const WorldSettings& settings, std::unique_ptr<ContactSolver> solver)
    : settings_(settings), solver_(std::move(solver)) {
  if (settings_.substeps < 1) throw std::invalid_argument("substeps must be at least 1");
}

int World::addBody(Body body) {
  body.updateCache();
  bodies_.push_back(std::move(body));
  sweepOrder_.push_back(int(bodies_.size()) - 1);
  return int(bodies_.size()) - 1;
}

void World::step() {
  const double h = settings_.dt / settings_.substeps;
  for (int i = 0; i < settings_.substeps; ++i) {
    applyLoads(double(stepCount_) * settings_.dt + i * h);
    substep(h);
  }
  ++stepCount_;
}

// Each substep's velocity update clears the forces, so loads are added again before each one.
void World::applyLoads(double time) {
  for (Body& body : bodies_) body.applyLoad(time);
}

void World::substep(double h) {
  statistics_ = StepStatistics{};
  wakeDisturbedBodies();
  if (std::none_of(bodies_.begin(), bodies_.end(), [](const Body& b) { return b.isAwake(); })) {
    // Nothing awake, nothing can move: the last manifolds are kept as they are, nothing is solved.
    statistics_.keptManifolds = int(manifolds_.size());
    return;
  }
  findContacts(h);
  wakeTouchedIslands();
  const bool solverMovesBodies = solver_->integratesBodies();
  if (!solverMovesBodies) integrateVelocities(h);
  stopAtNonFiniteBody();
  const StepContext context{bodies_, manifoldsToSolve(), h, observer_, settings_.gravity};
  solver_->solveVelocities(context);
  if (!solverMovesBodies) integratePositions(h);
  solver_->solvePositions(context);
  if (solverMovesBodies) {
    clearForces();
  } else {
    refreshCaches();
  }
  storeSolvedManifolds();
  stopAtNonFiniteBody();
  putRestingIslandsToSleep(h);
}

// Before the solver reads the velocities and after the substep: a load or mass beyond what a
// double holds stops the run at the first overflowed body, before any solver pivots on it.
void World::stopAtNonFiniteBody() const {
  impulse2d::stopAtNonFiniteBody(bodies_, settings_.gravity, stepCount_ + 1, solver_->name());
}

void World::wakeDisturbedBodies() {
  for (Body& body : bodies_) {
    if (body.asleep && disturbed(body)) body.wake();
  }
}

void World::findContacts() {
  statistics_ = StepStatistics{};
  findContacts(settings_.dt / settings_.substeps);
}

// Candidate pairs and the last substep's manifolds are both sorted by (A, B), so one merge walk
// keeps the manifolds of sleeping pairs and carries impulses over to the recomputed ones.
void World::findContacts(double h) {
  previousManifolds_.swap(manifolds_);
  manifolds_.clear();
  findCandidatePairs(h);
  ManifoldIterator old = previousManifolds_.cbegin();
  for (const BodyPair& pair : candidatePairs_) {
    old = keepSleepingManifolds(old, pair);
    const bool hadManifold = old != previousManifolds_.cend() && keyOf(*old) == pair;
    Manifold manifold;
    if (hadManifold && recycleManifold(*old, manifold)) {
      manifolds_.push_back(manifold);
      ++statistics_.recycledManifolds;
      continue;
    }
    if (!collidePair(pair, h, manifold)) continue;
    if (hadManifold) carryOverImpulses(*old, manifold);
    manifolds_.push_back(manifold);
  }
  keepSleepingManifolds(old, {int(bodies_.size()), 0});
}

// Old manifolds before `before`: those without an awake body are kept (their bodies have not
// moved, so the narrow phase would find them again); the rest are gone or recomputed.
World::ManifoldIterator World::keepSleepingManifolds(ManifoldIterator old, const BodyPair& before) {
  for (; old != previousManifolds_.cend() && keyOf(*old) < before; ++old) {
    if (involvesAwakeBody(*old)) continue;
    manifolds_.push_back(*old);
    ++statistics_.keptManifolds;
  }
  return old;
}

bool World::collidePair(const BodyPair& pair, double h, Manifold& manifold) {
  const Body& a = bodies_[pair.first];
  const Body& b = bodies_[pair.second];
  ++statistics_.narrowPhasePairs;
  manifold.bodyA = pair.first;
  manifold.bodyB = pair.second;
  const double distance = contactDistance(a, b, h);
  if (collide(a, b, distance, manifold) == 0) return false;
  manifold.found = {a.angle, b.angle, a.toLocal(b.position), distance};
  manifold.friction = mixFriction(a.friction, b.friction);
  manifold.restitution = mixRestitution(a.restitution, b.restitution);
  return true;
}

// Contact recycling (Box2D v3), when the solver asks for it: while neither body has turned more
// than the largest turn since the manifold was found, and B's centre has moved less than the
// recycle distance in A's frame (plus what the pair's relative turn moves a point at the
// farther-reaching dynamic body's largest extent), the manifold is kept with its normal, ids,
// impulses and arms as found; only each point's overlap follows how far the bodies moved since,
// the arms turned with them (a circle's not, with roundSurfaces), as a soft step's substeps
// measure it. A normal that runs to a circle's centre turns as the bodies move past each other,
// so the solver may ask to find such manifolds anew every step (renewRoundNormals; v3 keeps them).
bool World::recycleManifold(const Manifold& old, Manifold& manifold) const {
  const ContactRecycling limits = solver_->contactRecycling();
  if (limits.distance <= 0.0 || old.pointCount == 0) return false;
  const Body& a = bodies_[size_t(old.bodyA)];
  const Body& b = bodies_[size_t(old.bodyB)];
  if (limits.renewRoundNormals && normalRunsToCentre(a.shape, b.shape, old)) return false;
  const double turnA = a.angle - old.found.angleA;
  const double turnB = b.angle - old.found.angleB;
  if (std::abs(turnA) > limits.largestTurn || std::abs(turnB) > limits.largestTurn) return false;
  const double reach =
      std::max(a.isStatic() ? 0.0 : maxExtent(a.shape), b.isStatic() ? 0.0 : maxExtent(b.shape));
  const double moved =
      offsetMoved(limits, a, b, old.found) + reach * std::abs(std::sin(turnB - turnA));
  if (moved >= recycleDistance(limits, old)) return false;
  manifold = old;
  const auto armTurn = [&limits](const Body& body, double turn) {
    return !limits.roundSurfaces || surfaceTurnsWithShape(body.shape) ? turn : 0.0;
  };
  const Mat2 turnOfA = rotation(armTurn(a, turnA));
  const Mat2 turnOfB = rotation(armTurn(b, turnB));
  for (int i = 0; i < manifold.pointCount; ++i) {
    ContactPoint& point = manifold.points[size_t(i)];
    const Vec2 onA = a.position + turnOfA * point.foundArmA;
    const Vec2 onB = b.position + turnOfB * point.foundArmB;
    point.penetration = point.foundPenetration - (onB - onA).dot(manifold.normal);
    point.point = contactPointBetween(onA, onB);
    point.carried = true;
  }
  return true;
}

// Speculative contacts, by the world's setting or the solver's wish.
bool World::speculativeContacts() const {
  return settings_.speculativeContacts || solver_->wantsSpeculativeContacts();
}

// Speculative contacts: the gap the pair can close within the substep is added to the margin.
double World::contactDistance(const Body& a, const Body& b, double h) const {
  if (!speculativeContacts()) return settings_.contactMargin;
  return settings_.contactMargin + (b.velocity - a.velocity).norm() * h;
}

bool World::involvesAwakeBody(const Manifold& manifold) const {
  return bodies_[manifold.bodyA].isAwake() || bodies_[manifold.bodyB].isAwake();
}

// Sort and sweep along x: bodies sorted by the left edge of their bounds, each paired with the
// ones whose left edge lies before its right edge, then the y extents compared. Pairs without an
// awake body (two static, sleeping, or one of each) are skipped. Pairs come out sorted by (A, B).
void World::findCandidatePairs(double h) {
  computeSweepBounds(h);
  sortSweepOrder();
  layOutSweep();
  const double margin = settings_.contactMargin;
  candidatePairs_.clear();
  for (size_t i = 0; i < sweep_.size(); ++i) {
    const SweepEntry& first = sweep_[i];
    for (size_t j = i + 1; j < sweep_.size(); ++j) {
      const SweepEntry& second = sweep_[j];
      if (second.bounds.lower.x() > first.bounds.upper.x() + margin) break;
      if (second.bounds.lower.y() > first.bounds.upper.y() + margin ||
          first.bounds.lower.y() > second.bounds.upper.y() + margin) {
        continue;
      }
      if (!first.awake && !second.awake) continue;
      candidatePairs_.emplace_back(std::min(first.body, second.body),
                                   std::max(first.body, second.body));
    }
  }
  std::sort(candidatePairs_.begin(), candidatePairs_.end());
}

// Each body's bounds, grown by the distance it covers in the substep when contacts are
// speculative.
void World::computeSweepBounds(double h) {
  sweepBounds_.resize(bodies_.size());
  const bool speculative = speculativeContacts();
  for (size_t i = 0; i < bodies_.size(); ++i) {
    const Body& body = bodies_[i];
    const double reach = speculative ? body.velocity.norm() * h : 0.0;
    sweepBounds_[i] = {body.bounds.lower - Vec2(reach, reach),
                       body.bounds.upper + Vec2(reach, reach)};
  }
}

// Insertion sort by left edge: nearly linear, because the order hardly changes between steps.
void World::sortSweepOrder() {
  auto left = [this](int i) { return sweepBounds_[i].lower.x(); };
  for (size_t i = 1; i < sweepOrder_.size(); ++i) {
    const int body = sweepOrder_[i];
    size_t j = i;
    for (; j > 0 && left(sweepOrder_[j - 1]) > left(body); --j) sweepOrder_[j] = sweepOrder_[j - 1];
    sweepOrder_[j] = body;
  }
}

// The bodies' bounds and awake flags copied in sweep order: the sweep's inner loop then reads
// one contiguous array instead of jumping between bodies.
void World::layOutSweep() {
  sweep_.resize(sweepOrder_.size());
  for (size_t i = 0; i < sweepOrder_.size(); ++i) {
    const int body = sweepOrder_[i];
    sweep_[i] = {sweepBounds_[body], body, bodies_[body].isAwake()};
  }
}

// Islands by union-find: every contact between two dynamic bodies joins their islands. Static
// bodies join none, so a floor does not make the whole scene one island.
void World::buildIslands() {
  islandParent_.resize(bodies_.size());
  std::iota(islandParent_.begin(), islandParent_.end(), 0);
  for (const Manifold& manifold : manifolds_) {
    if (bodies_[manifold.bodyA].isStatic() || bodies_[manifold.bodyB].isStatic()) continue;
    islandParent_[islandOf(manifold.bodyA)] = islandOf(manifold.bodyB);
  }
}

/// The root of the body's island (path halving keeps the trees flat).
int World::islandOf(int body) {
  while (islandParent_[body] != body) {
    islandParent_[body] = islandParent_[islandParent_[body]];
    body = islandParent_[body];
  }
  return body;
}

// An awake body touching a sleeping one wakes the sleeper's whole island, so the island is
// solved as one again, with the manifolds it kept as warm-start data.
void World::wakeTouchedIslands() {
  if (!settings_.sleeping) return;
  buildIslands();
  islandAwake_.assign(bodies_.size(), 0);
  for (int i = 0; i < int(bodies_.size()); ++i) {
    if (bodies_[i].isAwake()) islandAwake_[islandOf(i)] = 1;
  }
  for (int i = 0; i < int(bodies_.size()); ++i) {
    if (bodies_[i].asleep && islandAwake_[islandOf(i)]) bodies_[i].wake();
  }
}

void World::integrateVelocities(double h) {
  for (Body& body : bodies_) {
    if (!body.isAwake()) continue;
    ++statistics_.awakeBodies;
    body.lastAcceleration = settings_.gravity + body.inverseMass * body.force;
    body.velocity += h * body.lastAcceleration;
    body.angularVelocity += h * body.inverseInertia * body.torque;
    body.force.setZero();
    body.torque = 0.0;
  }
}

// After a solver that moved the bodies itself (it used the forces in its substeps).
void World::clearForces() {
  for (Body& body : bodies_) {
    if (!body.isAwake()) continue;
    ++statistics_.awakeBodies;
    body.force.setZero();
    body.torque = 0.0;
  }
}

// All manifolds when none was kept asleep (then every one has an awake body); otherwise a copy
// of those with an awake body, written back after the solve.
std::vector<Manifold>& World::manifoldsToSolve() {
  solvedIndex_.clear();
  if (statistics_.keptManifolds == 0) {
    statistics_.solvedManifolds = int(manifolds_.size());
    return manifolds_;
  }
  solverManifolds_.clear();
  for (int i = 0; i < int(manifolds_.size()); ++i) {
    if (!involvesAwakeBody(manifolds_[i])) continue;
    solverManifolds_.push_back(manifolds_[i]);
    solvedIndex_.push_back(i);
  }
  statistics_.solvedManifolds = int(solverManifolds_.size());
  return solverManifolds_;
}

void World::storeSolvedManifolds() {
  for (size_t k = 0; k < solvedIndex_.size(); ++k) {
    manifolds_[solvedIndex_[k]] = solverManifolds_[k];
  }
}

void World::integratePositions(double h) {
  for (Body& body : bodies_) {
    if (!body.isAwake()) continue;
    body.position += h * body.velocity;
    body.angle += h * body.angularVelocity;
    body.updateRotation();
  }
}

// Once per substep, after the position pass: the rotation exact from the angle again, and the
// bounds the next broad phase sweeps with (the solvers move bodies without updating them).
void World::refreshCaches() {
  for (Body& body : bodies_) {
    if (body.isAwake()) body.updateCache();
  }
}

// An island sleeps when its most restless body has rested for timeToSleep (Box2D's rule): one
// moving body keeps the whole island awake.
void World::putRestingIslandsToSleep(double h) {
  if (!settings_.sleeping) return;
  islandRested_.assign(bodies_.size(), std::numeric_limits<double>::infinity());
  for (int i = 0; i < int(bodies_.size()); ++i) {
    if (!bodies_[i].isAwake()) continue;
    updateSleepTime(bodies_[i], h);
    double& rested = islandRested_[islandOf(i)];
    rested = std::min(rested, bodies_[i].sleepTime);
  }
  for (int i = 0; i < int(bodies_.size()); ++i) {
    if (bodies_[i].isAwake() && islandRested_[islandOf(i)] >= settings_.timeToSleep) {
      fallAsleep(bodies_[i]);
    }
  }
}

// A body rests while it is slower than the thresholds and, with keepSpeedingUpAwake, has not sped
// up by speedUpShare of them since its rest began; a body that has begins its rest again.
void World::updateSleepTime(Body& body, double h) const {
  const double speed = body.velocity.norm();
  const double spin = std::abs(body.angularVelocity);
  if (speed >= settings_.sleepLinearSpeed || spin >= settings_.sleepAngularSpeed) {
    body.sleepTime = 0.0;
    return;
  }
  const double share = settings_.speedUpShare;
  const bool speedingUp = settings_.keepSpeedingUpAwake &&
                          (speed - body.restSpeed > share * settings_.sleepLinearSpeed ||
                           spin - body.restSpin > share * settings_.sleepAngularSpeed);
  if (body.sleepTime == 0.0 || speedingUp) {
    body.sleepTime = 0.0;
    body.restSpeed = speed;
    body.restSpin = spin;
  }
  body.sleepTime += h;
}

}  // namespace impulse2d
