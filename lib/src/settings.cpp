// The declaration of every setting: its scene-file name, the field it sets, its unit, its range
// and its meaning. The scene loader checks values against these ranges, `i2d check` lists these
// fields, and a test requires docs/scene-format.md's tables to be these rows.
#include "impulse2d/settings.h"

#include <sstream>

#include "impulse2d/math.h"

namespace impulse2d {
namespace {

/// The reason given for the upper bound of a count that multiplies the work of a step.
const std::string kWork = "more would let one run take hours";
/// The reason given for Lemke's island size: a pivot costs points², a path points³.
const std::string kCubic = "Lemke's pivots on a larger island would take minutes each step";
/// A switch or a vector: no range.
const std::optional<SettingRange> kNone;

std::string formatBound(double value, bool integer) {
  std::ostringstream text;
  if (integer) {
    text << static_cast<long long>(value);
  } else {
    text << value;
  }
  return text.str();
}

}  // namespace

SettingRange closed(double lowest, double highest, const std::string& bound) {
  return {lowest, true, highest, bound};
}

SettingRange aboveZero(double highest) {
  return {0.0, false, highest, {}};
}

bool inSettingRange(double value, const SettingRange& range) {
  const bool aboveLowest = range.lowestIncluded ? value >= range.lowest : value > range.lowest;
  return aboveLowest && value <= range.highest;
}

std::string SettingChoice::listed() const {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

std::string describeSettingRange(const SettingRange& range, bool integer, double value) {
  std::string text = std::string("must be ") + (integer ? "an integer " : "") + "in " +
                     (range.lowestIncluded ? "[" : "(") + formatBound(range.lowest, integer) +
                     ", " + formatBound(range.highest, integer) + "]";
  if (value > range.highest && !range.bound.empty()) text += " (" + range.bound + ")";
  return text;
}

std::vector<SettingField> describe(WorldSettings& s) {
  return {
      {"gravity", &s.gravity, "m/s²", kNone, "acceleration of every dynamic body"},
      {"dt", &s.dt, "s", closed(1e-6, 1.0), "the fixed time step"},
      {"contact_margin", &s.contactMargin, "m", closed(0.0, 1.0),
       "contact points are kept while surfaces are closer than this; keep it above micro's "
       "`velocity_epsilon` × `dt`, or resting contacts flicker (`contact-generation.md`)"},
      {"substeps", &s.substeps, "", closed(1, 1000, kWork),
       "each step runs the whole pipeline this many times with `dt/substeps`"},
      {"speculative_contacts", &s.speculativeContacts, "", kNone,
       "find contacts `‖vB − vA‖·dt` early, so a fast small body cannot tunnel "
       "(`rigid-bodies.md`); soft step has them whatever this says, unless its own "
       "`speculative_contacts` is false"},
      {"continuous", &s.continuous, "", kNone,
       "a body whose substep would carry its core (half its smallest extent) into a static body "
       "is stopped where it reaches it, so a small fast body cannot tunnel (`rigid-bodies.md`)"},
      {"refuse_internal_edges", &s.refuseInternalEdges, "", kNone,
       "refuse contacts on the internal edges of static pieces laid flush, so a body crossing the "
       "seam of two floor tiles meets one surface (`contact-generation.md`)"},
      {"sleep", choice(s.sleep, {"off", "box2d", "keep_speeding_up_awake"}), "", kNone,
       "islands at rest sleep: not integrated, contacts neither recomputed nor solved; `box2d`: "
       "a body slower than the thresholds rests; `keep_speeding_up_awake`: and its speed grew by "
       "less than `speed_up_share` of them since its rest began (ours; Box2D's rule freezes a "
       "slowly starting body; `sleeping.md`)"},
      {"sleep_linear_speed", &s.sleepLinearSpeed, "m/s", closed(0.0, 100.0),
       "a body slower than this (and the angular speed) counts as resting"},
      {"sleep_angular_speed", &s.sleepAngularSpeed, "rad/s", closed(0.0, 100.0),
       "the angular speed below which a body counts as resting (2°/s)"},
      {"time_to_sleep", &s.timeToSleep, "s", closed(0.0, 1e6),
       "an island sleeps once all its bodies have rested this long"},
      {"speed_up_share", &s.speedUpShare, "", closed(0.0, 1.0),
       "that share under `keep_speeding_up_awake`: 1 mm/s and 0.2°/s at the default "
       "thresholds"}};
}

MicroCollisionSettings MicroCollisionSettings::lecture() {
  MicroCollisionSettings settings;
  settings.speculativeGaps = false;
  settings.impulses = MicroCollisionImpulses::Separate;
  settings.severityCountsPushedPoints = false;
  settings.warmStarting = false;
  settings.blockMoves = false;
  settings.passCapWhileProgressing = false;
  settings.positionEpsilon = 1e-5;
  return settings;
}

std::vector<SettingField> describe(MicroCollisionSettings& s) {
  return {
      {"remove_acceleration_velocity", &s.removeAccelerationVelocity, "", kNone,
       "take the velocity the last update's acceleration built up out of the bounce target"},
      {"lower_restitution_at_low_speed", &s.lowerRestitutionAtLowSpeed, "", kNone,
       "no bounce below `restitution_threshold`"},
      {"restitution_threshold", &s.restitutionThreshold, "m/s", closed(0.0, 1000.0),
       "below this closing speed a contact does not bounce (Millington: 0.25)"},
      {"friction", &s.friction, "", kNone,
       "friction through the 2×2 contact matrix; off: frictionless normal impulses"},
      {"velocity_epsilon", &s.velocityEpsilon, "m/s", closed(0.0, 1.0),
       "velocity resolution stops when no contact needs a larger change"},
      {"position_epsilon", &s.positionEpsilon, "m", closed(0.0, 1.0),
       "penetration resolution stops when no contact is deeper than this"},
      {"velocity_iterations_per_contact", &s.velocityIterationsPerContact, "",
       closed(0, 10000, kWork), "most impulses per contact point in a step"},
      {"position_iterations_per_contact", &s.positionIterationsPerContact, "",
       closed(0, 1000, kWork), "most penetration moves per contact point in a step"},
      {"angular_move_limit", &s.angularMoveLimit, "", closed(0.0, 10.0),
       "the share of a move that rotation may take, per metre of contact arm (Millington: 0.2)"},
      {"singular_matrix_tolerance", &s.singularMatrixTolerance, "", closed(0.0, 1.0),
       "below this |determinant| the contact matrix is singular (frictionless fallback)"},
      {"touching_tolerance", &s.touchingTolerance, "m", closed(0.0, 0.1),
       "a point apart by no more than this counts as touching"},
      {"speculative_gaps", &s.speculativeGaps, "", kNone,
       "a gap that would close within the step counts, and may close, no more (ours)"},
      {"impulses", choice(s.impulses, {"separate", "point_totals", "block", "block_with_bounces"}),
       "", kNone,
       "`separate`: each impulse is the lecture's rule alone; ours: `point_totals`, an update's "
       "impulses at a point add up to one micro-collision that never pulls; `block`, and a "
       "two-point manifold's worst point is resolved with its other point; `block_with_bounces`, "
       "and its points bounce as one"},
      {"severity_counts_pushed_points", &s.severityCountsPushedPoints, "", kNone,
       "worst first also counts a pushed point's overpush and slip (ours)"},
      {"warm_starting", &s.warmStarting, "", kNone,
       "each point starts the step from its last totals, by feature id (ours)"},
      {"block_moves", &s.blockMoves, "", kNone,
       "a two-point manifold's penetrations are removed by one move (ours)"},
      {"pass_cap_while_progressing", &s.passCapWhileProgressing, "", kNone,
       "a step at the impulse cap goes on while it still progresses (ours)"},
      {"progress_rounds", &s.progressRounds, "", closed(1, 10000),
       "rounds of one impulse per point over which progress is measured"},
      {"minimum_progress", &s.minimumProgress, "", closed(0.0, 1.0),
       "the least fraction the waiting total must fall over those rounds"},
      {"velocity_iterations_per_contact_limit", &s.velocityIterationsPerContactLimit, "",
       closed(0, 10000, kWork), "most impulses per contact point when passing the cap"},
      {"block_condition_limit", &s.blockConditionLimit, "", closed(1.0, 1e12),
       "a block is resolved together only when its matrix is this well conditioned"}};
}

namespace {

/// The shared nested structs keep the flat scene-file names they always had.
void addFields(std::vector<SettingField>& fields, ContactTargetSettings& s) {
  fields.insert(fields.end(),
                {{"penetration_bias", &s.penetrationBias, "", kNone,
                  "target a separating velocity that grows with penetration (Baumgarte)"},
                 {"bias_factor", &s.biasFactor, "", closed(0.0, 1.0),
                  "fraction of the penetration beyond the slop the bias removes per step"},
                 {"allowed_penetration", &s.allowedPenetration, "m", closed(0.0, 1.0),
                  "the slop: penetration the bias and the position pass leave alone"},
                 {"max_push_velocity", &s.maxPushVelocity, "m/s", closed(0.0, 1000.0),
                  "cap on the bias velocity"},
                 {"restitution_threshold", &s.restitutionThreshold, "m/s", closed(0.0, 1000.0),
                  "below this closing speed a contact does not bounce"}});
}

void addFields(std::vector<SettingField>& fields, PositionPassSettings& s) {
  fields.insert(fields.end(),
                {{"position_iterations", &s.iterations, "", closed(0, 1000, kWork),
                  "sweeps of the position pass; 0 turns it off"},
                 {"position_correction_factor", &s.correctionFactor, "", closed(0.0, 1.0),
                  "fraction of the penetration beyond the slop removed per sweep"},
                 {"max_position_correction", &s.maxCorrection, "m", closed(0.0, 10.0),
                  "largest correction at one contact in one sweep"},
                 {"block_position_correction", &s.blockSolve, "", kNone,
                  "the position pass corrects a two-point contact's corners together"}});
}

void addFields(std::vector<SettingField>& fields, RecyclingSettings& s) {
  fields.insert(
      fields.end(),
      {{"recycling", choice(s.rule, {"off", "box2d_v3", "refined"}), "", kNone,
        "a manifold is kept as found while the bodies move little (`box2d_v3`); `refined` "
        "(ours): also found anew past the distance a one-point manifold was found within, "
        "measured in the world's frame, and every step when its normal runs to a circle"},
       {"recycle_distance", &s.distance, "m", closed(0.0, 1.0),
        "a manifold is found anew once B has moved this far relative to A"},
       {"recycle_largest_turn", &s.largestTurn, "rad", closed(0.0, kPi),
        "...or once either body has turned this far"}});
}

/// m/s. A speed no contact reaches, the top of the settings' range: a cap or threshold that never
/// acts.
constexpr double kNoLimit = 1000.0;

}  // namespace

SequentialImpulseSettings SequentialImpulseSettings::box2dLite() {
  SequentialImpulseSettings settings;
  settings.velocityIterations = 10;
  settings.convergedImpulseChange = 0.0;
  settings.conjugateGradient = false;
  settings.targets.allowedPenetration = 0.01;
  settings.targets.maxPushVelocity = kNoLimit;       // Box2D-Lite caps no bias
  settings.targets.restitutionThreshold = kNoLimit;  // and has no bounce
  settings.positionPass.iterations = 0;
  settings.block.enabled = false;
  settings.positionPass.blockSolve = false;
  settings.recycling.rule = RecyclingRule::Off;
  return settings;
}

SequentialImpulseSettings SequentialImpulseSettings::box2d24() {
  SequentialImpulseSettings settings;
  settings.velocityIterations = 8;
  settings.convergedImpulseChange = 0.0;
  settings.conjugateGradient = false;
  settings.frictionFirst = true;
  settings.targets.penetrationBias = false;
  settings.positionPass.blockSolve = false;
  settings.recycling.rule = RecyclingRule::Off;
  return settings;
}

std::vector<SettingField> describe(SequentialImpulseSettings& s) {
  std::vector<SettingField> fields = {
      {"velocity_iterations", &s.velocityIterations, "", closed(0, 10000, kWork),
       "most sweeps over all contacts per step"},
      {"converged_impulse_change", &s.convergedImpulseChange, "", closed(0.0, 1000.0),
       "the sweeps stop once none changed an impulse by more than this share of the largest"},
      {"impulses", choice(s.impulses, {"clamped_each", "accumulated", "warm_started"}), "", kNone,
       "`clamped_each`: each impulse clamped alone; `accumulated`: each contact's running total "
       "clamped; `warm_started`: and each step begins from the last step's totals, by feature "
       "id"}};
  addFields(fields, s.targets);
  addFields(fields, s.positionPass);
  fields.insert(fields.end(),
                {{"block_solver", &s.block.enabled, "", kNone,
                  "solve a two-point contact's velocities as one block (Box2D 2.4)"},
                 {"block_condition_limit", &s.block.conditionLimit, "", closed(1.0, 1e12),
                  "a two-point contact is a block only while k₀₀² < this × det K"},
                 {"friction_first", &s.frictionFirst, "", kNone,
                  "friction before the normal impulses in each contact's solve (Box2D 2.4)"},
                 {"conjugate_gradient", &s.conjugateGradient, "", kNone,
                  "after each sweep, push the impulses on along the sweeps' direction "
                  "(nonsmooth conjugate gradient)"}});
  addFields(fields, s.recycling);
  return fields;
}

std::vector<SettingField> describe(ReferenceSolverSettings& s) {
  ActiveSetSettings& a = s.activeSet;
  std::vector<SettingField> fields = {
      {"residual_tolerance", &s.residualTolerance, "", aboveZero(1.0),
       "required residual of the physical conditions, relative to the step's impulse scale"},
      {"max_pivots", &s.lemke.maxPivots, "", closed(1, 1000000, kWork),
       "Lemke gives up after this many pivots"},
      {"max_pivots_per_variable", &s.lemke.maxPivotsPerVariable, "", closed(1, 100, kWork),
       "...or after this many per variable, if fewer"},
      {"lemke_island_points", &s.lemkeIslandPoints, "", closed(0, 500, kCubic),
       "islands of up to this many points are solved by Lemke, larger by the active set"},
      {"lemke_fallback_points", &s.lemkeFallbackPoints, "", closed(0, 500, kCubic),
       "an island the active set fails on goes to Lemke if it has at most this many points"},
      {"restitution_in_two_solves", &s.restitutionInTwoSolves, "", kNone,
       "an island whose bounce targets have no answer bounces by Poisson's law in two solves"},
      {"guess_sweeps", &a.guessSweeps, "", closed(0, 10000, kWork),
       "projected Gauss–Seidel sweeps that guess each point's state, more while one changes it"},
      {"warm_states", &a.warmStates, "", kNone,
       "a point solved last step starts in the state it was solved in"},
      {"keep_factors", &a.keepFactors, "", kNone,
       "keep the last factors and first try GMRES preconditioned by them"},
      {"refactor_after_solves", &a.refactorAfterSolves, "", closed(0, 100000),
       "solves on kept factors after which the next system is factorized afresh"},
      {"max_factorizations", &a.maxFactorizations, "", closed(0, 10000, kWork),
       "the active set gives up after this many factorizations"},
      {"cycling_safeguard", choice(a.cyclingSafeguard, {"judice_pires", "backtrack"}), "", kNone,
       "after a flip that does not help: `judice_pires`, more block flips, then one point at a "
       "time; `backtrack`, back to the best states, flipping half as many"},
      {"enter_sliding", &a.enterSliding, "", kNone,
       "a separated point the answer closes while it slips starts sliding, not sticking"},
      {"regularization", &a.regularization, "", closed(0.0, 1.0),
       "Tikhonov term on each velocity row, relative to its Delassus diagonal"},
      {"centre_on_guess", &a.centreOnGuess, "", kNone,
       "the regularization is centred on the guess instead of on zero"},
      {"refinements", &a.refinements, "", closed(0, 100, kWork),
       "most corrections that take the regularization's shift out"}};
  addFields(fields, s.targets);
  addFields(fields, s.positionPass);
  fields.insert(fields.end(),
                {{"block_condition_limit", &s.blockConditionLimit, "", closed(1.0, 1e12),
                  "a two-point contact is a block only while k₀₀² < this × det K"}});
  return fields;
}

std::vector<SettingField> describe(Box2dSettings& s) {
  return {{"velocity_iterations", &s.velocityIterations, "", closed(0, 1000, kWork),
           "Box2D's velocity iterations per step"},
          {"position_iterations", &s.positionIterations, "", closed(0, 1000, kWork),
           "Box2D's position iterations per step"}};
}

SoftStepSettings SoftStepSettings::box2dV3() {
  SoftStepSettings settings;
  settings.roundSurfaces = false;
  settings.speculativeAtTouch = false;
  settings.recycling.rule = RecyclingRule::Box2dV3;
  settings.restitutionBlock.enabled = false;
  settings.frictionInRestitution = false;
  settings.restitutionOnStepTotals = false;
  return settings;
}

std::vector<SettingField> describe(SoftStepSettings& s) {
  std::vector<SettingField> fields = {
      {"substeps", &s.substeps, "", closed(1, 1000, kWork), "substeps per world step (v3: 4)"},
      {"contact_hertz", &s.contactHertz, "Hz", aboveZero(1e4),
       "a contact's stiffness as the frequency it rings at (v3: 30)"},
      {"max_hertz_per_substep_rate", &s.maxHertzPerSubstepRate, "", aboveZero(1.0),
       "the stiffness never exceeds this share of the substep rate (v3: 0.25)"},
      {"damping_ratio", &s.dampingRatio, "", closed(0.0, 1e4),
       "the contact spring's damping ratio (v3: 10)"},
      {"static_hertz_factor", &s.staticHertzFactor, "", aboveZero(100.0),
       "contacts with a static body are this many times stiffer (v3: 2)"},
      {"max_push_velocity", &s.maxPushVelocity, "m/s", closed(0.0, 1000.0),
       "the fastest the bias pushes overlapping bodies apart (v3: 3)"},
      {"soft_contacts", &s.softContacts, "", kNone,
       "soft constraints from hertz and damping; off: the rigid limit"},
      {"relaxation", choice(s.relaxation, {"off", "friction_in_both", "friction_in_relax"}), "",
       kNone,
       "a solve without bias after the positions moved (v3's relax), friction in both solves "
       "(v3.0) or in the relax solve only (v3 since 2025)"},
      {"warm_starting", &s.warmStarting, "", kNone,
       "each step and substep starts from the last impulses"},
      {"speculative_contacts", &s.speculativeContacts, "", kNone,
       "speculative contacts whatever the world says, as v3 always has them"},
      {"round_surfaces", &s.roundSurfaces, "", kNone,
       "a circle's contact follows its centre and acts where it will touch (ours)"},
      {"speculative_at_touch", &s.speculativeAtTouch, "", kNone,
       "a speculative round contact takes its normal from where the two will touch (ours)"},
      {"friction_in_restitution", &s.frictionInRestitution, "", kNone,
       "one friction solve after a bounce (ours)"},
      {"restitution_on_step_totals", &s.restitutionOnStepTotals, "", kNone,
       "a bounce may take back what any substep pushed at its point (ours)"},
      {"restitution", &s.restitution, "", kNone, "a restitution pass after the substeps (v3)"},
      {"restitution_threshold", &s.restitutionThreshold, "m/s", closed(0.0, 1000.0),
       "below this closing speed a contact does not bounce (v3: 1)"},
      {"block_restitution", &s.restitutionBlock.enabled, "", kNone,
       "a two-point manifold whose points both bounce gets one 2×2 block of impulses (ours)"},
      {"block_condition_limit", &s.restitutionBlock.conditionLimit, "", closed(1.0, 1e12),
       "...only while k₀₀² < this × det K"}};
  addFields(fields, s.recycling);
  return fields;
}

}  // namespace impulse2d
