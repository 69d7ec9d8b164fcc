// The position pass that sequential impulses and the reference share, so their drift compares
// fairly: non-linear Gauss–Seidel on the penetrations, after Box2D 2.4's
// b2ContactSolver::SolvePositionConstraints.
//
// After the positions are integrated, some overlap may remain. For each contact point in turn the
// pass recomputes the penetration from the current body positions (the two surface anchors along
// the manifold normal), and moves and turns the two bodies directly so that a fraction of the
// penetration beyond the slop goes away, each body in proportion to its inverse mass and inertia,
// as an impulse would but applied to positions. Velocities are never touched, so the pass adds no
// kinetic energy; sweeps are repeated because moving one body changes its other contacts.
#pragma once

#include "impulse2d/solver.h"

namespace impulse2d {

/// How hard the pass corrects; each solver fills it from its settings.
struct PositionCorrection {
  int iterations = 0;                ///< sweeps over all points; 0 turns the pass off
  double correctionFactor = 0.0;     ///< fraction of (penetration − slop) removed per sweep
  double allowedPenetration = 0.0;   ///< m, the slop left alone so contacts stay touching
  double maxCorrection = 0.0;        ///< m, largest correction at one point in one sweep
  bool block = false;                ///< correct a two-point contact's corners together
  double blockConditionLimit = 0.0;  ///< see isWellConditioned (sequential_impulses.h)
};

/// The penetration of a manifold's point at the bodies' current positions: the anchor on A
/// minus the anchor on B, along the normal (> 0 overlap).
double currentPenetration(const Body& a, const Body& b, const Manifold& manifold, int point);

/// Runs the pass over the context's manifolds; reports each correction to the observer (phase
/// Position, iteration = sweep, desiredChange = the penetration it removed).
void correctPositions(const StepContext& context, const PositionCorrection& correction);

}  // namespace impulse2d
