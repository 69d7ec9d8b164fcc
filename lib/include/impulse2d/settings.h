// Every tunable number of the engine, gathered: the world's and the shared contact rules
// (shared_settings.h), each method's own struct beside it (solvers/*_settings.h), and Box2D's
// iteration counts. A scene file's [world] and [solver] tables set their fields by name.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "impulse2d/shared_settings.h"
#include "impulse2d/solvers/micro_collision_settings.h"
#include "impulse2d/solvers/reference_solver_settings.h"
#include "impulse2d/solvers/sequential_impulse_settings.h"
#include "impulse2d/solvers/soft_step_settings.h"

namespace impulse2d {

/// Box2D 2.4 running the same scene (the behaviour reference): its iteration counts.
struct Box2dSettings {
  /// Box2D's velocity iterations per step (its testbed default).
  /// Range: [0, 1000] (more would let one run take hours).
  int velocityIterations = 8;
  /// Box2D's position iterations per step (its testbed default).
  /// Range: [0, 1000] (more would let one run take hours).
  int positionIterations = 3;
};

/// The settings of every solver; a scene picks one solver, and its [solver] table sets that
/// solver's struct.
struct SolverSettings {
  /// "micro"
  MicroCollisionSettings micro;
  /// "sequential"
  SequentialImpulseSettings sequential;
  /// "reference"
  ReferenceSolverSettings reference;
  /// "box2d"
  Box2dSettings box2d;
  /// "soft_step"
  SoftStepSettings softStep;
};

/// One named field of a settings struct, for setting it by name from a scene file or the command
/// line and for listing it in `i2d check`.
struct SettingField {
  std::string name;  ///< snake_case, as in scene files
  /// the field in the struct
  std::variant<double*, int*, bool*, Vec2*> value;
};

std::vector<SettingField> describe(WorldSettings& settings);
std::vector<SettingField> describe(MicroCollisionSettings& settings);
std::vector<SettingField> describe(SequentialImpulseSettings& settings);
std::vector<SettingField> describe(ReferenceSolverSettings& settings);
std::vector<SettingField> describe(Box2dSettings& settings);
std::vector<SettingField> describe(SoftStepSettings& settings);

}  // namespace impulse2d
