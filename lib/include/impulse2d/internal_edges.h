// Internal edges: where a surface is made of several static pieces laid flush, the faces and
// corners where two pieces meet are inside the surface, and a contact on one of them is refused.
#pragma once

#include <vector>

#include "impulse2d/body.h"
#include "impulse2d/contact.h"

namespace impulse2d {

/// m. A contact point lies on a neighbour's face when it is this close to it: pieces laid flush
/// to within this much meet at an internal edge (Box2D's 0.1 × linear slop, as
/// kReferenceFaceTolerance).
constexpr double kFlushDistance = 0.1 * 0.005;

/// rad. Two faces are flush (anti-parallel, or in line) when their normals differ by less than
/// this; round-off in a piece's angle stays far below it.
constexpr double kFlushAngle = 1e-3;

/// Removes the points of a manifold between a static polygon and another body that a flush
/// static neighbour (a body of `staticBodies`, indices into `bodies`) makes internal, and returns
/// how many remain:
///  - a point on a face the neighbour covers: the neighbour has a face through the point whose
///    normal is the contact normal turned round (the side face of a floor tile, pressed against
///    the next tile, that a sliding box's corner catches);
///  - a point at a corner whose normal is none of the polygon's face normals, where a face of the
///    neighbour through the corner rises in front of the contact plane (the corner where two
///    flush tiles meet, whose slanted normal makes a rolling disc hop).
/// The same surface without the seam gives the moving body the contacts the other piece finds.
int dropInternalEdgePoints(const std::vector<Body>& bodies, const std::vector<int>& staticBodies,
                           Manifold& manifold);

}  // namespace impulse2d
