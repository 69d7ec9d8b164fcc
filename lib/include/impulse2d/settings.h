// Every tunable number of the engine, with its documented default and valid range (checked where
// a scene or --set gives it: scene/setting_ranges.h). One struct for the world and
// one per contact solver; a scene file's [world] and [solver] tables set their fields by name.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "impulse2d/math.h"

namespace impulse2d {

struct WorldSettings {
  /// m/s^2. Earth's gravity, downwards.
  Vec2 gravity = Vec2(0.0, -9.81);
  /// s. The fixed time step: 60 updates a second, as most games run.
  /// Range: [1e-06, 1].
  double dt = 1.0 / 60.0;
  /// m. Contact points are generated while the surfaces are closer than this, so a resting body
  /// whose correction left a hair's gap keeps its contact. Solvers treat a gap as speculative:
  /// they only act if the gap would close within the step.
  /// Range: [0, 1].
  double contactMargin = 0.005;
  /// Each step runs the whole pipeline this many times with dt/substeps: a cure for a time step
  /// too large for the scene (deep overlaps, soft stacks) that keeps the step the caller sees.
  /// Range: [1, 1000] (more would let one run take hours).
  int substeps = 1;
  /// Fast bodies find their contacts one step early: the broad phase fattens each body's bounds
  /// by |v|·dt and a pair keeps contact points while the gap is under contactMargin + |vB−vA|·dt,
  /// so the solver can stop a fast small ball at a thin wall instead of letting it tunnel.
  bool speculativeContacts = false;
  /// Islands of bodies at rest go to sleep: they are not integrated, their contacts are neither
  /// recomputed nor solved, until an awake body touches them or the user pushes one.
  bool sleeping = false;
  /// m/s. A body slower than this (and sleepAngularSpeed) counts as resting. Box2D's 0.01: a
  /// hundredth of a body width of 1 m per second is invisible at 60 frames a second.
  /// Range: [0, 100].
  double sleepLinearSpeed = 0.01;
  /// rad/s. The angular speed below which a body counts as resting: Box2D's 2 degrees a second.
  /// Range: [0, 100].
  double sleepAngularSpeed = 2.0 * 3.14159265358979323846 / 180.0;
  /// s. An island sleeps once every body in it has rested this long (Box2D's half a second:
  /// long enough that a body at the top of a bounce or a swing is not frozen).
  /// Range: [0, 1e+06].
  double timeToSleep = 0.5;
  /// Keep a body that is speeding up awake, ours beyond Box2D: a body counts as resting only while
  /// its speed and spin have grown by less than speedUpShare of the thresholds above since its
  /// rest began; past that its rest begins again. A body that starts from rest and gathers speed
  /// slowly is then not frozen before it reaches the thresholds: under Box2D's rule (off) a disc
  /// rolling down 0.15° (a = 0.017 m/s²), a box on a slope 0.002 under its friction's limit or a
  /// seesaw 0.5 % out of balance is still slower than them after timeToSleep, falls asleep and
  /// never moves again, since a static body wakes nothing. With it on the slowest start that
  /// escapes is ten times slower (docs/sleeping.md).
  bool keepSpeedingUpAwake = true;
  /// The share of sleepLinearSpeed (sleepAngularSpeed) by which a resting body's speed (spin) may
  /// grow before it counts as speeding up: 1 mm/s and 0.2°/s. A settled pile's bodies jitter up
  /// by at most half of that (4.7e-4 m/s measured on a 10-box stack under micro).
  /// Range: [0, 1].
  double speedUpShare = 0.1;
};

/// The lecture's micro-collision resolver (lecture 3.6, Millington ch. 14-15).
struct MicroCollisionSettings {
  /// Remove the velocity built up by the last update's acceleration from the bounce target:
  /// Δv = −vs − c·(vs − vacc). Off: a resting contact bounces on gravity's velocity (jitter).
  bool removeAccelerationVelocity = true;
  /// Use zero restitution when the closing speed is under restitutionVelocityLimit.
  bool lowerRestitutionAtLowSpeed = true;
  /// m/s. Below this closing speed a contact does not bounce. Millington uses 0.25.
  /// Range: [0, 1000].
  double restitutionVelocityLimit = 0.25;
  /// Friction as impulses through the 2×2 contact matrix. Off: frictionless normal impulses.
  bool friction = true;
  /// m/s. Velocity resolution stops when no contact needs a larger velocity change; a bounce
  /// smaller than this is none (the point is not marked as bounced).
  /// Range: [0, 1].
  double velocityEpsilon = 1e-4;
  /// m. Penetration resolution stops when no contact penetrates deeper than this. Resting
  /// bodies settle at up to this overlap, and every step the points that sink past it are moved
  /// out: the smaller it is, the more points cross it together and the longer the cascade of
  /// moves through a pile. With pair moves a box's corners come out together, so 1e-4 leaves a
  /// stack standing straight (stack20 drifts 0.5 mm in 10 s) at half the cost of 1e-5 on rain
  /// and tall pyramids. The lecture preset, which moves one corner at a time, keeps 1e-5: there
  /// a box settles tilted by up to the epsilon over its width, and a 10-box stack leans 5.5 mm
  /// at 1e-4 (docs/micro-collisions.md). Millington's engine uses 0.01.
  /// Range: [0, 1].
  double positionEpsilon = 1e-4;
  /// Velocity resolution may apply at most this many impulses per contact point in a step. A
  /// stack passes weight down one contact at a time: a 10-box stack needs about 200 to hold
  /// still (50 lets it sink and slide 8 cm in 10 s). With passCapWhileProgressing a step still
  /// converging at the cap goes on.
  /// Range: [0, 10000] (more would let one run take hours).
  int velocityIterationsPerContact = 200;
  /// Penetration resolution may resolve at most this many times per contact point in a step.
  /// Range: [0, 1000] (more would let one run take hours).
  int positionIterationsPerContact = 8;
  /// The rotation a penetration move may use, as a fraction of the contact arm: a move of d at
  /// arm r turns the body by at most angularMoveLimit·|r| of distance (Millington's 0.2).
  /// Range: [0, 10].
  double angularMoveLimit = 0.2;
  /// Below this |determinant| the contact matrix counts as singular (frictionless fallback).
  /// Range: [0, 1].
  double singularMatrixTolerance = 1e-12;
  /// m. A point apart by no more than this counts as touching. The penetration phase moves a
  /// resolved point to zero overlap, which the next step's contact reads give or take round-off
  /// (1e-16 m): without it, a row of touching balls that reads −1.7e-16 m at one pair stops the
  /// lecture preset's collision there, and the ball behind pushes its neighbour by moves alone.
  /// A speculative gap closing within the step is judged to the same tolerance, so the two
  /// corners of a face landing flat engage together.
  /// Range: [0, 0.1].
  double touchingTolerance = 1e-9;

  // Refinements of ours, beyond the lecture; each is off in lecture() (docs/micro-collisions.md).

  /// Speculative gaps: a point with a gap counts when the gap would close within the step, and
  /// without a bounce may close it, no more. Off: only touching or penetrating points count.
  bool speculativeGaps = true;
  /// Impulse totals per update: the impulses one update applies at a point add up to one
  /// micro-collision whose total can push but never pull, and a pushed point is resolved again
  /// when pushed too hard. Off: every impulse is the lecture's rule on its own, applied only to
  /// a closing point.
  bool impulseTotals = true;
  /// Worst first also counts, at a point already pushed, being pushed too hard and (while its
  /// friction is static) the slip its neighbours left. Off: only the normal need, as the lecture.
  bool severityCountsPushedPoints = true;
  /// Warm starting: each point starts the step from the totals it ended the last step with,
  /// matched by feature id, so resting weight does not have to pass down a stack one impulse at
  /// a time every step (667 M → 4.5 M instructions per step on pyramid20). Off: zero totals.
  bool warmStarting = true;
  /// Pair impulses: the worst point of a two-point manifold, when both its points touch and need
  /// resolving and the impulse that stops both (both normals and the shared slip, through the
  /// pair's 3×3 contact matrix; frictionless, its two normal rows alone) pushes at both points,
  /// is resolved with its other point in one micro-collision, so a box's two corners do not rock
  /// each other. Beyond the friction cone the pair slides: its tangent total is μ times its
  /// normal total, against the slip, and both normal targets still hold. Otherwise, and when a
  /// bounce is due (unless both bounce, pairBounces), one point. Off: one point at a time.
  bool pairImpulses = true;
  /// Pair bounces: with pair impulses, a two-point manifold whose points both bounce (neither has
  /// yet) bounces as one micro-collision, each point to −c times its closing velocity now, so a
  /// box landing flat leaves straight up. Off: a bounce passes point by point, and the first
  /// corner's impulse spins the box (flat 0.5 m box, e = 0.8, 240 Hz: 3.0 rad/s, 0.93 of e²h).
  bool pairBounces = true;
  /// Pair moves: the deepest point of a two-point manifold is resolved together with the other
  /// point, both penetrations removed by one move of each body (the 2×2 block solve on
  /// penetrations, as the position pass of sequential impulses does), so resolving one corner
  /// neither tilts the body nor drives the other corner deeper. Off: one point at a time.
  bool pairMoves = true;
  /// Past the cap while progressing: a step that reaches velocityIterationsPerContact goes on
  /// while the impulses still make progress, i.e. the total desired velocity change of the
  /// points still waiting fell by at least minimumProgress over the last progressRounds rounds
  /// of one impulse per point, up to velocityIterationsPerContactLimit. A 40-row pyramid's first
  /// step from rest needs 321 impulses per point and converges steadily to the end (the total
  /// falls 1.5 % a round, 26 % over 20); rain's landing steps never converge and creep on at
  /// about 0.5 % a round, so nearly all stop at the cap as before (21 of its 360 steps pass it,
  /// for 0.8 % more impulses). Off: the cap is the lecture's plain count.
  bool passCapWhileProgressing = true;
  /// Rounds of one impulse per point over which progress is measured (at least 1; fewer never
  /// pass the cap).
  /// Range: [1, 10000].
  int progressRounds = 20;
  /// The least fraction by which the waiting total must fall over progressRounds rounds.
  /// Range: [0, 1].
  double minimumProgress = 0.2;
  /// Most impulses per contact point in a step when passing the cap.
  /// Range: [0, 10000] (more would let one run take hours).
  int velocityIterationsPerContactLimit = 1000;
  /// A pair is resolved together only when its matrix is this well conditioned: for a move,
  /// k₀₀² < limit · det K (Box2D 2.4's test); for an impulse, det K > (product of K's diagonal) /
  /// limit. A narrower pair (two points almost at one place) is resolved one point at a time.
  /// Range: [1, 1e+12].
  double pairConditionLimit = 1000.0;

  /// The plain method of the lecture: every refinement above off, and positionEpsilon 1e-5
  /// (one corner at a time needs the tighter epsilon to settle level).
  static MicroCollisionSettings lecture();
};

/// The separating velocity a contact should reach after the solve (contact_math.h,
/// targetSeparatingVelocity): penetration bias and the bounce threshold. Shared by the methods
/// that fix their targets once per step (sequential impulses, the reference).
struct ContactTargetSettings {
  /// Target a small separating velocity that grows with penetration (Baumgarte bias).
  bool penetrationBias = true;
  /// Fraction of the penetration beyond the slop removed per step by the bias velocity.
  /// Range: [0, 1].
  double biasFactor = 0.2;
  /// m. The slop: penetration the bias and the position pass leave alone, so resting contacts
  /// stay touching. Its one home for each solver.
  /// Range: [0, 1].
  double allowedPenetration = 0.005;
  /// m/s. Cap on the bias velocity, so deep overlaps separate without an explosion.
  /// Range: [0, 1000].
  double maxBiasVelocity = 4.0;
  /// m/s. Below this closing speed a contact does not bounce (Box2D 2.4: 1 m/s).
  /// Range: [0, 1000].
  double restitutionVelocityThreshold = 1.0;
};

/// The rules above with penetration bias off: the reference's default.
inline ContactTargetSettings unbiasedTargets() {
  ContactTargetSettings targets;
  targets.penetrationBias = false;
  return targets;
}

/// The position pass (position_correction.h) run after the positions are integrated. It leaves
/// the slop of the solver's ContactTargetSettings alone.
struct PositionPassSettings {
  /// Sweeps of the position pass; 0 turns it off.
  /// Range: [0, 1000] (more would let one run take hours).
  int iterations = 3;
  /// Fraction of the remaining penetration beyond the slop removed per sweep.
  /// Range: [0, 1].
  double correctionFactor = 0.2;
  /// m. Largest correction at one contact in one sweep.
  /// Range: [0, 10].
  double maxCorrection = 0.2;
};

/// Solving the two points of a flat contact together, exactly (two_point_block.h).
struct BlockSolveSettings {
  /// On: both corners at once (Box2D 2.4's block solver). Off: one point at a time, as the text
  /// does; the corner visited first then always gets more, and a tall stack leans and sways.
  bool enabled = true;
  /// A two-point contact is solved as a block only while k₀₀² < this × det K (Box2D's 1000).
  /// Range: [1, 1e+12].
  double conditionLimit = 1000.0;
};

/// Sequential impulses ("Explaining the rigid body solver", Box2D-Lite).
struct SequentialImpulseSettings {
  /// Most sweeps over all contacts per step. A stack of n boxes starting from rest needs about n
  /// sweeps before the weight reaches the bottom within one step, and a 40-row pyramid rests only
  /// with about 40; once a pile rests the sweeps stop after one (convergedImpulseChange).
  /// Range: [0, 10000] (more would let one run take hours).
  int velocityIterations = 40;
  /// The sweeps stop early once a whole sweep changed no impulse (normal or friction) by more
  /// than this fraction of the largest normal total: the answer has converged, and the sweeps
  /// left would not move it. A warm-started pile at rest converges in one sweep; a stack
  /// starting from rest still needs all of them. At 1e-6 the settled drift, penetration and
  /// stack force error equal those of full sweeps to three digits (docs/sequential-impulses.md).
  /// 0 always makes velocityIterations sweeps, the text's method.
  /// Range: [0, 1000].
  double convergedImpulseChange = 1e-6;
  /// Clamp each contact's running total of impulse rather than each impulse.
  bool accumulateImpulses = true;
  /// Begin each step from the last step's totals, matched by feature id (needs accumulation).
  bool warmStarting = true;
  /// Bias and bounce targets.
  ContactTargetSettings targets;
  /// The position pass after integration.
  PositionPassSettings positionPass;
  /// The block solve of two-point contacts' velocities (it needs accumulated impulses).
  BlockSolveSettings block;
  /// The position pass corrects a two-point contact's corners together (true), or one corner at
  /// a time, as Box2D 2.4's position solver does (false).
  bool blockPositionCorrection = true;
  /// Friction before the normal impulses in each contact's solve, as Box2D 2.4 orders them ("non
  /// -penetration is more important than friction", so the normal has the last word in a sweep).
  /// False: the normal first, then friction against it, as Box2D-Lite and the text do. Needs
  /// accumulated impulses (without them friction is capped by this sweep's normal impulse).
  bool frictionFirst = false;

  /// Catto's Box2D-Lite: 10 sweeps to the end, normal then friction, Baumgarte bias 0.2 beyond a
  /// slop of 0.01 m with no cap, no bounce, no block solve, no position pass.
  static SequentialImpulseSettings box2dLite();
  /// Box2D 2.4.1's b2ContactSolver: 8 sweeps to the end, friction first, the block solver, bounce
  /// above 1 m/s and no penetration bias in the velocities; then 3 sweeps of its position solver
  /// one point at a time (0.2 of the penetration beyond 0.005 m, at most 0.2 m).
  static SequentialImpulseSettings box2d24();
};

/// Lemke's complementary pivoting (lcp.h): how it may pivot.
struct LemkeSettings {
  /// The method gives up (and says so) after this many pivots, or after maxPivotsPerVariable
  /// per variable of the problem if that is fewer.
  /// Range: [1, 1000000] (more would let one run take hours).
  int maxPivots = 100000;
  /// A path that reaches a solution takes a few pivots per variable (at most 4 seen, on a
  /// 10-row pyramid's landing); one that round-off sends in circles would run to maxPivots.
  /// Range: [1, 100] (more would let one run take hours).
  int maxPivotsPerVariable = 20;
  /// A column entry must exceed this times the column's largest entry (or 1) to be a pivot:
  /// smaller entries are round-off of zeros, and pivoting on one wrecks the basis inverse.
  /// Range: [0, 1].
  double pivotTolerance = 1e-9;
  /// Ratios closer than this (relative) count as a tie, broken lexicographically.
  /// Range: [0, 1].
  double tieTolerance = 1e-12;
  /// Harris's ratio test (RatioTest::Harris) may overshoot a basic variable by this much,
  /// relative to the largest basic value, to take a larger pivot.
  /// Range: [0, 1].
  double harrisTolerance = 1e-11;
};

/// The active-set method (active_set.h) that solves the reference's large islands.
struct ActiveSetSettings {
  /// Projected Gauss–Seidel sweeps from last step's impulses that guess each point's state
  /// (separated, sticking, sliding) before the first factorization.
  /// Range: [0, 10000] (more would let one run take hours).
  int guessSweeps = 20;
  /// After guessSweeps, the sweeps go on while one still changes a point's state, up to this
  /// many: a pile's first step starts from zero impulses, and its states settle only once the
  /// weight has reached the bottom, about one row a sweep.
  /// Range: [0, 10000] (more would let one run take hours).
  int maxGuessSweeps = 400;
  /// A point solved last step (its impulses and state carried over by feature id) starts in the
  /// state it was solved in; only new points take the state the sweeps guess, and a pile
  /// with no new point skips the sweeps. The sweeps give an unloaded point of a resting pile a
  /// little load, and the first factorization then finds it pulling: on a resting 20-row pyramid
  /// 45–95 such points a step. Off: every point's state comes from the sweeps.
  bool warmStates = true;
  /// The method gives up (and says so) after this many factorizations.
  /// Range: [0, 10000] (more would let one run take hours).
  int maxFactorizations = 200;
  /// Block flips in a row that do not lower the number of violated points before the method
  /// flips one point at a time (Júdice–Pires' safeguard against cycling).
  /// Range: [0, 10000].
  int blockFailures = 3;
  /// A flip that does not lower the number of violated points below the best seen goes back to
  /// the best states and flips half as many of their violators, the worst first, then a
  /// quarter, … down to one (instead of blockFailures more block flips from where it is). From
  /// rest a 40-row pyramid's first step falls to 9 violated points in 7 factorizations, and one
  /// more block flip from there raises it to 316. Off: Júdice–Pires as above.
  bool backtrack = true;
  /// A separated point that the answer closes while it slips takes up sliding against its slip
  /// (λt = ∓μλn), as a contact that starts while slipping does, instead of sticking; a slide
  /// the next answer reverses makes it stick. Forcing such a point to stick can contradict other
  /// states on dependent rows (a regularized self-stress of 1/r's size, flips that undo each
  /// other): of 100 random piles of 8 boxes thrown together, the active set alone answers the
  /// first step of 97 with it and 89 without; of 40 piles of 18 boxes, 30 and 20.
  bool enterSliding = true;
  /// Tikhonov term on each velocity row, relative to its Delassus diagonal: it makes the system
  /// of redundant contacts (a box face's two points, a pyramid) regular. The shift of the
  /// velocities it causes is taken out again by corrections centred on the last answer
  /// (`refinements`).
  /// Range: [0, 1].
  double regularization = 1e-8;
  /// The regularization is centred on the guess (last step's impulses at a point carried over,
  /// the sweeps' at a new one) instead of on zero: a resting pile's answer then needs no
  /// correction after its first solve, and redundant contacts keep the split they had. Off:
  /// centred on zero, the split the first solve chooses.
  bool centreOnGuess = true;
  /// Most corrections on fresh factors that take the regularization's shift out (proximal point
  /// steps; each removes all but about `regularization` of what is left, so one usually does).
  /// On kept factors the corrections may go on for up to keptRounds.
  /// Range: [0, 100] (more would let one run take hours).
  int refinements = 3;
  /// The corrections stop once the residual of the unregularized system is below this fraction
  /// of |b| + |A||x|: a thousandth of residualTolerance, and above the floor that a pile's
  /// redundant rows leave (about 1e-14, rising slowly as a resting pyramid settles).
  /// Range: [0, 1].
  double refinementTolerance = 1e-12;
  /// A condition counts as violated beyond this fraction of the island's impulse scale.
  /// Range: [0, 1].
  double flipTolerance = 1e-12;
  /// The factors of each island's last factorized system are kept, and a step's first system of
  /// the same size is first solved by GMRES preconditioned by them (KeptFactorization): a
  /// resting pile then needs no factorization a step. Off: every system is factorized.
  bool keepFactors = true;
  /// GMRES rounds on kept factors before the system is factorized after all, and then at most as
  /// many corrections that take the regularization out: each costs one solve with the factors,
  /// about 1/30 of a factorization of a 20-row pyramid's system.
  /// Range: [0, 10000] (more would let one run take hours).
  int keptRounds = 8;
  /// Solves with kept factors beyond a system's first solve and first correction (GMRES
  /// rounds, further corrections), summed since the factors were made, after which the next
  /// system is factorized afresh. A factorization of a 40-row pyramid's system costs about 44
  /// solves (35 ms against 0.79 ms), so a pile whose kept factors have drifted from it pays at
  /// most about twice what a factorization at the right moment would cost, and one that rests
  /// on them pays nothing more.
  /// Range: [0, 100000].
  int refactorAfterSolves = 40;
  /// A solve on kept factors is done once the residual of A x = b is below this fraction of
  /// |b| + |A||x| (largest entries, largest row sum): the round-off of a solve on fresh factors.
  /// Range: [0, 1].
  double keptTolerance = 1e-14;
  /// The factorization takes a row's own diagonal entry as its pivot when that entry is at
  /// least this fraction of the largest in its column, so the symmetric fill-reducing order
  /// holds; below, it pivots on the largest. The regularized pivots of a redundant pile are about
  /// `regularization` of their column and must pass; 1 is partial pivoting.
  /// Range: [0, 1].
  double diagonalPivotThreshold = 1e-12;
};

/// The global solve of all contact impulses together: the accuracy reference.
struct ReferenceSolverSettings {
  /// Required residual of the physical conditions (N s), relative to the step's impulse scale:
  /// the largest of the impulses, each point's cancelling impulses and the contact bodies' momenta.
  /// Range: (0, 1].
  double residualTolerance = 1e-9;
  /// Lemke's pivot limit and tolerances; reaching the limit is reported, never silently accepted.
  LemkeSettings lemke;
  /// A resting pile is massively degenerate (many zero velocities); in floating point the
  /// lexicographic rule can then still end on a ray. Lemke is retried once with q moved by
  /// this much (relative to its largest entry, growing along the rows), the textbook remedy;
  /// the answer is checked against the unperturbed problem, so it cannot pass unnoticed.
  /// Range: [0, 0.001].
  double degeneracyPerturbation = 1e-10;
  /// Then Lemke is tried with Harris's ratio test, and then along up to this many other covering
  /// vectors (entries drawn in [0.5, 2) from a fixed seed), each with both ratio tests: every
  /// path ends at a solution in exact arithmetic, but on a landing pile round-off and tiny pivots
  /// end some of them on a ray or an answer the residual check rejects. 0: no such retries.
  /// Range: [0, 100] (more would let one run take hours).
  int coveringRetries = 3;
  /// Islands of up to this many contact points are solved by Lemke; larger ones by the active
  /// set, whose cost grows with the sparse factorization instead of Lemke's points³ (a stack of
  /// 10 boxes has 20 points, a 10-row pyramid 280).
  /// Range: [0, 500] (a larger island would take Lemke minutes each step).
  int lemkeIslandPoints = 40;
  /// A large island on which the active set fails is given to Lemke if it has at most this many
  /// points; larger ones fail with the active set's reason.
  /// Range: [0, 500] (a larger island would take Lemke minutes each step).
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
  /// The position pass corrects a two-point contact's corners together (as sequential impulses).
  BlockSolveSettings positionBlock;
};

/// Box2D 2.4 running the same scene (the behaviour reference): its iteration counts.
struct Box2dSettings {
  /// Box2D's velocity iterations per step (its testbed default).
  /// Range: [0, 1000] (more would let one run take hours).
  int velocityIterations = 8;
  /// Box2D's position iterations per step (its testbed default).
  /// Range: [0, 1000] (more would let one run take hours).
  int positionIterations = 3;
};

/// Soft step (Box2D v3, Catto's Solver2D solve_soft_step; docs/soft-step.md): substeps of soft
/// contact constraints, each a spring-damper of a set stiffness and damping, then relaxation and
/// a restitution pass. The solver moves the bodies itself, substep by substep.
struct SoftStepSettings {
  /// Substeps per world step: velocities, warm start, a solve with bias, positions, a relax
  /// solve. Box2D v3's default: 4.
  /// Range: [1, 1000] (more would let one run take hours).
  int substeps = 4;
  /// Hz. Stiffness of a contact as the frequency it would oscillate at on its own mass
  /// (Box2D v3's contactHertz, 30).
  /// Range: (0, 10000].
  double contactHertz = 30.0;
  /// The stiffness never exceeds this fraction of the substep rate: a spring must be resolved by
  /// several substeps per period (Box2D v3: a quarter).
  /// Range: (0, 1].
  double maxHertzPerSubstepRate = 0.25;
  /// Damping ratio of the contact spring; above 1 it is overdamped and creeps back without
  /// overshoot (Box2D v3's contactDampingRatio, 10).
  /// Range: [0, 10000].
  double dampingRatio = 10.0;
  /// A contact with a static body is this many times stiffer in hertz, so the ground holds the
  /// weight of a pile (Box2D v3: 2).
  /// Range: (0, 100].
  double staticHertzFactor = 2.0;
  /// m/s. Largest speed at which the bias pushes overlapping bodies apart (Box2D v3's
  /// contactPushMaxVelocity, 3).
  /// Range: [0, 1000].
  double maxPushVelocity = 3.0;
  /// Soft constraints: bias rate, mass scale and impulse scale from hertz and damping ratio. Off:
  /// the rigid limit (infinite hertz): bias rate 1/h, mass scale 1, impulse scale 0, so each
  /// substep tries to remove the whole overlap.
  bool softContacts = true;
  /// A second solve after the positions moved, without bias, removing the velocity the bias added
  /// (Box2D v3's relax). Off: that velocity stays and the body overshoots.
  bool relax = true;
  /// Friction only in the relax solve, against the normal impulses left once the bias is gone
  /// (Box2D v3 since 2025); off, in both solves of each substep (Solver2D, v3.0). With relax off
  /// friction is always in the one solve there is. Without contact recycling a 40-box stack
  /// stands about twice as long with it; it leans on warm starting, which carries friction between
  /// substeps (without both, the demo's 10-box stack falls; docs/soft-step.md).
  bool frictionInRelax = true;
  /// Begin each step from the last step's impulses (by feature id) and each substep from the last
  /// substep's. Off: every substep starts from zero.
  bool warmStarting = true;
  /// Speculative contacts whatever the world's speculative_contacts says, as Box2D v3 always
  /// has them: a falling body's contact is found the step before it lands, so the solve stops it
  /// at the surface instead of finding it overlapping. Off (and the world's off): a 12 m/s ball
  /// tunnels through a 0.1 m wall, and a box dropped 0.2 m onto a 20° slope with μ 0.49 slides
  /// 8 cm after it lands (0.2 cm with them on; docs/soft-step.md, "A landing that one iteration
  /// per substep does not finish").
  bool speculativeContacts = true;
  /// Contact recycling, as Box2D v3 has it by default: a pair's manifold is kept from step to step
  /// while the bodies move little relative to each other (recycleDistance, recycleLargestTurn);
  /// its normal and its arms stay as found, unturned, and only each point's overlap follows the
  /// bodies, as within the substeps. The Jacobians then do not turn with a leaning box, and a
  /// 40-box stack at the defaults stands (top within 0.11 m of the axis for 10 s). Off: every
  /// step finds the manifold anew, its arms turn with the boxes, and the column buckles in an S
  /// and falls between 6 and 10 s (docs/soft-step.md).
  bool contactRecycling = true;
  /// Round surfaces: within a step a circle's contact moves with the circle's centre alone, since
  /// its surface under the contact is the same however it turns, and a contact found across a gap
  /// acts where the circle will touch, not in the middle of the gap. Off: every arm turns with its
  /// body, as Box2D v3's solver takes it for every shape; a circle's arm then lifts off the
  /// surface by r(1 − cos Δθ) as it rolls, the contact reads a gap, and a disc of 0.1 m rolling
  /// down 30° at 60 Hz (turning 0.5–1.6 rad a step) accelerates 3.2 % below (2/3) g sin θ; and
  /// a 5 cm disc glancing off a wall turns about a lever up to half the margin too long (3 % too
  /// fast along the wall at 15,360 Hz; docs/soft-step.md).
  bool roundSurfaces = true;
  /// m. A manifold is found anew once B has moved this far relative to A since it was found,
  /// counting the turn of the farther-reaching body at its largest extent (Box2D v3: 10 × its
  /// linear slop of 0.005 m).
  /// Range: [0, 1].
  double recycleDistance = 0.05;
  /// rad. A manifold is also found anew once either body has turned this far since it was found
  /// (Box2D v3: cosine above 0.98, about 11.5°).
  /// Range: [0, 3.14159].
  double recycleLargestTurn = 0.2;
  /// Recycle within the found distance, ours beyond Box2D v3: a one-point manifold (a vertex or
  /// a circle on a face) is also found anew once the bodies have moved, as recycleDistance counts
  /// it, as far as the contact distance it was found within (the margin plus the speculative
  /// reach), so the next vertex of a polygon pivoting on one cannot reach the surface unseen. A
  /// two-point manifold keeps recycleDistance: its polygon's next vertex is an exterior angle of
  /// turning away (45° for a regular octagon), beyond recycleLargestTurn. Off: v3's
  /// recycleDistance for all, and a pentagon rolling over its vertices lands its next vertex up to
  /// 2.4 cm deep (240 Hz; 3.4e-4 m with it on).
  bool recycleWithinFoundDistance = true;
  /// Recycle in the world's frame, ours beyond Box2D v3: B's movement since the manifold was
  /// found is measured in the world's frame, where the kept normal and arms live, not in A's, so
  /// a pair that turns together by θ at a distance d between centres counts as moving d θ. Off
  /// (v3): such a pair never moves, its unturned arms read a slip that is not there, and friction
  /// holding that slip drags the top body outward by about d θ² / 2: a box 1.5 m out on a seesaw
  /// turning 0.18 rad crept 2.5 cm along it and the plank turned 18 % too slowly (5 mm and 8 %
  /// with it on; docs/soft-step.md).
  bool recycleInWorldFrame = true;
  /// Renew round normals, ours beyond Box2D v3: a manifold whose normal runs to a circle's centre
  /// from a polygon's vertex or another circle's centre is found anew every step, since that
  /// normal turns as the bodies move past each other (by the distance moved over the radius),
  /// where a face's turns only with its body. Off (v3 recycles them): a disc rolling over a
  /// table's edge pivots on a normal up to the recycle distance old and leaves with its speed
  /// 1.8 % off however small the step (0.03 % at 3,840 Hz with it on; docs/soft-step.md).
  bool renewRoundNormals = true;
  /// After the substeps, one pass that makes a closing contact separate at −e times its closing
  /// speed before the step (Box2D v3's b2ApplyRestitution). Off: soft contacts do not bounce.
  bool restitution = true;
  /// m/s. Below this closing speed a contact does not bounce (Box2D v3: 1 m/s).
  /// Range: [0, 1000].
  double restitutionVelocityThreshold = 1.0;
  /// Pair restitution, ours beyond Box2D v3: a two-point manifold whose points both bounce gets
  /// their restitution impulses together, its 2×2 block of normals solved exactly on the
  /// accumulated impulses (two_point_block.h), so a box landing flat leaves straight up at e times
  /// its closing speed. Off: v3's one pass point by point, in which the first corner's impulse
  /// turns the box and the second corner's then partly undoes the bounce (a flat 1 × 0.5 box
  /// dropped 1 m at 60 Hz, e 0.8, rose to 0.37 of e²h spinning at 2.5 rad/s; docs/soft-step.md).
  BlockSolveSettings pairRestitution;
  /// Friction in the restitution pass, ours beyond Box2D v3: a contact that bounces gets one
  /// friction solve after its bounce, bounded by μ times its normal impulse with the bounce in
  /// it, so an impact's friction can take μ (1 + e) times the closing impulse, Newton's and
  /// Coulomb's laws together. Off (v3): friction only against the compression, so a disc thrown
  /// at a wall (45°, e 0.5, μ 0.3) keeps 5 % too much of its slide, and one that a speculative
  /// contact stops a few millimetres short of the wall bounces with hardly any friction at all
  /// (docs/soft-step.md).
  bool frictionInRestitution = true;
  /// Restitution on the step's totals, ours beyond Box2D v3: a bounce keeps the impulse applied
  /// at its point over the whole step non-negative, so it can take back what any substep pushed
  /// there, as the rigid methods' accumulated impulses can. Off (v3): it can take back only the
  /// last substep's, so a corner pushed in earlier substeps, and then driven apart by the other
  /// corner's bounce, keeps separating faster than its own bounce: a frictionless elastic impact
  /// of two polygons gained up to 25 % of its energy (35 of 2,000 random impacts above 1 % at
  /// 60 Hz; with it on, 4, up to 3.2 %, as the reference's 3.3 %; docs/soft-step.md).
  bool restitutionOnStepTotals = true;

  /// Box2D v3's soft step as published: every refinement marked "ours beyond Box2D v3" off.
  static SoftStepSettings box2dV3();
};

/// The settings of every solver; a scene picks one solver, and its [solver] table sets that
/// solver's struct.
struct SolverSettings {
  MicroCollisionSettings micro;
  SequentialImpulseSettings sequential;
  ReferenceSolverSettings reference;
  Box2dSettings box2d;
  SoftStepSettings softStep;
};

/// One named field of a settings struct, for setting it by name from a scene file or the command
/// line and for listing it in `i2d check`.
struct SettingField {
  std::string name;  ///< snake_case, as in scene files
  std::variant<double*, int*, bool*, Vec2*> value;
};

std::vector<SettingField> describe(WorldSettings& settings);
std::vector<SettingField> describe(MicroCollisionSettings& settings);
std::vector<SettingField> describe(SequentialImpulseSettings& settings);
std::vector<SettingField> describe(ReferenceSolverSettings& settings);
std::vector<SettingField> describe(Box2dSettings& settings);
std::vector<SettingField> describe(SoftStepSettings& settings);

}  // namespace impulse2d
