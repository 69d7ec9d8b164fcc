// The settings fields by their scene-file names.
#include "impulse2d/settings.h"

namespace impulse2d {

std::vector<SettingField> describe(WorldSettings& s) {
  return {{"gravity", &s.gravity},
          {"dt", &s.dt},
          {"contact_margin", &s.contactMargin},
          {"substeps", &s.substeps},
          {"speculative_contacts", &s.speculativeContacts},
          {"continuous", &s.continuous},
          {"refuse_internal_edges", &s.refuseInternalEdges},
          {"sleeping", &s.sleeping},
          {"sleep_linear_speed", &s.sleepLinearSpeed},
          {"sleep_angular_speed", &s.sleepAngularSpeed},
          {"time_to_sleep", &s.timeToSleep},
          {"keep_speeding_up_awake", &s.keepSpeedingUpAwake},
          {"speed_up_share", &s.speedUpShare}};
}

MicroCollisionSettings MicroCollisionSettings::lecture() {
  MicroCollisionSettings settings;
  settings.speculativeGaps = false;
  settings.impulseTotals = false;
  settings.severityCountsPushedPoints = false;
  settings.warmStarting = false;
  settings.pairImpulses = false;
  settings.pairBounces = false;
  settings.pairMoves = false;
  settings.passCapWhileProgressing = false;
  settings.positionEpsilon = 1e-5;
  return settings;
}

std::vector<SettingField> describe(MicroCollisionSettings& s) {
  return {{"remove_acceleration_velocity", &s.removeAccelerationVelocity},
          {"lower_restitution_at_low_speed", &s.lowerRestitutionAtLowSpeed},
          {"restitution_velocity_limit", &s.restitutionVelocityLimit},
          {"friction", &s.friction},
          {"velocity_epsilon", &s.velocityEpsilon},
          {"position_epsilon", &s.positionEpsilon},
          {"velocity_iterations_per_contact", &s.velocityIterationsPerContact},
          {"position_iterations_per_contact", &s.positionIterationsPerContact},
          {"angular_move_limit", &s.angularMoveLimit},
          {"singular_matrix_tolerance", &s.singularMatrixTolerance},
          {"touching_tolerance", &s.touchingTolerance},
          {"speculative_gaps", &s.speculativeGaps},
          {"impulse_totals", &s.impulseTotals},
          {"severity_counts_pushed_points", &s.severityCountsPushedPoints},
          {"warm_starting", &s.warmStarting},
          {"pair_impulses", &s.pairImpulses},
          {"pair_bounces", &s.pairBounces},
          {"pair_moves", &s.pairMoves},
          {"pass_cap_while_progressing", &s.passCapWhileProgressing},
          {"progress_rounds", &s.progressRounds},
          {"minimum_progress", &s.minimumProgress},
          {"velocity_iterations_per_contact_limit", &s.velocityIterationsPerContactLimit},
          {"pair_condition_limit", &s.pairConditionLimit}};
}

namespace {

/// The shared nested structs keep the flat scene-file names they always had.
void addFields(std::vector<SettingField>& fields, ContactTargetSettings& s) {
  fields.insert(fields.end(),
                {{"penetration_bias", &s.penetrationBias},
                 {"bias_factor", &s.biasFactor},
                 {"allowed_penetration", &s.allowedPenetration},
                 {"max_bias_velocity", &s.maxBiasVelocity},
                 {"restitution_velocity_threshold", &s.restitutionVelocityThreshold}});
}

void addFields(std::vector<SettingField>& fields, PositionPassSettings& s) {
  fields.insert(fields.end(), {{"position_iterations", &s.iterations},
                               {"position_correction_factor", &s.correctionFactor},
                               {"max_position_correction", &s.maxCorrection}});
}

}  // namespace

namespace {

/// m/s. A speed no contact reaches, the top of the settings' range: a cap or threshold that never
/// acts.
constexpr double kNoLimit = 1000.0;

}  // namespace

SequentialImpulseSettings SequentialImpulseSettings::box2dLite() {
  SequentialImpulseSettings settings;
  settings.velocityIterations = 10;
  settings.convergedImpulseChange = 0.0;
  settings.targets.allowedPenetration = 0.01;
  settings.targets.maxBiasVelocity = kNoLimit;               // Box2D-Lite caps no bias
  settings.targets.restitutionVelocityThreshold = kNoLimit;  // and has no bounce
  settings.positionPass.iterations = 0;
  settings.block.enabled = false;
  settings.blockPositionCorrection = false;
  return settings;
}

SequentialImpulseSettings SequentialImpulseSettings::box2d24() {
  SequentialImpulseSettings settings;
  settings.velocityIterations = 8;
  settings.convergedImpulseChange = 0.0;
  settings.frictionFirst = true;
  settings.targets.penetrationBias = false;
  settings.blockPositionCorrection = false;
  return settings;
}

std::vector<SettingField> describe(SequentialImpulseSettings& s) {
  std::vector<SettingField> fields = {{"velocity_iterations", &s.velocityIterations},
                                      {"converged_impulse_change", &s.convergedImpulseChange},
                                      {"accumulate_impulses", &s.accumulateImpulses},
                                      {"warm_starting", &s.warmStarting}};
  addFields(fields, s.targets);
  addFields(fields, s.positionPass);
  fields.insert(fields.end(), {{"block_solver", &s.block.enabled},
                               {"block_condition_limit", &s.block.conditionLimit},
                               {"block_position_correction", &s.blockPositionCorrection},
                               {"friction_first", &s.frictionFirst}});
  return fields;
}

std::vector<SettingField> describe(ReferenceSolverSettings& s) {
  std::vector<SettingField> fields = {
      {"residual_tolerance", &s.residualTolerance},
      {"max_pivots", &s.lemke.maxPivots},
      {"max_pivots_per_variable", &s.lemke.maxPivotsPerVariable},
      {"pivot_tolerance", &s.lemke.pivotTolerance},
      {"tie_tolerance", &s.lemke.tieTolerance},
      {"degeneracy_perturbation", &s.degeneracyPerturbation},
      {"covering_retries", &s.coveringRetries},
      {"harris_tolerance", &s.lemke.harrisTolerance},
      {"lemke_island_points", &s.lemkeIslandPoints},
      {"lemke_fallback_points", &s.lemkeFallbackPoints},
      {"restitution_in_two_solves", &s.restitutionInTwoSolves},
      {"guess_sweeps", &s.activeSet.guessSweeps},
      {"max_guess_sweeps", &s.activeSet.maxGuessSweeps},
      {"warm_states", &s.activeSet.warmStates},
      {"keep_factors", &s.activeSet.keepFactors},
      {"kept_rounds", &s.activeSet.keptRounds},
      {"kept_tolerance", &s.activeSet.keptTolerance},
      {"refactor_after_solves", &s.activeSet.refactorAfterSolves},
      {"diagonal_pivot_threshold", &s.activeSet.diagonalPivotThreshold},
      {"max_factorizations", &s.activeSet.maxFactorizations},
      {"block_failures", &s.activeSet.blockFailures},
      {"backtrack", &s.activeSet.backtrack},
      {"enter_sliding", &s.activeSet.enterSliding},
      {"regularization", &s.activeSet.regularization},
      {"centre_on_guess", &s.activeSet.centreOnGuess},
      {"refinements", &s.activeSet.refinements},
      {"refinement_tolerance", &s.activeSet.refinementTolerance},
      {"flip_tolerance", &s.activeSet.flipTolerance}};
  addFields(fields, s.targets);
  addFields(fields, s.positionPass);
  fields.insert(fields.end(), {{"block_position_correction", &s.positionBlock.enabled},
                               {"block_condition_limit", &s.positionBlock.conditionLimit}});
  return fields;
}

std::vector<SettingField> describe(Box2dSettings& s) {
  return {{"velocity_iterations", &s.velocityIterations},
          {"position_iterations", &s.positionIterations}};
}

SoftStepSettings SoftStepSettings::box2dV3() {
  SoftStepSettings settings;
  settings.roundSurfaces = false;
  settings.speculativeAtTouch = false;
  settings.recycleWithinFoundDistance = false;
  settings.recycleInWorldFrame = false;
  settings.renewRoundNormals = false;
  settings.pairRestitution.enabled = false;
  settings.frictionInRestitution = false;
  settings.restitutionOnStepTotals = false;
  return settings;
}

std::vector<SettingField> describe(SoftStepSettings& s) {
  return {{"substeps", &s.substeps},
          {"contact_hertz", &s.contactHertz},
          {"max_hertz_per_substep_rate", &s.maxHertzPerSubstepRate},
          {"damping_ratio", &s.dampingRatio},
          {"static_hertz_factor", &s.staticHertzFactor},
          {"max_push_velocity", &s.maxPushVelocity},
          {"soft_contacts", &s.softContacts},
          {"relax", &s.relax},
          {"friction_in_relax", &s.frictionInRelax},
          {"warm_starting", &s.warmStarting},
          {"speculative_contacts", &s.speculativeContacts},
          {"contact_recycling", &s.contactRecycling},
          {"round_surfaces", &s.roundSurfaces},
          {"speculative_at_touch", &s.speculativeAtTouch},
          {"recycle_distance", &s.recycleDistance},
          {"recycle_largest_turn", &s.recycleLargestTurn},
          {"recycle_within_found_distance", &s.recycleWithinFoundDistance},
          {"recycle_in_world_frame", &s.recycleInWorldFrame},
          {"friction_in_restitution", &s.frictionInRestitution},
          {"restitution_on_step_totals", &s.restitutionOnStepTotals},
          {"renew_round_normals", &s.renewRoundNormals},
          {"restitution", &s.restitution},
          {"restitution_velocity_threshold", &s.restitutionVelocityThreshold},
          {"pair_restitution", &s.pairRestitution.enabled},
          {"pair_restitution_condition_limit", &s.pairRestitution.conditionLimit}};
}

}  // namespace impulse2d
