// Internal edges (internal_edges.h): a contact point on a static polygon is refused where a flush
// static neighbour makes the feature it touches part of the surface's inside. The rules look only
// at the point on the polygon's surface and the contact normal, so they serve circles and
// polygons alike.
#include "impulse2d/internal_edges.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {
namespace {

/// One face of a polygon body, in world coordinates.
struct WorldFace {
  Vec2 start;
  Vec2 end;
  Vec2 normal;
};

WorldFace worldFace(const Body& body, int face) {
  const int count = static_cast<int>(body.shape.vertices.size());
  return {body.toWorld(body.shape.vertices[face]),
          body.toWorld(body.shape.vertices[(face + 1) % count]),
          body.rotation * body.shape.normals[face]};
}

/// Distance of a point from a segment.
double distanceToSegment(const Vec2& point, const WorldFace& face) {
  const Vec2 along = face.end - face.start;
  const double t = std::clamp(along.dot(point - face.start) / along.squaredNorm(), 0.0, 1.0);
  return (face.start + t * along - point).norm();
}

/// Whether the face passes through the point.
bool throughPoint(const WorldFace& face, const Vec2& point) {
  return distanceToSegment(point, face) <= kFlushDistance;
}

/// The face of the polygon the point lies on whose normal is (within kFlushAngle) the contact
/// normal; -1 when there is none: the point is at a corner of the polygon's own.
int faceUnder(const Body& polygon, const Vec2& point, const Vec2& normal) {
  for (int i = 0; i < static_cast<int>(polygon.shape.vertices.size()); ++i) {
    const WorldFace face = worldFace(polygon, i);
    if (face.normal.dot(normal) >= std::cos(kFlushAngle) && throughPoint(face, point)) return i;
  }
  return -1;
}

/// A face of the neighbour pressed against the polygon's face at the point: turned against it,
/// through the point, and covering the face there. Where the cover ends short of the face's own
/// end, the face goes on outside it and a point at that end of the cover is on the surface (a box
/// in the corner of a wall standing on the floor touches the floor there).
bool coversFace(const WorldFace& cover, const WorldFace& face, const Vec2& point) {
  if (cover.normal.dot(face.normal) > -std::cos(kFlushAngle) || !throughPoint(cover, point)) {
    return false;
  }
  const double length = (face.end - face.start).norm();
  const Vec2 along = (face.end - face.start) / length;
  const double at = along.dot(point - face.start);
  const double coverStart = std::max(
      0.0, std::min(along.dot(cover.start - face.start), along.dot(cover.end - face.start)));
  const double coverEnd = std::min(
      length, std::max(along.dot(cover.start - face.start), along.dot(cover.end - face.start)));
  const bool atOpenStart = at < coverStart + kFlushDistance && coverStart > kFlushDistance;
  const bool atOpenEnd = at > coverEnd - kFlushDistance && coverEnd < length - kFlushDistance;
  return !atOpenStart && !atOpenEnd;
}

/// A face of the neighbour through the corner that rises in front of the contact plane: the
/// surface does not turn at the corner by as much as the normal says.
bool risesInFront(const WorldFace& face, const Vec2& corner, const Vec2& normal) {
  if (!throughPoint(face, corner)) return false;
  for (const Vec2& end : {face.start, face.end}) {
    const Vec2 away = end - corner;
    if (normal.dot(away) > std::sin(kFlushAngle) * away.norm()) return true;
  }
  return false;
}

/// Whether a face of the neighbour makes the point internal: it covers the polygon's face there
/// (`face` ≥ 0), or rises in front of the contact plane at the polygon's corner (`face` < 0).
bool internalTo(const Body& neighbour, const Body& polygon, int face, const Vec2& point,
                const Vec2& normal) {
  for (int i = 0; i < static_cast<int>(neighbour.shape.vertices.size()); ++i) {
    const WorldFace side = worldFace(neighbour, i);
    const bool internal = face >= 0 ? coversFace(side, worldFace(polygon, face), point)
                                    : risesInFront(side, point, normal);
    if (internal) return true;
  }
  return false;
}

bool nearBounds(const Aabb& bounds, const Vec2& point) {
  return (point.array() >= bounds.lower.array() - kFlushDistance).all() &&
         (point.array() <= bounds.upper.array() + kFlushDistance).all();
}

bool onInternalEdge(const std::vector<Body>& bodies, const std::vector<int>& staticBodies,
                    int surface, const Vec2& point, const Vec2& normal) {
  const Body& polygon = bodies[surface];
  const int face = faceUnder(polygon, point, normal);
  for (const int other : staticBodies) {
    const Body& neighbour = bodies[other];
    if (other == surface || neighbour.shape.type != ShapeType::Polygon) continue;
    if (!nearBounds(neighbour.bounds, point)) continue;
    if (internalTo(neighbour, polygon, face, point, normal)) return true;
  }
  return false;
}

}  // namespace

int dropInternalEdgePoints(const std::vector<Body>& bodies, const std::vector<int>& staticBodies,
                           Manifold& manifold) {
  const Body& a = bodies[manifold.bodyA];
  const Body& b = bodies[manifold.bodyB];
  const bool surfaceIsA = a.isStatic() && a.shape.type == ShapeType::Polygon;
  const bool surfaceIsB = b.isStatic() && b.shape.type == ShapeType::Polygon;
  if (surfaceIsA == surfaceIsB) return manifold.pointCount;
  const int surface = surfaceIsA ? manifold.bodyA : manifold.bodyB;
  const Vec2 normal = surfaceIsA ? manifold.normal : Vec2(-manifold.normal);
  int kept = 0;
  for (int i = 0; i < manifold.pointCount; ++i) {
    const ContactPoint& point = manifold.points[i];
    const Vec2 onSurface = surfaceIsA ? a.toWorld(point.anchorA) : b.toWorld(point.anchorB);
    if (onInternalEdge(bodies, staticBodies, surface, onSurface, normal)) continue;
    manifold.points[kept++] = point;
  }
  manifold.pointCount = kept;
  return kept;
}

}  // namespace impulse2d
