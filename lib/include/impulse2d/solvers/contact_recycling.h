// Contact recycling (Box2D v3): a pair's manifold is kept from one step to the next,
// its normal, ids, impulses and arms as found, while its bodies move little; only each point's
// overlap follows how far they moved. What that needs of a manifold, where its bodies and points
// were when it was found, is kept here, beside the world's manifolds, not in them.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "impulse2d/shared_settings.h"
#include "impulse2d/solver.h"

namespace impulse2d {

/// Where two bodies were when the narrow phase found their manifold.
struct FoundPose {
  double angleA = 0.0;                   ///< rad
  double angleB = 0.0;                   ///< rad
  Mat2 rotationA = Mat2::Identity();     ///< A's rotation then, so turns need no trigonometry
  Mat2 rotationB = Mat2::Identity();     ///< B's rotation then
  Vec2 relativePosition = Vec2::Zero();  ///< m: B's centre in A's body frame
  double distance = 0.0;                 ///< m: the contact distance the points were found within
  double reach = 0.0;  ///< m: the larger extent of the pair's dynamic bodies (maxExtent)
};

/// A contact point as the narrow phase found it, world frame.
struct FoundPoint {
  Vec2 armA = Vec2::Zero();  ///< m: from A's centre to the point
  Vec2 armB = Vec2::Zero();  ///< m: from B's centre to the point
  double penetration = 0.0;  ///< m, along the normal
};

/// A pair's manifold as it was found: its bodies' pose then and its points' arms. A recycled
/// manifold keeps the one it was found with.
struct FoundManifold {
  int bodyA = -1;                    ///< index into the world's bodies
  int bodyB = -1;                    ///< index into the world's bodies
  FoundPose pose;                    ///< the bodies' pose when the points were found
  std::array<FoundPoint, 2> points;  ///< in the manifold's order
};

/// Decides which manifolds a method keeps (soft step, sequential impulses), and remembers how each
/// of the world's manifolds was found. The world asks it pair by pair, in the order of its
/// manifolds (by bodyA, then bodyB).
class ContactRecycling : public ManifoldKeeping {
 public:
  /// Recycling as `settings` ask. With `roundSurfaces` (soft step's) a circle's arm stays as found
  /// while the circle turns, its contact following its centre; otherwise every arm turns with its
  /// body.
  ContactRecycling(const RecyclingSettings& settings, bool roundSurfaces)
      : settings_(settings), roundSurfaces_(roundSurfaces) {}

  void startFinding() override;
  /// Keeps `previous` while its bodies have moved little since it was found
  /// (docs/contact-generation.md).
  bool keep(const Manifold& previous, const std::vector<Body>& bodies, Manifold& kept) override;
  void found(const Manifold& manifold, const std::vector<Body>& bodies, double distance) override;

  /// Whether a manifold like this one may be kept at all: recycling is on, and its normal is not
  /// one that is found anew every step (RecyclingRule::Refined). One that may not was found this
  /// step.
  bool mayKeep(const Manifold& manifold, const std::vector<Body>& bodies) const;
  /// How the world's manifold of that pair was found (null if it was found without this), from
  /// the last call of startFinding on. A caller walking the manifolds in the world's order passes
  /// the same `from` (first 0) to each call, and each search starts there.
  const FoundManifold* foundManifold(const Manifold& manifold, std::size_t& from) const;

 private:
  /// Whether the body's arms turn with it: every body's, except a circle's with roundSurfaces.
  bool armTurns(const Body& body) const;
  /// Whether our rules beyond v3's apply (RecyclingRule::Refined).
  bool refined() const { return settings_.rule == RecyclingRule::Refined; }
  /// The record of `previous`, found in the last substep's records; the records passed on the way
  /// that the world keeps (their bodies all sleep) are carried over as they are.
  const FoundManifold* recordOf(const Manifold& previous, const std::vector<Body>& bodies);
  bool movedLittle(const FoundManifold& found, const Manifold& previous, const Body& a,
                   const Body& b) const;
  double recycleDistance(const FoundManifold& found, const Manifold& previous) const;
  double offsetMoved(const Body& a, const Body& b, const FoundPose& found) const;

  RecyclingSettings settings_;
  bool roundSurfaces_;
  std::vector<FoundManifold> previous_;  ///< the last substep's records, by (bodyA, bodyB)
  std::size_t next_ = 0;                 ///< the first of previous_ not yet passed
  std::vector<FoundManifold> records_;   ///< this substep's, by (bodyA, bodyB)
};

}  // namespace impulse2d
