// The global reference's settings (reference_solver.h): Lemke's method for small islands, the
// active set for large ones, and the targets and position pass it shares.
#pragma once

#include "impulse2d/shared_settings.h"

namespace impulse2d {

/// Lemke's complementary pivoting (lcp.h): how it may pivot.
struct LemkeSettings {
  /// The method gives up (and says so) after this many pivots, or after maxPivotsPerVariable
  /// per variable of the problem if that is fewer.
  int maxPivots = 100000;
  /// A path that reaches a solution takes a few pivots per variable (at most 4 seen, on a
  /// 10-row pyramid's landing); one that round-off sends in circles would run to maxPivots.
  int maxPivotsPerVariable = 20;
  /// A column entry must exceed this times the column's largest entry (or 1) to be a pivot:
  /// smaller entries are round-off of zeros, and pivoting on one wrecks the basis inverse.
  double pivotTolerance = 1e-9;
  /// Ratios closer than this (relative) count as a tie, broken lexicographically.
  double tieTolerance = 1e-12;
  /// Harris's ratio test (RatioTest::Harris) may overshoot a basic variable by this much,
  /// relative to the largest basic value, to take a larger pivot.
  double harrisTolerance = 1e-11;
};

/// The active set's safeguard against cycling: what follows a flip that does not lower the number
/// of violated points below the best seen.
enum class CyclingSafeguard {
  /// Júdice–Pires: blockFailures more block flips from where it is, then one point at a time.
  JudicePires,
  /// Go back to the best states and flip half as many of their violators, the worst first, then
  /// a quarter, … down to one, then one at a time. From rest a 40-row pyramid's first step falls
  /// to 9 violated points in 7 factorizations, and one more block flip from there raises it to
  /// 316.
  Backtrack,
};

/// The active-set method (active_set.h) that solves the reference's large islands.
struct ActiveSetSettings {
  /// Projected Gauss–Seidel sweeps from last step's impulses that guess each point's state
  /// (separated, sticking, sliding) before the first factorization.
  int guessSweeps = 20;
  /// After guessSweeps, the sweeps go on while one still changes a point's state, up to this
  /// many: a pile's first step starts from zero impulses, and its states settle only once the
  /// weight has reached the bottom, about one row a sweep.
  int maxGuessSweeps = 400;
  /// A point solved last step (its impulses and state carried over by feature id) starts in the
  /// state it was solved in; only new points take the state the sweeps guess, and a pile
  /// with no new point skips the sweeps. The sweeps give an unloaded point of a resting pile a
  /// little load, and the first factorization then finds it pulling: on a resting 20-row pyramid
  /// 45–95 such points a step. Off: every point's state comes from the sweeps.
  bool warmStates = true;
  /// The method gives up (and says so) after this many factorizations.
  int maxFactorizations = 200;
  /// What the method does after a flip that does not lower the number of violated points.
  CyclingSafeguard cyclingSafeguard = CyclingSafeguard::Backtrack;
  /// Under Júdice–Pires: block flips in a row that do not lower the number of violated points
  /// before the method flips one point at a time.
  int blockFailures = 3;
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
  /// On kept factors the corrections may go on for up to keptRounds.
  int refinements = 3;
  /// The corrections stop once the residual of the unregularized system is below this fraction
  /// of |b| + |A||x|: a thousandth of residualTolerance, and above the floor that a pile's
  /// redundant rows leave (about 1e-14, rising slowly as a resting pyramid settles).
  double refinementTolerance = 1e-12;
  /// A condition counts as violated beyond this fraction of the island's impulse scale.
  double flipTolerance = 1e-12;
  /// The factors of each island's last factorized system are kept, and a step's first system of
  /// the same size is first solved by GMRES preconditioned by them (KeptFactorization): a
  /// resting pile then needs no factorization a step. Off: every system is factorized.
  bool keepFactors = true;
  /// GMRES rounds on kept factors before the system is factorized after all, and then at most as
  /// many corrections that take the regularization out: each costs one solve with the factors,
  /// about 1/30 of a factorization of a 20-row pyramid's system.
  int keptRounds = 8;
  /// Solves with kept factors beyond a system's first solve and first correction (GMRES
  /// rounds, further corrections), summed since the factors were made, after which the next
  /// system is factorized afresh. A large pile's factorization costs about as much as this many
  /// solves on kept factors (docs/design/reference-active-set.md), so a pile whose kept factors
  /// have drifted from it pays at most about twice what a factorization at the right moment
  /// would cost, and one that rests on them pays nothing more.
  int refactorAfterSolves = 40;
  /// A solve on kept factors is done once the residual of A x = b is below this fraction of
  /// |b| + |A||x| (largest entries, largest row sum): the round-off of a solve on fresh factors.
  double keptTolerance = 1e-14;
  /// The factorization takes a row's own diagonal entry as its pivot when that entry is at
  /// least this fraction of the largest in its column, so the symmetric fill-reducing order
  /// holds; below, it pivots on the largest. The regularized pivots of a redundant pile are about
  /// `regularization` of their column and must pass; 1 is partial pivoting.
  double diagonalPivotThreshold = 1e-12;
};

/// The global solve of all contact impulses together: the accuracy reference.
struct ReferenceSolverSettings {
  /// Required residual of the physical conditions (N s), relative to the step's impulse scale:
  /// the largest of the impulses, each point's cancelling impulses and the contact bodies' momenta.
  double residualTolerance = 1e-9;
  /// Lemke's pivot limit and tolerances; reaching the limit is reported, never silently accepted.
  LemkeSettings lemke;
  /// A resting pile is massively degenerate (many zero velocities); in floating point the
  /// lexicographic rule can then still end on a ray. Lemke is retried once with q moved by
  /// this much (relative to its largest entry, growing along the rows), the textbook remedy;
  /// the answer is checked against the unperturbed problem, so it cannot pass unnoticed.
  double degeneracyPerturbation = 1e-10;
  /// Then Lemke is tried with Harris's ratio test, and then along up to this many other covering
  /// vectors (entries drawn in [0.5, 2) from a fixed seed), each with both ratio tests: every
  /// path ends at a solution in exact arithmetic, but on a landing pile round-off and tiny pivots
  /// end some of them on a ray or an answer the residual check rejects. 0: no such retries.
  int coveringRetries = 3;
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
