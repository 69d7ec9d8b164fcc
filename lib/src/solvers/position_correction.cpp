// The shared position pass: non-linear Gauss–Seidel on penetrations (Box2D 2.4's
// SolvePositionConstraints), moving positions and angles, never velocities.
#include "impulse2d/solvers/position_correction.h"

#include <algorithm>
#include <array>

#include "impulse2d/solvers/contact_math.h"
#include "impulse2d/solvers/two_point_block.h"

namespace impulse2d {
namespace {

/// Moves a body as a positional "impulse" P at world point `where` would: x += P/m,
/// θ += (r × P)/I. The rotation follows without trigonometry; the bounds are the world's to
/// refresh after the pass.
void moveBody(Body& body, const Vec2& push, const Vec2& where) {
  if (body.isStatic()) return;
  body.position += body.inverseMass * push;
  body.turnBy(body.inverseInertia * cross(Vec2(where - body.position), push));
}

/// How hard the pass corrects: the solver's settings, gathered once per pass.
struct Correction {
  const PositionPassSettings& pass;
  double allowedPenetration;
  double blockConditionLimit;
};

/// A manifold's point at the bodies' current poses: where it is (contactPointBetween the surface
/// anchors) and how deep (as currentPenetration), from one transform of each anchor.
struct CurrentPoint {
  Vec2 where;
  double penetration;
};

CurrentPoint currentPoint(const Body& a, const Body& b, const Manifold& manifold, int index) {
  const ContactPoint& point = manifold.points[index];
  const Vec2 anchorA = a.toWorld(point.anchorA);
  const Vec2 anchorB = b.toWorld(point.anchorB);
  return {contactPointBetween(anchorA, anchorB), (anchorA - anchorB).dot(manifold.normal)};
}

/// What one sweep should remove at a point: a fraction of the penetration beyond the slop,
/// capped; ≤ 0 when there is nothing to remove.
double wantedRemoval(double penetration, const Correction& correction) {
  const double excess = penetration - correction.allowedPenetration;
  return std::min(correction.pass.correctionFactor * excess, correction.pass.maxCorrection);
}

void report(const StepContext& context, int sweep, int manifold, int point, double removed) {
  if (removed <= 0.0) return;
  context.report({SolverEvent::Phase::Position, sweep, manifold, point, removed, 0.0, 0.0});
}

/// One point on its own: the positional impulse removal / K along the normal. Returns whether it
/// moved the bodies.
bool correctPoint(const StepContext& context, int manifoldIndex, int index,
                  const Correction& correction, int sweep) {
  const Manifold& manifold = context.manifolds[manifoldIndex];
  Body& a = context.bodies[manifold.bodyA];
  Body& b = context.bodies[manifold.bodyB];
  const CurrentPoint point = currentPoint(a, b, manifold, index);
  const double removed = wantedRemoval(point.penetration, correction);
  if (removed <= 0.0) return false;
  const Vec2 push =
      (removed / unitImpulseResponse(a, b, point.where, manifold.normal)) * manifold.normal;
  moveBody(a, -push, point.where);
  moveBody(b, push, point.where);
  report(context, sweep, manifoldIndex, index, removed);
  return true;
}

/// What correcting a flat contact's two corners together did.
enum class BlockCorrection { Moved, NothingToRemove, IllConditioned };

/// Both corners of a flat contact at once, so neither is favoured: positional impulses x ≥ 0 with
/// K x ≥ the wanted removals, complementary (the same 2×2 problem as the velocity block solve).
/// Does nothing when K is too ill-conditioned to solve as a block, and says so.
BlockCorrection correctTogether(const StepContext& context, int manifoldIndex,
                                const Correction& correction, int sweep) {
  const Manifold& manifold = context.manifolds[manifoldIndex];
  Body& a = context.bodies[manifold.bodyA];
  Body& b = context.bodies[manifold.bodyB];
  const std::array<CurrentPoint, 2> points{currentPoint(a, b, manifold, 0),
                                           currentPoint(a, b, manifold, 1)};
  const Vec2 wanted(wantedRemoval(points[0].penetration, correction),
                    wantedRemoval(points[1].penetration, correction));
  if (wanted(0) <= 0.0 && wanted(1) <= 0.0) return BlockCorrection::NothingToRemove;
  const Mat2 k = normalCouplingMatrix(a, b, manifold.normal, points[0].where, points[1].where);
  if (!isWellConditioned(k, correction.blockConditionLimit)) {
    return BlockCorrection::IllConditioned;
  }
  const Vec2 pushes = solveTwoPointLcp(k, -wanted);
  const Vec2 removed = k * pushes;
  for (int i = 0; i < 2; ++i) {
    moveBody(a, -pushes(i) * manifold.normal, points[i].where);
    moveBody(b, pushes(i) * manifold.normal, points[i].where);
    report(context, sweep, manifoldIndex, i, removed(i));
  }
  return BlockCorrection::Moved;
}

/// One sweep over every contact. Returns whether it moved any body: a sweep that found every
/// point within the slop leaves the poses as they were, so another would find the same.
bool correctionSweep(const StepContext& context, const Correction& correction, int sweep) {
  bool moved = false;
  for (int m = 0; m < static_cast<int>(context.manifolds.size()); ++m) {
    const int points = context.manifolds[m].pointCount;
    if (correction.pass.blockSolve && points == 2) {
      const BlockCorrection block = correctTogether(context, m, correction, sweep);
      moved = moved || block == BlockCorrection::Moved;
      if (block != BlockCorrection::IllConditioned) continue;
    }
    for (int i = 0; i < points; ++i)
      moved = correctPoint(context, m, i, correction, sweep) || moved;
  }
  return moved;
}

}  // namespace

// The sweeps stop at the first that moves nothing (Box2D 2.4 stops once no contact is deeper
// than three slops; this stop changes no result): a resting pile, all within the slop, costs one.
void correctPositions(const StepContext& context, const PositionPassSettings& pass,
                      double allowedPenetration, double blockConditionLimit) {
  const Correction correction{pass, allowedPenetration, blockConditionLimit};
  for (int sweep = 0; sweep < pass.iterations; ++sweep) {
    if (!correctionSweep(context, correction, sweep)) break;
  }
}

}  // namespace impulse2d
