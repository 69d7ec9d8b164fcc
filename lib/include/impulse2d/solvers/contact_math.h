// The contact math every solver shares (Solver2D's solve_common): how an impulse at a contact
// changes velocities, the relative velocity at a point, applying a contact impulse, where a
// contact point is now and how deep it is, the separating velocity a contact should reach, and
// the friction state of a point. Each solver file sits on this module; no solver includes
// another. Signs are those of contact.h.
#pragma once

#include <array>
#include <vector>

#include "impulse2d/body.h"
#include "impulse2d/contact.h"
#include "impulse2d/settings.h"

namespace impulse2d {

/// What an iterative solver's impulses read and change of a body: a compact copy of its
/// velocities and inverse mass and inertia (zero for static bodies), written back at the end.
struct SolverBody {
  /// m/s
  Vec2 velocity = Vec2::Zero();
  /// rad/s
  double angularVelocity = 0.0;
  /// 1/kg
  double inverseMass = 0.0;
  /// 1/(kg m^2)
  double inverseInertia = 0.0;
};

/// A manifold as an iterative solve holds it: which of the step's manifolds, its two bodies, its
/// normal, its mixed coefficients and how many points it has.
struct SolverManifold {
  int manifold = 0;            ///< index into the step's manifolds
  int bodyA = 0;               ///< index into the world's bodies
  int bodyB = 0;               ///< index into the world's bodies
  Vec2 normal = Vec2::Zero();  ///< unit, from A to B
  double friction = 0.0;       ///< mixed coefficient of friction
  double restitution = 0.0;    ///< mixed coefficient of restitution
  int pointCount = 0;          ///< 1 or 2

  /// Takes manifold number `index` of the step.
  void load(const Manifold& contact, int index) {
    manifold = index;
    bodyA = contact.bodyA;
    bodyB = contact.bodyB;
    normal = contact.normal;
    friction = contact.friction;
    restitution = contact.restitution;
    pointCount = contact.pointCount;
  }
};

/// Velocity of a solver body's material at arm r (any type with velocity and angularVelocity).
template <typename Velocities>
Vec2 pointVelocity(const Velocities& body, const Vec2& r) {
  return body.velocity + cross(body.angularVelocity, r);
}

/// The relative velocity at arms rA, rB of two solver bodies: B's material minus A's.
template <typename Velocities>
Vec2 relativeVelocity(const Velocities& a, const Velocities& b, const Vec2& rA, const Vec2& rB) {
  return pointVelocity(b, rB) - pointVelocity(a, rA);
}

/// J·u of one contact row: the relative velocity (B's material minus A's) along unit d at a point
/// whose torque arms, r × d from A's and B's centres, are torqueArmA and torqueArmB:
/// (vB − vA)·d + ωB (rB × d) − ωA (rA × d). The row (−d, −rA × d, d, rB × d) is the Jacobian.
inline double velocityAlong(const SolverBody& a, const SolverBody& b, const Vec2& d,
                            double torqueArmA, double torqueArmB) {
  return (b.velocity - a.velocity).dot(d) + b.angularVelocity * torqueArmB -
         a.angularVelocity * torqueArmA;
}

/// An impulse λ along that row, M⁻¹Jᵀλ: −λd to A, +λd to B, and their turns λ (r × d)/I.
inline void applyAlong(SolverBody& a, SolverBody& b, const Vec2& d, double torqueArmA,
                       double torqueArmB, double impulse) {
  a.velocity -= (a.inverseMass * impulse) * d;
  a.angularVelocity -= a.inverseInertia * impulse * torqueArmA;
  b.velocity += (b.inverseMass * impulse) * d;
  b.angularVelocity += b.inverseInertia * impulse * torqueArmB;
}

/// The impulse P at arms rA, rB of two solver bodies: −P to A, +P to B.
template <typename Velocities>
void applyPairImpulse(Velocities& a, Velocities& b, const Vec2& rA, const Vec2& rB, const Vec2& P) {
  a.velocity -= a.inverseMass * P;
  a.angularVelocity -= a.inverseInertia * cross(rA, P);
  b.velocity += b.inverseMass * P;
  b.angularVelocity += b.inverseInertia * cross(rB, P);
}

/// One SolverBody per body, in the bodies' order: each body's velocities and inverse mass and
/// inertia (zero for static bodies, so impulses leave them still).
inline void loadSolverBodies(const std::vector<Body>& bodies,
                             std::vector<SolverBody>& solverBodies) {
  solverBodies.resize(bodies.size());
  for (int i = 0; i < static_cast<int>(bodies.size()); ++i) {
    const Body& body = bodies[i];
    solverBodies[i] = {body.velocity, body.angularVelocity, body.inverseMass, body.inverseInertia};
  }
}

/// The inverse effective mass of a contact along `direction` (unit), from the arms rA, rB of
/// each centre to the point: 1/m_A + 1/m_B + (rA × d)²/I_A + (rB × d)²/I_B, the relative
/// velocity there per unit impulse along d.
template <typename Masses>
double inverseEffectiveMass(const Masses& a, const Masses& b, const Vec2& armA, const Vec2& armB,
                            const Vec2& direction) {
  const double rA = cross(armA, direction);
  const double rB = cross(armB, direction);
  return a.inverseMass + b.inverseMass + a.inverseInertia * rA * rA + b.inverseInertia * rB * rB;
}

/// One entry of a contact matrix K from arms: the relative velocity along dj at the point of
/// arms (armAj, armBj) per unit impulse along di at the point of arms (armAi, armBi),
/// (1/m_A + 1/m_B) di·dj + (rAi × di)(rAj × dj)/I_A + (rBi × di)(rBj × dj)/I_B.
template <typename Masses>
double couplingPerUnitImpulse(const Masses& a, const Masses& b, const Vec2& armAi,
                              const Vec2& armBi, const Vec2& di, const Vec2& armAj,
                              const Vec2& armBj, const Vec2& dj) {
  return (a.inverseMass + b.inverseMass) * di.dot(dj) +
         a.inverseInertia * cross(armAi, di) * cross(armAj, dj) +
         b.inverseInertia * cross(armBi, di) * cross(armBj, dj);
}

// ---- velocity change per unit impulse: the one building block of every effective mass ----

/// The velocity change of `body` along `measureDirection` at `measurePoint` that a unit impulse
/// along `impulseDirection` at `impulsePoint` causes: d·d'/m + (r×d)(r'×d')/I. The building block
/// of the unit-impulse probe (one point), the lecture's contact matrix (one point, two
/// directions) and the reference's Delassus matrix (two points).
inline double velocityPerUnitImpulse(const Body& body, const Vec2& impulsePoint,
                                     const Vec2& impulseDirection, const Vec2& measurePoint,
                                     const Vec2& measureDirection) {
  const Vec2 impulseArm = impulsePoint - body.position;
  const Vec2 measureArm = measurePoint - body.position;
  return body.inverseMass * impulseDirection.dot(measureDirection) +
         body.inverseInertia * cross(impulseArm, impulseDirection) *
             cross(measureArm, measureDirection);
}

/// The two-body form: how the relative velocity of point i along direction i (B's material minus
/// A's) changes per unit impulse along direction j at point j of the same pair (+ on B, − on A).
inline double pairVelocityPerUnitImpulse(const Body& a, const Body& b, const Vec2& impulsePoint,
                                         const Vec2& impulseDirection, const Vec2& measurePoint,
                                         const Vec2& measureDirection) {
  return velocityPerUnitImpulse(a, impulsePoint, impulseDirection, measurePoint, measureDirection) +
         velocityPerUnitImpulse(b, impulsePoint, impulseDirection, measurePoint, measureDirection);
}

/// The text's unit-impulse probe in closed form: how much the relative velocity along `direction`
/// at `point` changes when an impulse of 1 N s acts there (+direction on B, −direction on A):
/// 1/m_A + 1/m_B + (r_A×d)²/I_A + (r_B×d)²/I_B. Its inverse is the impulse per unit of velocity
/// change: the normal (or tangent) mass.
inline double unitImpulseResponse(const Body& a, const Body& b, const Vec2& point,
                                  const Vec2& direction) {
  return pairVelocityPerUnitImpulse(a, b, point, direction, point, direction);
}

/// The lecture's contact matrix of one point: the velocity change (normal, tangent) that a unit
/// impulse (normal, tangent) causes, summed over both bodies. Row and column 0 are the normal,
/// 1 the tangent (ContactAxis). The planar form of the skew-symmetric construction.
Mat2 contactMatrix(const Body& a, const Body& b, const Vec2& point, const Vec2& normal);

/// The normal coupling matrix K of two points of one manifold: entry (i, j) is the change of
/// point i's normal velocity per unit normal impulse at point j. Symmetric; its diagonal is the
/// unit-impulse response of each point.
inline Mat2 normalCouplingMatrix(const Body& a, const Body& b, const Vec2& normal,
                                 const Vec2& point0, const Vec2& point1) {
  const double coupling = pairVelocityPerUnitImpulse(a, b, point0, normal, point1, normal);
  Mat2 k;
  k << unitImpulseResponse(a, b, point0, normal), coupling, coupling,
      unitImpulseResponse(a, b, point1, normal);
  return k;
}

/// The same K from the two points' arms, for bodies as a solver holds them (any type with
/// inverseMass and inverseInertia): for a solver whose arms stay as found while the bodies move
/// (soft step), so that no world point is shared by both bodies.
template <typename Masses>
Mat2 normalCouplingMatrix(const Masses& a, const Masses& b, const Vec2& normal,
                          const std::array<Vec2, 2>& armsA, const std::array<Vec2, 2>& armsB) {
  Mat2 k;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      k(i, j) = a.inverseMass + b.inverseMass +
                a.inverseInertia * cross(armsA[i], normal) * cross(armsA[j], normal) +
                b.inverseInertia * cross(armsB[i], normal) * cross(armsB[j], normal);
    }
  }
  return k;
}

// ---- velocities and impulses at a contact ----

/// The relative velocity (B's material minus A's) at `point`, along `direction`: vn on the
/// normal (< 0 closing), vt on the tangent.
inline double relativeVelocity(const Body& a, const Body& b, const Vec2& point,
                               const Vec2& direction) {
  return relativeVelocity<Body>(a, b, Vec2(point - a.position), Vec2(point - b.position))
      .dot(direction);
}

/// The relative velocity of B against A at a world point in contact coordinates:
/// (normal, tangent), i.e. (vn, vt).
Vec2 contactVelocity(const Body& a, const Body& b, const Vec2& point, const Vec2& normal);

/// Applies the impulse (normal, tangent) at a manifold's point: +P to B, −P to A.
void applyContactImpulse(std::vector<Body>& bodies, const Manifold& manifold, int point,
                         double normalImpulse, double tangentImpulse);

// ---- where a contact is now ----

/// The penetration of a manifold's point at the bodies' current poses: the anchor on A minus the
/// anchor on B, along the normal (> 0 overlap).
inline double currentPenetration(const Body& a, const Body& b, const Manifold& manifold,
                                 int point) {
  const ContactPoint& contact = manifold.points[point];
  return (a.toWorld(contact.anchorA) - b.toWorld(contact.anchorB)).dot(manifold.normal);
}

// ---- targets and friction ----

/// The target separating velocity of one point, from its closing velocity before the solve:
/// - touching (penetration ≥ 0): the penetration bias min(β·(d − slop)/dt, cap), or 0;
/// - a gap (penetration < 0, speculative): −gap/dt, the approach that just closes it;
/// - a bounce −e·vn, when the closing speed exceeds the threshold and the gap closes within the
///   step, replaces either if larger. The bias never enters the bounce: a deep contact does not
///   bounce harder, and a bounce is not scaled by the penetration.
double targetSeparatingVelocity(double normalVelocityBefore, double penetration, double restitution,
                                double dt, const ContactTargetSettings& rules);

/// Static inside Coulomb's limit |λt| < μλn, Dynamic on it (within `tolerance`, N s), None when
/// the point carries no normal impulse.
FrictionState frictionStateOf(double normalImpulse, double tangentImpulse, double friction,
                              double tolerance);

}  // namespace impulse2d
