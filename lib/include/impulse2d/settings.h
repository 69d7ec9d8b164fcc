// Every tunable number of the engine, gathered: the world's and the shared contact rules
// (shared_settings.h), each method's own struct beside it (solvers/*_settings.h), and Box2D's
// iteration counts. Each struct gives its fields' defaults; describe() declares each field's
// scene-file name, unit, range and meaning, from which a scene file's [world] and [solver] tables
// set them, the ranges are checked and docs/scene-format.md's tables are generated.
#pragma once

#include <functional>
#include <optional>
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
  int velocityIterations = 8;
  /// Box2D's position iterations per step (its testbed default).
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

/// The values a setting may take: from lowest to highest, each end included or not.
struct SettingRange {
  double lowest = 0.0;         ///< the lower end
  bool lowestIncluded = true;  ///< [lowest, ...] or (lowest, ...]
  double highest = 0.0;        ///< the upper end
  /// Why the upper bound is there, for keys that would make a run unbounded; empty otherwise.
  std::string bound;
};

/// A setting that is one of a few named values (an enum): its scene-file value is one of `names`,
/// in the enum's order.
struct SettingChoice {
  std::vector<std::string> names;  ///< each value's scene-file name, in the enum's order
  std::function<int()> get;        ///< the field's value, as its index in `names`
  std::function<void(int)> set;    ///< sets the field to the value at an index of `names`

  /// The scene-file name of the field's value.
  const std::string& current() const { return names[size_t(get())]; }
  /// "a, b, c": the names, for messages and listings.
  std::string listed() const;
};

/// The choice of `field`, an enum whose values in order are called `names` in scene files.
template <typename Enum>
SettingChoice choice(Enum& field, std::vector<std::string> names) {
  return {std::move(names), [&field] { return static_cast<int>(field); },
          [&field](int index) { field = static_cast<Enum>(index); }};
}

/// The declaration of one setting: its scene-file name, the field it sets, its unit, its range
/// and its meaning in a line. The field's default is its initializer in the struct. The scene
/// loader, its range checks, `i2d check`'s listing and the tables of docs/scene-format.md all
/// read these declarations (describe() below).
struct SettingField {
  std::string name;  ///< snake_case, as in scene files
  /// the field in the struct
  std::variant<double*, int*, bool*, Vec2*, SettingChoice> value;
  std::string unit;                   ///< SI unit, empty for a count, a ratio, a switch or a choice
  std::optional<SettingRange> range;  ///< every number has one; a switch, choice or vector none
  std::string meaning;                ///< one line, as the docs' tables show it
};

/// [lowest, highest], with the reason for the upper bound if it keeps a run from taking hours.
SettingRange closed(double lowest, double highest, const std::string& bound = {});
/// (0, highest].
SettingRange aboveZero(double highest);

/// Whether `value` lies in `range`.
bool inSettingRange(double value, const SettingRange& range);

/// "must be an integer in [1, 1000]" or "must be in (0, 1]", with the bound's reason when the
/// value is above it.
std::string describeSettingRange(const SettingRange& range, bool integer, double value);

/// The declarations of each settings struct's fields, in the order `i2d check` lists them.
std::vector<SettingField> describe(WorldSettings& settings);
std::vector<SettingField> describe(MicroCollisionSettings& settings);
std::vector<SettingField> describe(SequentialImpulseSettings& settings);
std::vector<SettingField> describe(ReferenceSolverSettings& settings);
std::vector<SettingField> describe(Box2dSettings& settings);
std::vector<SettingField> describe(SoftStepSettings& settings);

}  // namespace impulse2d
