// Continuous collision against static bodies (continuous.h) by conservative advancement: the
// gap to the static body is a lower bound on the distance (separating axes, collide.h), and no
// point of the moving body travels faster than its centre's speed plus its spin times its reach,
// so advancing by gap / that speed never passes into the static body.
#include "impulse2d/continuous.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "impulse2d/collide.h"

namespace impulse2d {
namespace {

/// m. The distance of the shape's farthest point from its centre.
double reach(const Shape& shape) {
  double farthest = shape.radius;
  for (const Vec2& vertex : shape.vertices) farthest = std::max(farthest, vertex.norm());
  return farthest;
}

/// m. A circle's radius, or the distance of a polygon's nearest face from its centre.
double smallestExtent(const Shape& shape) {
  if (shape.type == ShapeType::Circle) return shape.radius;
  double nearest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < shape.vertices.size(); ++i) {
    nearest = std::min(nearest, shape.normals[i].dot(shape.vertices[i]));
  }
  return nearest;
}

/// The body's motion over the substep, as a fraction t of it runs from 0 to 1.
struct Motion {
  Pose start;
  Pose end;
  Pose at(double t) const {
    return {start.position + t * (end.position - start.position),
            start.angle + t * (end.angle - start.angle)};
  }
};

void place(Body& body, const Pose& pose) {
  body.position = pose.position;
  body.angle = pose.angle;
  body.updateRotation();
}

/// The first fraction of the motion at which gap(t) ≤ target, advancing by (gap − 0) / speed;
/// 1 or more when it is not reached. `gap` places the body and measures.
template <typename Gap>
double advance(const Gap& gap, double speed, double target) {
  if (speed <= 0.0) return 1.0;
  double t = 0.0;
  for (int i = 0; i < kMaxAdvances && t < 1.0; ++i) {
    const double distance = gap(t);
    if (distance <= target) return t;
    t += distance / speed;
  }
  return t;
}

/// The fraction at which the motion should stop against one static body; 1 when it need not.
double impactFraction(Body& body, const Body& wall, const Motion& motion, double targetGap) {
  const double core = kCoreShare * smallestExtent(body.shape);
  const double travel = (motion.end.position - motion.start.position).norm();
  const auto coreGap = [&](double t) {
    return separationFromPoint(wall, motion.at(t).position) - core;
  };
  if (coreGap(0.0) <= 0.0) return 1.0;  // already deep at the start: the contacts handle it
  const double coreHit = advance(coreGap, travel, 0.0);
  if (coreHit >= 1.0) return 1.0;
  const double sweep = travel + std::abs(motion.end.angle - motion.start.angle) * reach(body.shape);
  const auto surfaceGap = [&](double t) {
    place(body, motion.at(t));
    return separation(body, wall);
  };
  const double touch = std::min(advance(surfaceGap, sweep, targetGap), coreHit);
  return touch > 0.0 ? touch : coreHit;
}

bool sweptBoundsMeet(const Body& body, double travel, const Body& wall) {
  const Vec2 grow(travel, travel);
  return Aabb{body.bounds.lower - grow, body.bounds.upper + grow}.overlaps(wall.bounds);
}

/// Moves one body back to its time of impact with the nearest static body in its way.
bool stopBody(std::vector<Body>& bodies, Body& body, const Motion& motion,
              const std::vector<int>& staticBodies, double targetGap) {
  const double travel = (motion.end.position - motion.start.position).norm();
  if (travel <= kCoreShare * smallestExtent(body.shape)) return false;
  double first = 1.0;
  for (const int wall : staticBodies) {
    if (!sweptBoundsMeet(body, travel, bodies[wall])) continue;
    first = std::min(first, impactFraction(body, bodies[wall], motion, targetGap));
  }
  if (first >= 1.0) return false;
  place(body, motion.at(first));
  body.updateCache();
  return true;
}

}  // namespace

int stopAtTimeOfImpact(std::vector<Body>& bodies, const std::vector<Pose>& start,
                       const std::vector<int>& staticBodies, double targetGap) {
  int stopped = 0;
  for (size_t i = 0; i < bodies.size(); ++i) {
    Body& body = bodies[i];
    if (!body.isAwake()) continue;
    const Motion motion{start[i], {body.position, body.angle}};
    if (stopBody(bodies, body, motion, staticBodies, targetGap)) ++stopped;
  }
  return stopped;
}

}  // namespace impulse2d
