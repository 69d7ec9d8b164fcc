// The contact math every solver shares: effective masses, relative velocities, impulses, current
// points and penetrations, targets and friction states.
#include "impulse2d/solvers/contact_math.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace impulse2d {

double velocityPerUnitImpulse(const Body& body, const Vec2& impulsePoint,
                              const Vec2& impulseDirection, const Vec2& measurePoint,
                              const Vec2& measureDirection) {
  const Vec2 impulseArm = impulsePoint - body.position;
  const Vec2 measureArm = measurePoint - body.position;
  return body.inverseMass * impulseDirection.dot(measureDirection) +
         body.inverseInertia * cross(impulseArm, impulseDirection) *
             cross(measureArm, measureDirection);
}

double pairVelocityPerUnitImpulse(const Body& a, const Body& b, const Vec2& impulsePoint,
                                  const Vec2& impulseDirection, const Vec2& measurePoint,
                                  const Vec2& measureDirection) {
  return velocityPerUnitImpulse(a, impulsePoint, impulseDirection, measurePoint, measureDirection) +
         velocityPerUnitImpulse(b, impulsePoint, impulseDirection, measurePoint, measureDirection);
}

double unitImpulseResponse(const Body& a, const Body& b, const Vec2& point, const Vec2& direction) {
  return pairVelocityPerUnitImpulse(a, b, point, direction, point, direction);
}

Mat2 contactMatrix(const Body& a, const Body& b, const Vec2& point, const Vec2& normal) {
  const Vec2 tangent = leftPerpendicular(normal);
  const double coupling = pairVelocityPerUnitImpulse(a, b, point, tangent, point, normal);
  Mat2 matrix;
  matrix << unitImpulseResponse(a, b, point, normal), coupling, coupling,
      unitImpulseResponse(a, b, point, tangent);
  return matrix;
}

Mat2 normalCouplingMatrix(const Body& a, const Body& b, const Vec2& normal, const Vec2& point0,
                          const Vec2& point1) {
  const double coupling = pairVelocityPerUnitImpulse(a, b, point0, normal, point1, normal);
  Mat2 k;
  k << unitImpulseResponse(a, b, point0, normal), coupling, coupling,
      unitImpulseResponse(a, b, point1, normal);
  return k;
}

Mat2 couplingBlock(const std::vector<Body>& bodies, const Manifold& mi, const Vec2& pi,
                   const Manifold& mj, const Vec2& pj) {
  const std::array<Vec2, 2> directionsI{mi.normal, mi.tangent()};
  const std::array<Vec2, 2> directionsJ{mj.normal, mj.tangent()};
  const std::array<std::pair<int, double>, 2> bodiesI{{{mi.bodyA, -1.0}, {mi.bodyB, 1.0}}};
  const std::array<std::pair<int, double>, 2> bodiesJ{{{mj.bodyA, -1.0}, {mj.bodyB, 1.0}}};
  Mat2 block = Mat2::Zero();
  for (const auto& [bodyI, signI] : bodiesI) {
    for (const auto& [bodyJ, signJ] : bodiesJ) {
      const Body& body = bodies[static_cast<size_t>(bodyI)];
      if (bodyI != bodyJ || body.isStatic()) continue;
      for (int r = 0; r < 2; ++r) {
        for (int c = 0; c < 2; ++c) {
          block(r, c) += signI * signJ *
                         velocityPerUnitImpulse(body, pj, directionsJ[static_cast<size_t>(c)], pi,
                                                directionsI[static_cast<size_t>(r)]);
        }
      }
    }
  }
  return block;
}

double relativeVelocity(const Body& a, const Body& b, const Vec2& point, const Vec2& direction) {
  return (b.velocityAt(point) - a.velocityAt(point)).dot(direction);
}

Vec2 contactVelocity(const Body& a, const Body& b, const Vec2& point, const Vec2& normal) {
  const Vec2 relative = b.velocityAt(point) - a.velocityAt(point);
  return Vec2(relative.dot(normal), relative.dot(leftPerpendicular(normal)));
}

void applyContactImpulse(std::vector<Body>& bodies, const Manifold& manifold, int point,
                         double normalImpulse, double tangentImpulse) {
  const Vec2 impulse = normalImpulse * manifold.normal + tangentImpulse * manifold.tangent();
  const Vec2& where = manifold.points[static_cast<size_t>(point)].point;
  bodies[static_cast<size_t>(manifold.bodyA)].applyImpulse(-impulse, where);
  bodies[static_cast<size_t>(manifold.bodyB)].applyImpulse(impulse, where);
}

Vec2 currentContactPoint(const Body& a, const Body& b, const ContactPoint& point) {
  return 0.5 * (a.toWorld(point.anchorA) + b.toWorld(point.anchorB));
}

double currentPenetration(const Body& a, const Body& b, const Manifold& manifold, int point) {
  const ContactPoint& contact = manifold.points[static_cast<size_t>(point)];
  return (a.toWorld(contact.anchorA) - b.toWorld(contact.anchorB)).dot(manifold.normal);
}

double targetSeparatingVelocity(double normalVelocityBefore, double penetration, double restitution,
                                double dt, const ContactTargetSettings& rules) {
  double target = 0.0;
  if (penetration < 0.0) {
    target = penetration / dt;
  } else if (rules.penetrationBias) {
    const double excess = std::max(penetration - rules.allowedPenetration, 0.0);
    target = std::min(rules.biasFactor * excess / dt, rules.maxBiasVelocity);
  }
  const bool closesThisStep = normalVelocityBefore * dt < penetration;
  const bool bounces = restitution > 0.0 && closesThisStep &&
                       normalVelocityBefore < -rules.restitutionVelocityThreshold;
  if (bounces) target = std::max(target, -restitution * normalVelocityBefore);
  return target;
}

FrictionState frictionStateOf(double normalImpulse, double tangentImpulse, double friction,
                              double tolerance) {
  if (normalImpulse <= 0.0) return FrictionState::None;
  return std::abs(tangentImpulse) >= friction * normalImpulse - tolerance ? FrictionState::Dynamic
                                                                          : FrictionState::Static;
}

}  // namespace impulse2d
