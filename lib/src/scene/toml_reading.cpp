// Typed reading of scene-file values, each error located where the value is written.
#include "toml_reading.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>
#include <variant>

#include "impulse2d/scene/scene_file.h"
#include "impulse2d/scene/setting_ranges.h"

namespace impulse2d::scene_file {
namespace {

/// "a string", "an integer", ...: what a node is, for "must be X, not Y" messages.
std::string describeType(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a floating-point number";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    default:
      return "a date or time";
  }
}

[[noreturn]] void failType(const toml::node& node, std::string_view key, const std::string& want) {
  fail(node.source(), "'" + std::string(key) + "' must be " + want + ", not " + describeType(node));
}

std::string formatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

bool inRange(double value, Range range) {
  switch (range) {
    case Range::NonNegative:
      return value >= 0.0;
    case Range::Positive:
      return value > 0.0;
    case Range::UnitInterval:
      return value >= 0.0 && value <= 1.0;
    default:
      return true;
  }
}

std::string describeRange(Range range) {
  switch (range) {
    case Range::NonNegative:
      return ">= 0";
    case Range::Positive:
      return "> 0";
    default:
      return "in [0, 1]";
  }
}

[[noreturn]] void failRange(const toml::node& node, std::string_view key, const std::string& value,
                            const SettingRange& range, bool integer, double number) {
  fail(node.source(),
       std::string(key) + " = " + value + ": " + describeSettingRange(range, integer, number));
}

double readSettingNumber(const toml::node& node, std::string_view key,
                         const std::optional<SettingRange>& range) {
  const double value = readNumber(node, key, range ? Range::Any : Range::NonNegative);
  if (range && !inSettingRange(value, *range)) {
    failRange(node, key, formatNumber(value), *range, false, value);
  }
  return value;
}

/// A choice's value: one of its names, or a located error listing them.
void readChoice(const SettingChoice& choice, const toml::node& node, const std::string& key) {
  if (!node.is_string()) failType(node, key, "a string (one of: " + choice.listed() + ")");
  const std::string value = *node.value<std::string>();
  const auto found = std::find(choice.names.begin(), choice.names.end(), value);
  if (found == choice.names.end()) {
    fail(node.source(),
         "unknown value '" + value + "' for '" + key + "' (known: " + choice.listed() + ")");
  }
  choice.set(static_cast<int>(found - choice.names.begin()));
}

void readSetting(const SettingField& field, const toml::node& node) {
  std::visit(
      [&](const auto& target) {
        using Target = std::decay_t<decltype(target)>;
        if constexpr (std::is_same_v<Target, double*>) {
          *target = readSettingNumber(node, field.name, field.range);
        }
        if constexpr (std::is_same_v<Target, int*>) {
          *target = readSettingInteger(node, field.name, field.range);
        }
        if constexpr (std::is_same_v<Target, bool*>) *target = readBoolean(node, field.name);
        if constexpr (std::is_same_v<Target, Vec2*>) *target = readVec2(node, field.name);
        if constexpr (std::is_same_v<Target, SettingChoice>) readChoice(target, node, field.name);
      },
      field.value);
}

bool precedes(const toml::source_position& a, const toml::source_position& b) {
  return a.line < b.line || (a.line == b.line && a.column < b.column);
}

}  // namespace

void fail(const toml::source_region& where, const std::string& message) {
  const std::string source = where.path ? *where.path : std::string();
  throw SceneError(source, int(where.begin.line), int(where.begin.column), message);
}

std::string joinNames(const std::vector<std::string>& names) {
  std::string joined;
  for (const std::string& name : names) joined += (joined.empty() ? "" : ", ") + name;
  return joined;
}

void rejectUnknownKeys(const toml::table& table, const std::vector<std::string>& known,
                       const std::string& tableName) {
  const toml::key* first = nullptr;
  for (const auto& [key, value] : table) {
    const bool isKnown = std::find(known.begin(), known.end(), key.str()) != known.end();
    if (!isKnown && (!first || precedes(key.source().begin, first->source().begin))) first = &key;
  }
  if (first) {
    fail(first->source(), "unknown key '" + std::string(first->str()) + "' in " + tableName +
                              " (known: " + joinNames(known) + ")");
  }
}

const toml::node& requireKey(const toml::table& table, std::string_view key,
                             const std::string& hint) {
  const toml::node* node = table.get(key);
  if (!node) fail(table.source(), "missing required key '" + std::string(key) + "' (" + hint + ")");
  return *node;
}

double readNumber(const toml::node& node, std::string_view key, Range range) {
  if (!node.is_number()) failType(node, key, "a number");
  const double value = node.is_integer() ? double(*node.value<int64_t>()) : *node.value<double>();
  if (!std::isfinite(value)) {
    fail(node.source(), "'" + std::string(key) + "' must be finite, not " + formatNumber(value));
  }
  if (!inRange(value, range)) {
    fail(node.source(), "'" + std::string(key) + "' must be " + describeRange(range) + ", not " +
                            formatNumber(value));
  }
  return value;
}

int readInteger(const toml::node& node, std::string_view key, int minimum, int maximum) {
  if (!node.is_integer()) failType(node, key, "an integer");
  const int64_t value = *node.value<int64_t>();
  if (value < minimum) {
    fail(node.source(), "'" + std::string(key) + "' must be >= " + std::to_string(minimum) +
                            ", not " + std::to_string(value));
  }
  if (value > maximum) {
    fail(node.source(), "'" + std::string(key) + "' must be <= " + std::to_string(maximum) +
                            ", not " + std::to_string(value));
  }
  return int(value);
}

bool readBoolean(const toml::node& node, std::string_view key) {
  if (!node.is_boolean()) failType(node, key, "true or false");
  return *node.value<bool>();
}

std::string readString(const toml::node& node, std::string_view key) {
  if (!node.is_string()) failType(node, key, "a string");
  return *node.value<std::string>();
}

Vec2 readVec2(const toml::node& node, std::string_view key, Range range) {
  const toml::array* array = node.as_array();
  if (!array) failType(node, key, "an array of 2 numbers [x, y]");
  if (array->size() != 2) {
    fail(node.source(), "'" + std::string(key) + "' must have 2 numbers [x, y], not " +
                            std::to_string(array->size()));
  }
  return Vec2(readNumber((*array)[0], key, range), readNumber((*array)[1], key, range));
}

std::vector<Vec2> readPoints(const toml::node& node, std::string_view key) {
  const toml::array* array = node.as_array();
  if (!array) failType(node, key, "an array of [x, y] points");
  std::vector<Vec2> points;
  for (const toml::node& point : *array) points.push_back(readVec2(point, key));
  return points;
}

const toml::table& readTable(const toml::node& node, std::string_view key) {
  if (!node.is_table()) failType(node, key, "a table [" + std::string(key) + "]");
  return *node.as_table();
}

std::vector<const toml::table*> readTableArray(const toml::node& node, std::string_view key) {
  const std::string want = "an array of tables [[" + std::string(key) + "]]";
  const toml::array* array = node.as_array();
  if (!array) failType(node, key, want);
  std::vector<const toml::table*> tables;
  for (const toml::node& element : *array) {
    if (!element.is_table()) failType(element, key, want);
    tables.push_back(element.as_table());
  }
  return tables;
}

void readOptional(const toml::table& table, std::string_view key, double& target, Range range) {
  if (const toml::node* node = table.get(key)) target = readNumber(*node, key, range);
}

void readOptional(const toml::table& table, std::string_view key, int& target, int minimum) {
  if (const toml::node* node = table.get(key)) target = readInteger(*node, key, minimum);
}

void readOptional(const toml::table& table, std::string_view key, Vec2& target, Range range) {
  if (const toml::node* node = table.get(key)) target = readVec2(*node, key, range);
}

void readOptional(const toml::table& table, std::string_view key, std::string& target) {
  if (const toml::node* node = table.get(key)) target = readString(*node, key);
}

int readSettingInteger(const toml::node& node, std::string_view key,
                       const std::optional<SettingRange>& range) {
  if (!range) return readInteger(node, key, 0);
  if (!node.is_integer()) failType(node, key, "an integer");
  const int64_t value = *node.value<int64_t>();
  if (!inSettingRange(double(value), *range)) {
    failRange(node, key, std::to_string(value), *range, true, double(value));
  }
  return int(value);
}

void readSettingsTable(const toml::table& table, const std::vector<SettingField>& fields,
                       const std::vector<std::string>& otherKeys, const std::string& tableName) {
  std::vector<std::string> known;
  for (const SettingField& field : fields) known.push_back(field.name);
  known.insert(known.end(), otherKeys.begin(), otherKeys.end());
  rejectUnknownKeys(table, known, tableName);
  for (const SettingField& field : fields) {
    if (const toml::node* node = table.get(field.name)) readSetting(field, *node);
  }
}

}  // namespace impulse2d::scene_file
