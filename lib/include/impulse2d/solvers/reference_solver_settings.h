// The global reference's settings (reference_solver.h): Lemke's method for small islands, the
// active set for large ones, and the targets and position pass it shares.
#pragma once

#include "impulse2d/shared_settings.h"

namespace impulse2d {

/// Lemke's complementary pivoting (lcp.h): how long it may pivot. Its tolerances, which only
/// tell round-off from a pivot or a tie, are constants of lcp.cpp.
struct LemkeSettings {
  /// The method gives up (and says so) after this many pivots, or after maxPivotsPerVariable
  /// per variable of the problem if that is fewer.
  int maxPivots = 100000;
  /// A path that reaches a solution takes a few pivots per variable (at most 4 seen, on a
  /// 10-row pyramid's landing); one that round-off sends in circles would run to maxPivots.
  int maxPivotsPerVariable = 20;
};

/// The active set's safeguard against cycling: what follows a flip that does not lower the number
/// of violated points below the best seen.
enum class CyclingSafeguard {
  /// Júdice–Pires: a few more block flips from where it is, then one point at a time.
  JudicePires,
  /// Go back to the best states and flip half as many of their violators, the worst first, then
  /// a quarter, … down to one, then one at a time. From rest a 40-row pyramid's first step falls
  /// to 9 violated points in 7 factorizations, and one more block flip from there raises it to
  /// 316.
  Backtrack,
};

/// The active-set method (active_set.h) that solves the reference's large islands. What only
/// changes its cost, not its answer (how long the guess sweeps and GMRES go on), and its
/// round-off tolerances are constants of active_set.cpp and kept_factorization.cpp.
struct ActiveSetSettings {
  /// Projected Gauss–Seidel sweeps from last step's impulses that guess each point's state
  /// (separated, sticking, sliding) before the first factorization; they go on after these while
  /// a sweep still changes a point's state.
  int guessSweeps = 20;
  /// A point solved last step (its impulses and state carried over by feature id) starts in the
  /// state it was solved in; only new points take the state the sweeps guess, and a pile
  /// with no new point skips the sweeps. The sweeps give an unloaded point of a resting pile a
  /// little load, and the first factorization then finds it pulling, every step of a resting
  /// pile (docs/design/reference-active-set.md, "Warm states"). Off: every point's state comes
  /// from the sweeps.
  bool warmStates = true;
  /// The method gives up (and says so) after this many factorizations.
  int maxFactorizations = 200;
  /// What the method does after a flip that does not lower the number of violated points.
  CyclingSafeguard cyclingSafeguard = CyclingSafeguard::Backtrack;
  /// A separated point that the answer closes while it slips takes up sliding against its slip
  /// (λt = ∓μλn), as a contact that starts while slipping does, instead of sticking; a slide
  /// the next answer reverses makes it stick. Forcing such a point to stick can contradict other
  /// states on dependent rows (a regularized self-stress of 1/r's size, flips that undo each
  /// other), so more random piles are answered by the active set alone with it on
  /// (docs/design/reference-active-set.md).
  bool enterSliding = true;
  /// Tikhonov term on each velocity row, relative to its Delassus diagonal: it makes the system
  /// of redundant contacts (a box face's two points, a pyramid) regular. The shift of the
  /// velocities it causes is taken out again by corrections centred on the last answer
  /// (`refinements`).
  double regularization = 1e-8;
  /// The regularization is centred on the guess (last step's impulses at a point carried over,
  /// the sweeps' at a new one) instead of on zero: a resting pile's answer then needs no
  /// correction after its first solve, and redundant contacts keep the split they had. Off:
  /// centred on zero, the split the first solve chooses.
  bool centreOnGuess = true;
  /// Most corrections on fresh factors that take the regularization's shift out (proximal point
  /// steps; each removes all but about `regularization` of what is left, so one usually does).
  /// On kept factors the corrections may go on for as many rounds as GMRES may take.
  int refinements = 3;
  /// The factors of each island's last factorized system are kept, and a step's first system of
  /// the same size is first solved by GMRES preconditioned by them (KeptFactorization): a
  /// resting pile then needs no factorization a step. Off: every system is factorized.
  bool keepFactors = true;
  /// Solves with kept factors beyond a system's first solve and first correction (GMRES
  /// rounds, further corrections), summed since the factors were made, after which the next
  /// system is factorized afresh. A large pile's factorization costs about as much as this many
  /// solves on kept factors (docs/design/reference-active-set.md), so a pile whose kept factors
  /// have drifted from it pays at most about twice what a factorization at the right moment
  /// would cost, and one that rests on them pays nothing more.
  int refactorAfterSolves = 40;
};

/// The global solve of all contact impulses together: the accuracy reference.
struct ReferenceSolverSettings {
  /// Required residual of the physical conditions (N s), relative to the step's impulse scale:
  /// the largest of the impulses, each point's cancelling impulses and the contact bodies' momenta.
  double residualTolerance = 1e-9;
  /// Lemke's pivot limit; reaching it is reported, never silently accepted. A path that fails is
  /// retried along others (reference_solver.cpp, lemkeAttempt), each answer checked.
  LemkeSettings lemke;
  /// Islands of up to this many contact points are solved by Lemke; larger ones by the active
  /// set, whose cost grows with the sparse factorization instead of Lemke's points³ (a stack of
  /// 10 boxes has 20 points, a 10-row pyramid 280).
  int lemkeIslandPoints = 40;
  /// A large island on which the active set fails is given to Lemke if it has at most this many
  /// points; larger ones fail with the active set's reason.
  int lemkeFallbackPoints = 300;
  /// The active set of large islands.
  ActiveSetSettings activeSet;
  /// When no impulses meet an island's bounce targets together (every path ends on a ray: a box
  /// sliding down a slope into a wall bounces off it while friction holds its face, and Newton's
  /// law of restitution at several contacts with friction need not have an answer), the island
  /// bounces by Poisson's law in two solves: first compression, every bounce target taken out;
  /// then each bouncing point pushed by its restitution times its compression impulse, and the
  /// island solved again with no bounce. Both solves are checked. Off: the step fails.
  bool restitutionInTwoSolves = true;
  /// Bounce targets and speculative gaps by the same rules as sequential impulses, but without
  /// penetration bias (penetration is the position pass's alone): a bias asks the points of a
  /// statically indeterminate pile to separate at rates that differ from corner to corner, and
  /// such a problem may have no exact answer — Lemke then ends on a ray along every path (a
  /// 5-row pyramid landing from 0.5 m). Without bias the problem always has one
  /// (docs/global-reference.md). --error-vs-reference still poses the method's own targets.
  ContactTargetSettings targets = unbiasedTargets();
  /// The same position pass as sequential impulses.
  PositionPassSettings positionPass;
  /// The position pass's block solve takes a two-point contact's corners together only while
  /// k₀₀² < this × det K (Box2D's 1000, as sequential impulses' block.conditionLimit).
  double blockConditionLimit = 1000.0;
};

}  // namespace impulse2d
