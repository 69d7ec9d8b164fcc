// The position pass that sequential impulses and the reference share, so their drift compares
// fairly: non-linear Gauss–Seidel on the penetrations, after Box2D 2.4's
// b2ContactSolver::SolvePositionConstraints.
//
// After the positions are integrated, some overlap may remain. For each contact point in turn the
// pass recomputes the penetration from the current body positions (the two surface anchors along
// the manifold normal), and moves and turns the two bodies directly so that a fraction of the
// penetration beyond the slop goes away, each body in proportion to its inverse mass and inertia,
// as an impulse would but applied to positions. Velocities are never touched, so the pass adds no
// kinetic energy; sweeps are repeated because moving one body changes its other contacts, until
// one moves nothing.
#pragma once

#include "impulse2d/solver.h"

namespace impulse2d {

/// Runs the pass over the context's manifolds, leaving `allowedPenetration` (the solver's slop)
/// alone; with the pass's block solve, a two-point contact is one block while k₀₀² <
/// blockConditionLimit × det K. Reports each correction to the observer (phase Position,
/// iteration = sweep, desiredChange = the penetration it removed).
void correctPositions(const StepContext& context, const PositionPassSettings& pass,
                      double allowedPenetration, double blockConditionLimit);

}  // namespace impulse2d
