// Narrow phase: the contact manifold of two shapes, by separating axes and clipping.
#pragma once

#include "impulse2d/body.h"
#include "impulse2d/contact.h"

namespace impulse2d {

/// Fills manifold.normal, pointCount and each point's position, anchors, penetration and feature
/// id for bodies a and b (indices already set by the caller), following the sign convention of
/// contact.h: the normal points from a to b. Points are kept while the surfaces are closer than
/// margin (penetration > −margin). Returns pointCount; 0 when they do not touch.
int collide(const Body& a, const Body& b, double margin, Manifold& manifold);

}  // namespace impulse2d
