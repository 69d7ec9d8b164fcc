// Continuous collision against static bodies: a body that would pass deep into a static body
// within one substep is stopped where it reaches it (the time of impact), so a small fast body
// cannot tunnel through a thin wall between two steps.
#pragma once

#include <vector>

#include "impulse2d/body.h"

namespace impulse2d {

/// Where a body was at the start of a substep.
struct Pose {
  Vec2 position = Vec2::Zero();  ///< m
  double angle = 0.0;            ///< rad
};

/// Share of a body's smallest extent (a circle's radius, a polygon's nearest face from its
/// centre) that is its core: a substep whose motion would carry the core into a static body is
/// cut at the time of impact (Box2D v3's fallback core is a quarter; half catches a body before
/// its centre passes the middle of a wall as thin as the body).
constexpr double kCoreShare = 0.5;

/// Conservative advancement stops once the surfaces are within the target gap or after this
/// many advances, at a time the bodies do not yet overlap.
constexpr int kMaxAdvances = 30;

/// For each awake dynamic body: if moving linearly from `start` (its pose when the substep
/// began) to its pose now would carry its core into a static body (indices in `staticBodies`),
/// it is moved back to the first pose of that motion at which its surface is within `targetGap`
/// of that body, or where its core touches it if it was already that close at the start. Its
/// velocity is kept, so the next step's contact (found within the contact margin) stops it.
/// Returns how many bodies were moved back.
int stopAtTimeOfImpact(std::vector<Body>& bodies, const std::vector<Pose>& start,
                       const std::vector<int>& staticBodies, double targetGap);

}  // namespace impulse2d
