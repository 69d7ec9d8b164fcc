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

/// m. How far the point stands outside the body: exact for a circle and in front of a polygon's
/// face, less than the distance beside a polygon's corner; < 0 inside.
double separationFromPoint(const Body& body, const Vec2& point);

/// m. A lower bound on the distance between the two bodies' surfaces, by separating axes: exact
/// for two circles and where a face is nearest, less beside corners; ≤ 0 when they overlap.
double separation(const Body& a, const Body& b);

/// Whether the manifold collide(a, b, …) found has a normal that runs to a circle's centre from
/// the other circle's centre or from a polygon's vertex: such a normal turns as the bodies move
/// past each other, where a face's normal only turns with its body.
bool normalRunsToCentre(const Shape& a, const Shape& b, const Manifold& manifold);

/// m. Between two polygons, B's face becomes the reference face only when it separates them by
/// more than A's face plus this much, so a box resting flat keeps the same reference face every
/// step instead of flip-flopping on round-off (Box2D: 0.1 × its linear slop of 0.005 m). Within
/// it the order of the arguments decides, so collide(a, b) and collide(b, a) may take their
/// normals from different bodies' faces.
constexpr double kReferenceFaceTolerance = 0.1 * 0.005;

}  // namespace impulse2d
