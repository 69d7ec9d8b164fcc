// Contact recycling: which manifolds are kept, and how each was found.
#include "impulse2d/solvers/contact_recycling.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "impulse2d/collide.h"

namespace impulse2d {
namespace {

/// Records and manifolds are ordered by their two bodies: A, then B.
template <class T>
std::uint64_t pairOf(const T& recordOrManifold) {
  return std::uint64_t(std::uint32_t(recordOrManifold.bodyA)) << 32 |
         std::uint32_t(recordOrManifold.bodyB);
}

/// The rotation a body has turned through since its rotation was `then`, from its cached rotation.
Mat2 turnSinceFound(const Body& body, const Mat2& then) {
  return body.rotation * then.transpose();
}

}  // namespace

// The records of the last substep's pairs that the world did not look at (their bodies sleep, or
// they were passed after the last pair it looked at) stay for the substeps that wake them. A
// record is read only for a manifold the world kept or found, so one left from a pair that fell
// apart is never read, and goes once a body of its pair is awake.
void ContactRecycling::startFinding() {
  records_.insert(records_.end(), previous_.begin() + std::ptrdiff_t(next_), previous_.end());
  previous_.swap(records_);
  records_.clear();
  next_ = 0;
}

const FoundManifold* ContactRecycling::recordOf(const Manifold& previous,
                                                const std::vector<Body>& bodies) {
  for (; next_ < previous_.size() && pairOf(previous_[next_]) < pairOf(previous); ++next_) {
    const FoundManifold& passed = previous_[next_];
    if (!bodies[passed.bodyA].isAwake() && !bodies[passed.bodyB].isAwake()) {
      records_.push_back(passed);
    }
  }
  if (next_ < previous_.size() && pairOf(previous_[next_]) == pairOf(previous)) {
    return &previous_[next_++];
  }
  return nullptr;
}

// While neither body has turned more than the largest turn since the manifold was found, and B's
// centre has moved less than the recycle distance in A's frame (plus what the pair's relative turn
// moves a point at the farther-reaching dynamic body's largest extent), the manifold is kept with
// its normal, ids, impulses and arms as found; only each point's overlap follows how far the
// bodies moved since, the arms turned with them, as the substeps measure it. With roundSurfaces a
// circle's arm does not turn: its contact follows its centre, and its surface anchor (which the
// position pass reads) is put back where the kept normal meets its surface. A normal that runs to
// a circle's centre turns as the bodies move past each other, so such manifolds may be found anew
// every step (RecyclingRule::Refined; v3 keeps them).
bool ContactRecycling::keep(const Manifold& previous, const std::vector<Body>& bodies,
                            Manifold& kept) {
  const FoundManifold* found = recordOf(previous, bodies);
  if (!found || !mayKeep(previous, bodies)) return false;
  const Body& a = bodies[previous.bodyA];
  const Body& b = bodies[previous.bodyB];
  if (!movedLittle(*found, previous, a, b)) return false;
  const Mat2 turnOfA =
      armTurns(a) ? turnSinceFound(a, found->pose.rotationA) : Mat2(Mat2::Identity());
  const Mat2 turnOfB =
      armTurns(b) ? turnSinceFound(b, found->pose.rotationB) : Mat2(Mat2::Identity());
  kept = previous;
  for (int i = 0; i < kept.pointCount; ++i) {
    ContactPoint& point = kept.points[i];
    const FoundPoint& foundPoint = found->points[i];
    const Vec2 onA = a.position + turnOfA * foundPoint.armA;
    const Vec2 onB = b.position + turnOfB * foundPoint.armB;
    point.penetration = foundPoint.penetration - (onB - onA).dot(kept.normal);
    point.point = contactPointBetween(onA, onB);
    point.carried = true;
    if (!armTurns(a)) point.anchorA = a.toLocal(a.position + a.shape.radius * kept.normal);
    if (!armTurns(b)) point.anchorB = b.toLocal(b.position - b.shape.radius * kept.normal);
  }
  records_.push_back(*found);
  return true;
}

bool ContactRecycling::armTurns(const Body& body) const {
  return !roundSurfaces_ || surfaceTurnsWithShape(body.shape);
}

bool ContactRecycling::mayKeep(const Manifold& manifold, const std::vector<Body>& bodies) const {
  if (settings_.rule == RecyclingRule::Off || settings_.distance <= 0.0 ||
      manifold.pointCount == 0) {
    return false;
  }
  const Shape& a = bodies[manifold.bodyA].shape;
  const Shape& b = bodies[manifold.bodyB].shape;
  return !refined() || !normalRunsToCentre(a, b, manifold);
}

// The turns are taken from the angles, not the rotations: a rotation is the cos and sin of the
// angle, which C libraries round differently in the last bit, and a keep decision that read them
// would go otherwise in the browser than in i2d. A circle's turn counts too, though its arm does
// not turn: kept while it spins, a heap of discs settled worse (docs/design/
// sequential-impulses-speed.md). The relative turn θ moves a point at the reach by at most
// reach·|θ|.
bool ContactRecycling::movedLittle(const FoundManifold& found, const Manifold& previous,
                                   const Body& a, const Body& b) const {
  const double turnA = a.angle - found.pose.angleA;
  const double turnB = b.angle - found.pose.angleB;
  const double largestTurn = settings_.largestTurn;
  if (std::abs(turnA) > largestTurn || std::abs(turnB) > largestTurn) return false;
  const double moved = offsetMoved(a, b, found.pose) + found.pose.reach * std::abs(turnB - turnA);
  return moved < recycleDistance(found, previous);
}

// How far B may move before its manifold is found anew. Within the found distance a one-point
// manifold (a vertex or a circle on a face) is found anew before any point of B has moved as far
// as the distance it was found within, so a vertex that was not in it, such as the next vertex of
// a polygon pivoting on one, cannot have reached A's surface unseen. A two-point manifold holds
// both ends of an edge on the face: the next vertex of that polygon reaches the face only by
// turning through the exterior angle there (72° for a regular pentagon, 45° for an octagon),
// beyond the largest turn (11.5°) that finds it anew, so it keeps v3's recycle distance. Only a
// corner flatter than the largest turn, on an irregular polygon, could still land unseen.
double ContactRecycling::recycleDistance(const FoundManifold& found,
                                         const Manifold& previous) const {
  if (!refined() || previous.pointCount == 2) {
    return settings_.distance;
  }
  return std::min(settings_.distance, found.pose.distance);
}

// m. How far B's centre has moved relative to A's since the manifold was found: in A's frame (v3),
// or in the world's, where the recycled normal and arms are kept, so that a pair turning together
// by θ at a distance d counts as moving d θ.
double ContactRecycling::offsetMoved(const Body& a, const Body& b, const FoundPose& found) const {
  if (!refined()) {
    return (a.toLocal(b.position) - found.relativePosition).norm();
  }
  return (b.position - a.position - found.rotationA * found.relativePosition).norm();
}

// The bodies are where the narrow phase just found the manifold. One that may not be kept needs
// no record: its points are where they were found.
void ContactRecycling::found(const Manifold& manifold, const std::vector<Body>& bodies,
                             double distance) {
  if (!mayKeep(manifold, bodies)) return;
  recordOf(manifold, bodies);
  const Body& a = bodies[manifold.bodyA];
  const Body& b = bodies[manifold.bodyB];
  const double reach =
      std::max(a.isStatic() ? 0.0 : maxExtent(a.shape), b.isStatic() ? 0.0 : maxExtent(b.shape));
  const auto asFound = [&](int i) {
    const ContactPoint& point = manifold.points[i];
    return FoundPoint{point.point - a.position, point.point - b.position, point.penetration};
  };
  records_.push_back(
      {manifold.bodyA,
       manifold.bodyB,
       {a.angle, b.angle, a.rotation, b.rotation, a.toLocal(b.position), distance, reach},
       {asFound(0), manifold.pointCount > 1 ? asFound(1) : FoundPoint{}}});
}

const FoundManifold* ContactRecycling::foundManifold(const Manifold& manifold,
                                                     std::size_t& from) const {
  while (from < records_.size() && pairOf(records_[from]) < pairOf(manifold)) ++from;
  if (from < records_.size() && pairOf(records_[from]) == pairOf(manifold)) return &records_[from];
  // A pair kept asleep after the last pair the world looked at, woken since.
  const auto rest = previous_.begin() + std::ptrdiff_t(next_);
  const auto record =
      std::lower_bound(rest, previous_.end(), pairOf(manifold),
                       [](const FoundManifold& r, std::uint64_t pair) { return pairOf(r) < pair; });
  return record != previous_.end() && pairOf(*record) == pairOf(manifold) ? &*record : nullptr;
}

}  // namespace impulse2d
