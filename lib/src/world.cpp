// The world's step: contacts, islands, velocities, the solver, positions, sleep (order in
// world.h).
#include "impulse2d/world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "impulse2d/collide.h"
#include "impulse2d/continuous.h"
#include "impulse2d/internal_edges.h"

namespace impulse2d {
namespace {

std::pair<int, int> keyOf(const Manifold& manifold) {
  return {manifold.bodyA, manifold.bodyB};
}

/// Impulses of the last step at points with the same feature id (warm starting).
void carryOverImpulses(const Manifold& previous, Manifold& manifold) {
  for (int i = 0; i < manifold.pointCount; ++i) {
    ContactPoint& point = manifold.points[i];
    const int j = previous.pointMadeBy(point.id);
    if (j < 0) continue;
    point.normalImpulse = previous.points[j].normalImpulse;
    point.tangentImpulse = previous.points[j].tangentImpulse;
    point.carried = true;
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

}  // namespace

// The shared stages of a substep of length h, as the solver's step calls them.
class World::WorldStages : public StepStages {
 public:
  WorldStages(World& world, double h) : world_(world), h_(h) {}
  StepContext findContacts(const ContactFinding& finding) override {
    world_.findContacts(h_, finding);
    world_.wakeTouchedIslands();
    return {world_.bodies_, world_.manifoldsToSolve(), h_, world_.observer_,
            world_.settings_.gravity};
  }
  void integrateVelocities() override {
    world_.integrateVelocities(h_);
    if (world_.observer_) world_.observer_->onVelocitiesChanged(world_.bodies_);
  }
  void integratePositions() override { world_.integratePositions(h_); }
  void clearForces() override { world_.clearForces(); }
  void refreshCaches() override { world_.refreshCaches(); }
  void stopAtNonFiniteBody() override { world_.stopAtNonFiniteBody(); }
  void storeImpulses() override { world_.storeSolvedManifolds(); }

 private:
  World& world_;
  double h_;
};

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
  rememberStartPoses();
  WorldStages stages(*this, h);
  solver_->step(stages);
  if (settings_.continuous) {
    stopAtTimeOfImpact(bodies_, startPoses_, staticBodies_, 0.5 * settings_.contactMargin);
  }
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

void World::findContacts(const ContactFinding& finding) {
  statistics_ = StepStatistics{};
  findContacts(settings_.dt / settings_.substeps, finding);
}

// Candidate pairs and the last substep's manifolds are both sorted by (A, B), so one merge walk
// keeps the manifolds of sleeping pairs and carries impulses over to the recomputed ones. Each
// pair's manifold is made in place at the end of the list, and taken back if it has no contact.
void World::findContacts(double h, const ContactFinding& finding) {
  finding_ = finding;
  previousManifolds_.swap(manifolds_);
  manifolds_.clear();
  findCandidatePairs(h);
  listStaticBodies();
  ManifoldIterator old = previousManifolds_.cbegin();
  if (finding.keeping) finding.keeping->startFinding();
  for (const BodyPair& pair : candidatePairs_) {
    old = keepSleepingManifolds(old, pair);
    const bool hadManifold = old != previousManifolds_.cend() && keyOf(*old) == pair;
    Manifold& manifold = manifolds_.emplace_back();
    if (hadManifold && finding.keeping && finding.keeping->keep(*old, bodies_, manifold)) {
      ++statistics_.reusedManifolds;
      continue;
    }
    if (!collidePair(pair, h, manifold)) {
      manifolds_.pop_back();
      continue;
    }
    if (hadManifold) carryOverImpulses(*old, manifold);
    if (finding.keeping) {
      finding.keeping->found(manifold, bodies_,
                             contactDistance(bodies_[pair.first], bodies_[pair.second], h));
    }
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
  // Only a contact with a static body can lie on an internal edge.
  const bool onStaticBody = a.isStatic() || b.isStatic();
  if (settings_.refuseInternalEdges && onStaticBody &&
      dropInternalEdgePoints(bodies_, staticBodies_, manifold) == 0) {
    return false;
  }
  manifold.friction = mixFriction(a.friction, b.friction);
  manifold.restitution = mixRestitution(a.restitution, b.restitution);
  return true;
}

// Where each body starts the substep, for continuous collision.
void World::rememberStartPoses() {
  if (!settings_.continuous) return;
  startPoses_.resize(bodies_.size());
  for (size_t i = 0; i < bodies_.size(); ++i) {
    startPoses_[i] = {bodies_[i].position, bodies_[i].angle};
  }
}

// The static bodies a contact on one of them may meet a flush neighbour among (internal edges).
void World::listStaticBodies() {
  staticBodies_.clear();
  for (int i = 0; i < int(bodies_.size()); ++i) {
    if (bodies_[i].isStatic()) staticBodies_.push_back(i);
  }
}

// Speculative contacts, by the world's setting or because the method finds its contacts ahead.
bool World::speculativeContacts() const {
  return settings_.speculativeContacts || finding_.ahead;
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
  candidatePairs_.clear();
  const size_t count = sweep_.size();
  for (size_t i = 0; i < count; ++i) {
    const SweepEntry& first = sweep_[i];
    for (size_t j = i + 1; j < count; ++j) {
      if (sweepLeft_[j] > first.reachRight) break;
      const SweepEntry& second = sweep_[j];
      if (second.bottom > first.reachTop || first.bottom > second.reachTop) continue;
      if (!first.awake && !second.awake) continue;
      candidatePairs_.emplace_back(std::min(first.body, second.body),
                                   std::max(first.body, second.body));
    }
  }
  sortCandidatePairs();
}

// The candidate pairs by (A, B), in time linear in their number: a radix sort, placed by B and
// then, keeping that order, by A (two counting sorts).
void World::sortCandidatePairs() {
  placeCandidatePairs(&BodyPair::second);
  placeCandidatePairs(&BodyPair::first);
}

// One counting sort of the candidate pairs by one of their bodies, keeping the order of pairs with
// the same body: counted, where each body's pairs start, then placed.
void World::placeCandidatePairs(int BodyPair::*body) {
  pairsStart_.assign(bodies_.size() + 1, 0);
  for (const BodyPair& pair : candidatePairs_) ++pairsStart_[pair.*body + 1];
  for (size_t i = 1; i < pairsStart_.size(); ++i) pairsStart_[i] += pairsStart_[i - 1];
  sortedPairs_.resize(candidatePairs_.size());
  for (const BodyPair& pair : candidatePairs_) sortedPairs_[pairsStart_[pair.*body]++] = pair;
  candidatePairs_.swap(sortedPairs_);
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

// The bodies' bounds, their upper edges grown by the contact margin, and awake flags copied in
// sweep order: the sweep's inner loop then reads contiguous arrays instead of jumping between
// bodies, and the left edges it stops at lie apart, eight to a cache line.
void World::layOutSweep() {
  const double margin = settings_.contactMargin;
  sweep_.resize(sweepOrder_.size());
  sweepLeft_.resize(sweepOrder_.size());
  for (size_t i = 0; i < sweepOrder_.size(); ++i) {
    const int body = sweepOrder_[i];
    const Aabb& bounds = sweepBounds_[body];
    sweepLeft_[i] = bounds.lower.x();
    sweep_[i] = {bounds.upper.x() + margin, bounds.lower.y(), bounds.upper.y() + margin, body,
                 bodies_[body].isAwake()};
  }
}

// Islands by union-find: every contact between two dynamic bodies joins their islands. Static
// bodies join none, so a floor does not make the whole scene one island.
void World::buildIslands() {
  islands_.reset(static_cast<int>(bodies_.size()));
  for (const Manifold& manifold : manifolds_) {
    if (bodies_[manifold.bodyA].isStatic() || bodies_[manifold.bodyB].isStatic()) continue;
    islands_.join(manifold.bodyA, manifold.bodyB);
  }
}

/// The root of the body's island.
int World::islandOf(int body) {
  return islands_.root(body);
}

// An awake body touching a sleeping one wakes the sleeper's whole island, so the island is
// solved as one again, with the manifolds it kept as warm-start data.
void World::wakeTouchedIslands() {
  if (settings_.sleep == Sleep::Off) return;
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
    body.integrateVelocity(settings_.gravity, h);
  }
}

// After a solver that moved the bodies itself (it used the forces in its own integration).
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
  if (settings_.sleep == Sleep::Off) return;
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

// A body rests while it is slower than the thresholds and, with Sleep::KeepSpeedingUpAwake, has not
// sped up by speedUpShare of them since its rest began; a body that has begins its rest again.
void World::updateSleepTime(Body& body, double h) const {
  const double speed = body.velocity.norm();
  const double spin = std::abs(body.angularVelocity);
  if (speed >= settings_.sleepLinearSpeed || spin >= settings_.sleepAngularSpeed) {
    body.sleepTime = 0.0;
    return;
  }
  const double share = settings_.speedUpShare;
  const bool speedingUp = settings_.sleep == Sleep::KeepSpeedingUpAwake &&
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
