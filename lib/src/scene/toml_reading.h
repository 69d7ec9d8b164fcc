// Typed reading of parsed TOML for scene files: every value is checked for its type and range
// where it is read, and every problem is thrown as a SceneError at the place it is written.
#pragma once

#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "impulse2d/math.h"
#include "impulse2d/settings.h"

namespace impulse2d::scene_file {

/// The values a number read from a scene file may take; every number must also be finite.
enum class Range { Any, NonNegative, Positive, UnitInterval };

/// Throws SceneError("FILE:LINE:COLUMN: message") at the start of `where`.
[[noreturn]] void fail(const toml::source_region& where, const std::string& message);

/// Throws naming the first key of `table` (in file order) that is not in `known`, and the known
/// keys, so a misspelt key such as `fricton` is caught rather than silently ignored.
void rejectUnknownKeys(const toml::table& table, const std::vector<std::string>& known,
                       const std::string& tableName);

/// The value of a key the table must have; `hint` shows what the key looks like.
const toml::node& requireKey(const toml::table& table, std::string_view key,
                             const std::string& hint);

double readNumber(const toml::node& node, std::string_view key, Range range = Range::Any);
/// An integer in [minimum, maximum].
int readInteger(const toml::node& node, std::string_view key, int minimum,
                int maximum = std::numeric_limits<int>::max());
bool readBoolean(const toml::node& node, std::string_view key);
std::string readString(const toml::node& node, std::string_view key);
/// An array of two numbers [x, y], each in `range`.
Vec2 readVec2(const toml::node& node, std::string_view key, Range range = Range::Any);
/// An array of [x, y] points.
std::vector<Vec2> readPoints(const toml::node& node, std::string_view key);
const toml::table& readTable(const toml::node& node, std::string_view key);
/// The tables of an array of tables such as [[body]].
std::vector<const toml::table*> readTableArray(const toml::node& node, std::string_view key);

/// Optional keys: the target keeps its default when the table does not have the key.
void readOptional(const toml::table& table, std::string_view key, double& target,
                  Range range = Range::Any);
void readOptional(const toml::table& table, std::string_view key, int& target, int minimum);
void readOptional(const toml::table& table, std::string_view key, Vec2& target,
                  Range range = Range::Any);
void readOptional(const toml::table& table, std::string_view key, std::string& target);

/// Sets each settings field the table names, each number finite and in the range its declaration
/// gives; keys not in `fields` must be in `otherKeys`. Out of range: "key = value: must be in
/// [a, b]", located at the value.
void readSettingsTable(const toml::table& table, const std::vector<SettingField>& fields,
                       const std::vector<std::string>& otherKeys, const std::string& tableName);

/// An integer setting such as the scene's steps, in `range` (any integer ≥ 0 without one).
int readSettingInteger(const toml::node& node, std::string_view key,
                       const std::optional<SettingRange>& range);

/// "a, b, c": the names in a message listing what is known.
std::string joinNames(const std::vector<std::string>& names);

}  // namespace impulse2d::scene_file
