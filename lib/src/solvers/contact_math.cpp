// The contact math every solver shares: effective masses, relative velocities, impulses, current
// points and penetrations, targets and friction states.
#include "impulse2d/solvers/contact_math.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace impulse2d {

Mat2 contactMatrix(const Body& a, const Body& b, const Vec2& point, const Vec2& normal) {
  const Vec2 tangent = leftPerpendicular(normal);
  const double coupling = pairVelocityPerUnitImpulse(a, b, point, tangent, point, normal);
  Mat2 matrix;
  matrix << unitImpulseResponse(a, b, point, normal), coupling, coupling,
      unitImpulseResponse(a, b, point, tangent);
  return matrix;
}

Vec2 contactVelocity(const Body& a, const Body& b, const Vec2& point, const Vec2& normal) {
  const Vec2 relative = b.velocityAt(point) - a.velocityAt(point);
  return Vec2(relative.dot(normal), relative.dot(leftPerpendicular(normal)));
}

void applyContactImpulse(std::vector<Body>& bodies, const Manifold& manifold, int point,
                         double normalImpulse, double tangentImpulse) {
  const Vec2 impulse = normalImpulse * manifold.normal + tangentImpulse * manifold.tangent();
  const Vec2& where = manifold.points[point].point;
  bodies[manifold.bodyA].applyImpulse(-impulse, where);
  bodies[manifold.bodyB].applyImpulse(impulse, where);
}

double targetSeparatingVelocity(double normalVelocityBefore, double penetration, double restitution,
                                double dt, const ContactTargetSettings& rules) {
  double target = 0.0;
  if (penetration < 0.0) {
    target = penetration / dt;
  } else if (rules.penetrationBias) {
    const double excess = std::max(penetration - rules.allowedPenetration, 0.0);
    target = std::min(rules.biasFactor * excess / dt, rules.maxPushVelocity);
  }
  const bool closesThisStep = normalVelocityBefore * dt < penetration;
  const bool bounces =
      restitution > 0.0 && closesThisStep && normalVelocityBefore < -rules.restitutionThreshold;
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
