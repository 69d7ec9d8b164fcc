// The narrow phase: where two shapes touch. Circles meet along the line of their centres; a
// circle meets a polygon at the polygon's closest face or vertex; two polygons are tested by
// separating axes (SAT) and their contact points found by clipping the incident edge against the
// side planes of the reference face (the Box2D-Lite / Box2D 2.4 method). The sign convention is
// the one of contact.h: the normal points from A to B and penetration > 0 means overlap.
#include "impulse2d/collide.h"

#include <algorithm>
#include <array>
#include <limits>

namespace impulse2d {
namespace {

/// m. Circle centres closer than this are coincident: their direction is undefined, so the
/// normal falls back to +y.
constexpr double kCoincidentCentres = 1e-12;

/// Which feature of the polygon a circle touches: inside a face's region or a vertex's.
enum class CircleRegion { Face = 0, Vertex = 1 };

/// The feature id of a circle against a polygon: the polygon's face or vertex it touches.
FeatureId circleRegionId(int feature, CircleRegion region) {
  return makeFeatureId(feature, static_cast<int>(region));
}

/// The region a circle's feature id names: its second feature, the high half of makeFeatureId.
CircleRegion circleRegionOf(FeatureId id) {
  return static_cast<CircleRegion>(id >> 16);
}

int nextVertex(const Shape& polygon, int index) {
  return (index + 1) % static_cast<int>(polygon.vertices.size());
}

int noContact(Manifold& manifold) {
  manifold.pointCount = 0;
  return 0;
}

/// A contact point from the points on A's and B's surfaces (world): impulses act at
/// contactPointBetween (contact.h).
ContactPoint contactPoint(const Body& a, const Body& b, const Vec2& onA, const Vec2& onB,
                          double penetration, FeatureId id) {
  ContactPoint point;
  point.point = contactPointBetween(onA, onB);
  point.anchorA = a.toLocal(onA);
  point.anchorB = b.toLocal(onB);
  point.penetration = penetration;
  point.id = id;
  return point;
}

int collideCircles(const Body& a, const Body& b, double margin, Manifold& manifold) {
  const Vec2 between = b.position - a.position;
  const double distance = between.norm();
  const Vec2 normal = distance > kCoincidentCentres ? Vec2(between / distance) : Vec2(0.0, 1.0);
  const double penetration = a.shape.radius + b.shape.radius - distance;
  if (penetration <= -margin) return noContact(manifold);
  manifold.normal = normal;
  manifold.points[0] = contactPoint(a, b, a.position + a.shape.radius * normal,
                                    b.position - b.shape.radius * normal, penetration, 0);
  manifold.pointCount = 1;
  return 1;
}

/// How far a face of a polygon lets a point (or a whole shape) stand out in front of it.
struct FaceSeparation {
  int face = 0;
  double separation = -std::numeric_limits<double>::infinity();
};

/// The face whose plane the body-frame point stands furthest in front of.
FaceSeparation deepestFaceToPoint(const Shape& polygon, const Vec2& point) {
  FaceSeparation best;
  for (int i = 0; i < static_cast<int>(polygon.vertices.size()); ++i) {
    const double separation = polygon.normals[i].dot(point - polygon.vertices[i]);
    if (separation > best.separation) best = {i, separation};
  }
  return best;
}

/// The closest feature of a polygon to a circle centre, in the polygon's frame.
struct ClosestFeature {
  Vec2 normal;      ///< unit, from the polygon towards the centre
  Vec2 surface;     ///< the point on the polygon's surface
  double distance;  ///< of the centre from the surface along normal; < 0 inside
  FeatureId id;
};

/// Voronoi regions of the face the centre stands furthest in front of: past either end of that
/// face the closest feature is the vertex, otherwise the face (also when the centre is inside).
ClosestFeature closestFeature(const Shape& polygon, const Vec2& centre) {
  const FaceSeparation face = deepestFaceToPoint(polygon, centre);
  const int first = face.face;
  const int second = nextVertex(polygon, first);
  const Vec2& v1 = polygon.vertices[first];
  const Vec2& v2 = polygon.vertices[second];
  if (face.separation > 0.0 && (centre - v1).dot(v2 - v1) <= 0.0) {
    return {(centre - v1).normalized(), v1, (centre - v1).norm(),
            circleRegionId(first, CircleRegion::Vertex)};
  }
  if (face.separation > 0.0 && (centre - v2).dot(v1 - v2) <= 0.0) {
    return {(centre - v2).normalized(), v2, (centre - v2).norm(),
            circleRegionId(second, CircleRegion::Vertex)};
  }
  const Vec2& normal = polygon.normals[first];
  return {normal, centre - face.separation * normal, face.separation,
          circleRegionId(first, CircleRegion::Face)};
}

/// A polygon and a circle in either order: polygonIsA says which body is A, so the normal can be
/// turned to point from A to B.
int collidePolygonAndCircle(const Body& polygon, const Body& circle, bool polygonIsA, double margin,
                            Manifold& manifold) {
  const ClosestFeature closest = closestFeature(polygon.shape, polygon.toLocal(circle.position));
  const double penetration = circle.shape.radius - closest.distance;
  if (penetration <= -margin) return noContact(manifold);
  const Vec2 towardsCircle = polygon.rotation * closest.normal;
  const Vec2 onPolygon = polygon.toWorld(closest.surface);
  const Vec2 onCircle = circle.position - circle.shape.radius * towardsCircle;
  manifold.normal = polygonIsA ? towardsCircle : Vec2(-towardsCircle);
  manifold.points[0] =
      polygonIsA ? contactPoint(polygon, circle, onPolygon, onCircle, penetration, closest.id)
                 : contactPoint(circle, polygon, onCircle, onPolygon, penetration, closest.id);
  manifold.pointCount = 1;
  return 1;
}

/// SAT: the face of `reference` that separates `other` most. Its separation is the deepest
/// vertex of `other` below the face plane; > 0 means that face is a separating axis.
FaceSeparation findMaxSeparation(const Body& reference, const Body& other) {
  const Mat2 referenceToOther = other.rotation.transpose() * reference.rotation;
  const Vec2 referenceOrigin = other.toLocal(reference.position);
  FaceSeparation best;
  const Shape& polygon = reference.shape;
  for (int i = 0; i < static_cast<int>(polygon.vertices.size()); ++i) {
    const Vec2 normal = referenceToOther * polygon.normals[i];
    const Vec2 faceVertex = referenceOrigin + referenceToOther * polygon.vertices[i];
    double deepest = std::numeric_limits<double>::infinity();
    for (const Vec2& vertex : other.shape.vertices) {
      deepest = std::min(deepest, normal.dot(vertex - faceVertex));
    }
    if (deepest > best.separation) best = {i, deepest};
  }
  return best;
}

/// The reference face in world coordinates: from start to end, with its outward normal.
struct ReferenceFace {
  Vec2 start;
  Vec2 end;
  Vec2 normal;
  Vec2 tangent;  ///< unit, from start to end
};

ReferenceFace referenceFace(const Body& body, int face) {
  const Vec2 start = body.toWorld(body.shape.vertices[face]);
  const Vec2 end = body.toWorld(body.shape.vertices[nextVertex(body.shape, face)]);
  return {start, end, body.rotation * body.shape.normals[face], (end - start).normalized()};
}

/// The edge of the incident body facing the reference face: its normal is the most
/// anti-parallel to the reference normal.
int incidentEdge(const Body& incident, const Vec2& referenceNormal) {
  const Vec2 localNormal = incident.rotation.transpose() * referenceNormal;
  int best = 0;
  double mostOpposed = std::numeric_limits<double>::infinity();
  for (int i = 0; i < static_cast<int>(incident.shape.normals.size()); ++i) {
    const double alignment = incident.shape.normals[i].dot(localNormal);
    if (alignment < mostOpposed) {
      mostOpposed = alignment;
      best = i;
    }
  }
  return best;
}

/// The incident edge while it is clipped: its two ends, in world coordinates.
using ClipSegment = std::array<Vec2, 2>;

ClipSegment incidentSegment(const Body& incident, int edge) {
  return {incident.toWorld(incident.shape.vertices[edge]),
          incident.toWorld(incident.shape.vertices[nextVertex(incident.shape, edge)])};
}

/// Sutherland–Hodgman against one line: keeps the part of the segment where normal·x ≤ offset;
/// a cut end is replaced by the crossing point. Returns how many points remain (0, 1 or 2).
int clipSegmentToLine(const ClipSegment& in, const Vec2& normal, double offset, ClipSegment& out) {
  const double distance0 = normal.dot(in[0]) - offset;
  const double distance1 = normal.dot(in[1]) - offset;
  int count = 0;
  if (distance0 <= 0.0) out[count++] = in[0];
  if (distance1 <= 0.0) out[count++] = in[1];
  if (distance0 * distance1 < 0.0) {
    out[count++] = in[0] + distance0 / (distance0 - distance1) * (in[1] - in[0]);
  }
  return count;
}

/// Cuts the incident edge to the slab between the reference face's two side planes. False when
/// less than a segment survives (the edges only graze the side of the reference face).
bool clipToSidePlanes(const ClipSegment& incident, const ReferenceFace& face, ClipSegment& out) {
  ClipSegment behindStart;
  if (clipSegmentToLine(incident, -face.tangent, -face.tangent.dot(face.start), behindStart) < 2) {
    return false;
  }
  return clipSegmentToLine(behindStart, face.tangent, face.tangent.dot(face.end), out) == 2;
}

/// The feature ids of the two clipped points: the vertices of the two polygons at each end of the
/// contact. The incident edge runs against the reference face, so the point nearer the face's
/// start pairs the face's start vertex with the incident edge's end vertex, and the other the
/// face's end with the incident start. Written as (vertex of A, vertex of B), an id is the same
/// whichever polygon gave the reference face, so a flip of the reference keeps the warm start.
std::array<FeatureId, 2> clippedPointIds(const ClipSegment& clipped, const ReferenceFace& face,
                                         const Body& reference, int referenceEdge,
                                         const Body& incident, int edge, bool flipped) {
  const auto id = [&](int onReference, int onIncident) {
    return flipped ? makeFeatureId(onIncident, onReference)
                   : makeFeatureId(onReference, onIncident);
  };
  const FeatureId nearStart = id(referenceEdge, nextVertex(incident.shape, edge));
  const FeatureId nearEnd = id(nextVertex(reference.shape, referenceEdge), edge);
  const bool firstNearStart = face.tangent.dot(clipped[1] - clipped[0]) >= 0.0;
  return firstNearStart ? std::array<FeatureId, 2>{nearStart, nearEnd}
                        : std::array<FeatureId, 2>{nearEnd, nearStart};
}

/// Two polygons: SAT on both bodies' faces, the reference face chosen with a tolerance that
/// favours A, then the incident edge clipped; points deeper than −margin are kept.
int collidePolygons(const Body& a, const Body& b, double margin, Manifold& manifold) {
  const FaceSeparation faceA = findMaxSeparation(a, b);
  if (faceA.separation >= margin) return noContact(manifold);
  const FaceSeparation faceB = findMaxSeparation(b, a);
  if (faceB.separation >= margin) return noContact(manifold);

  const bool flipped = faceB.separation > faceA.separation + kReferenceFaceTolerance;
  const Body& reference = flipped ? b : a;
  const Body& incident = flipped ? a : b;
  const int referenceEdge = flipped ? faceB.face : faceA.face;
  const ReferenceFace face = referenceFace(reference, referenceEdge);
  const int edge = incidentEdge(incident, face.normal);
  ClipSegment clipped;
  if (!clipToSidePlanes(incidentSegment(incident, edge), face, clipped)) {
    return noContact(manifold);
  }

  manifold.normal = flipped ? Vec2(-face.normal) : face.normal;
  const std::array<FeatureId, 2> ids =
      clippedPointIds(clipped, face, reference, referenceEdge, incident, edge, flipped);
  int count = 0;
  for (int which = 0; which < 2; ++which) {
    const Vec2& onIncident = clipped[which];
    const double separation = face.normal.dot(onIncident - face.start);
    if (separation >= margin) continue;
    const Vec2 onReference = onIncident - separation * face.normal;
    const FeatureId id = ids[size_t(which)];
    manifold.points[count++] = flipped
                                   ? contactPoint(a, b, onIncident, onReference, -separation, id)
                                   : contactPoint(a, b, onReference, onIncident, -separation, id);
  }
  manifold.pointCount = count;
  return count;
}

}  // namespace

bool normalRunsToCentre(const Shape& a, const Shape& b, const Manifold& manifold) {
  const bool circleA = a.type == ShapeType::Circle;
  const bool circleB = b.type == ShapeType::Circle;
  if (circleA && circleB) return true;
  if (circleA == circleB || manifold.pointCount != 1) return false;
  return circleRegionOf(manifold.points[0].id) == CircleRegion::Vertex;
}

double separationFromPoint(const Body& body, const Vec2& point) {
  if (body.shape.type == ShapeType::Circle) {
    return (point - body.position).norm() - body.shape.radius;
  }
  return deepestFaceToPoint(body.shape, body.toLocal(point)).separation;
}

double separation(const Body& a, const Body& b) {
  const bool circleA = a.shape.type == ShapeType::Circle;
  const bool circleB = b.shape.type == ShapeType::Circle;
  if (circleB) return separationFromPoint(a, b.position) - b.shape.radius;
  if (circleA) return separationFromPoint(b, a.position) - a.shape.radius;
  return std::max(findMaxSeparation(a, b).separation, findMaxSeparation(b, a).separation);
}

int collide(const Body& a, const Body& b, double margin, Manifold& manifold) {
  const bool circleA = a.shape.type == ShapeType::Circle;
  const bool circleB = b.shape.type == ShapeType::Circle;
  if (circleA && circleB) return collideCircles(a, b, margin, manifold);
  if (!circleA && !circleB) return collidePolygons(a, b, margin, manifold);
  if (circleB) return collidePolygonAndCircle(a, b, true, margin, manifold);
  return collidePolygonAndCircle(b, a, false, margin, manifold);
}

}  // namespace impulse2d
