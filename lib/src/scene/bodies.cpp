// The bodies of a scene file: [[body]] tables, and the [[stack]] and [[pyramid]] generators that
// expand to ordinary boxes.
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

#include "impulse2d/shape.h"
#include "placement.h"
#include "scene_tables.h"
#include "toml_reading.h"

namespace impulse2d::scene_file {
namespace {

/// Most boxes one generator may make: far more than the solvers run at interactive speed, few
/// enough that a mistyped count cannot exhaust memory.
constexpr int kMaxGeneratedBoxes = 100000;

double radians(double degrees) {
  return degrees * kPi / 180.0;
}

/// Density, friction and restitution: the keys bodies and generators share.
void readMaterial(const toml::table& table, BodyDef& body) {
  readOptional(table, "density", body.density, Range::Positive);
  readOptional(table, "friction", body.friction, Range::NonNegative);
  readOptional(table, "restitution", body.restitution, Range::UnitInterval);
}

BodyType readBodyType(const toml::table& table) {
  const toml::node* node = table.get("type");
  if (!node) return BodyType::Dynamic;
  const std::string type = readString(*node, "type");
  if (type == "dynamic") return BodyType::Dynamic;
  if (type == "static") return BodyType::Static;
  fail(node->source(), "unknown body type '" + type + "' (known: dynamic, static)");
}

CentredPolygon readBox(const toml::table& table) {
  const toml::node& node = requireKey(table, "size", "a box needs size = [width, height]");
  const Vec2 size = readVec2(node, "size", Range::Positive);
  return {makeBox(size.x(), size.y()), Vec2::Zero()};
}

CentredPolygon readCircle(const toml::table& table) {
  const toml::node& node = requireKey(table, "radius", "a circle needs radius = r");
  return {makeCircle(readNumber(node, "radius", Range::Positive)), Vec2::Zero()};
}

CentredPolygon readPolygon(const toml::table& table) {
  const toml::node& node =
      requireKey(table, "vertices", "a polygon needs vertices = [[x, y], ...], convex");
  try {
    return makePolygon(readPoints(node, "vertices"));
  } catch (const ShapeError& error) {
    fail(node.source(), "'vertices': " + std::string(error.what()));
  }
}

/// Each shape takes one dimension key; the others' keys are mistakes, not silently ignored.
void rejectOtherShapeKeys(const toml::table& table, const std::string& shape,
                          const std::string& dimensionKey) {
  for (const char* key : {"size", "radius", "vertices"}) {
    const auto entry = table.find(key);
    if (key == dimensionKey || entry == table.end()) continue;
    fail(entry->first.source(), "key '" + std::string(key) + "' does not apply to a " + shape +
                                    " (a " + shape + " takes '" + dimensionKey + "')");
  }
}

/// The body's shape, centred on its centroid, and where that centroid is in the file's frame.
CentredPolygon readShape(const toml::table& table) {
  const toml::node& node = requireKey(table, "shape", "shape = box, circle or polygon");
  const std::string shape = readString(node, "shape");
  const std::map<std::string, std::string> dimensionKeys = {
      {"box", "size"}, {"circle", "radius"}, {"polygon", "vertices"}};
  const auto dimension = dimensionKeys.find(shape);
  if (dimension == dimensionKeys.end()) {
    fail(node.source(), "unknown shape '" + shape + "' (known: box, circle, polygon)");
  }
  rejectOtherShapeKeys(table, shape, dimension->second);
  if (shape == "box") return readBox(table);
  if (shape == "circle") return readCircle(table);
  return readPolygon(table);
}

/// The applied load of a dynamic body; a static body never moves, so a load on it is a mistake.
void readLoad(const toml::table& table, BodyDef& body) {
  readOptional(table, "force", body.load.force);
  readOptional(table, "force_rate", body.load.forceRate);
  readOptional(table, "force_point", body.load.point);
  readOptional(table, "torque", body.load.torque);
  if (body.type != BodyType::Static) return;
  for (const char* key : {"force", "force_rate", "force_point", "torque"}) {
    if (const auto entry = table.find(key); entry != table.end()) {
      fail(entry->first.source(), "key '" + std::string(key) +
                                      "' applies a load, and a static body never moves; make "
                                      "the body dynamic or remove the key");
    }
  }
}

/// `on = "name"` and `offset`: the body rests on another, placed once all bodies are read; a
/// `position` would contradict it, and an `offset` means nothing without it.
std::optional<Placement> readPlacement(const toml::table& table, size_t index) {
  const toml::node* on = table.get("on");
  if (!on) {
    if (const auto offset = table.find("offset"); offset != table.end()) {
      fail(offset->first.source(),
           "'offset' places a body along the face it rests on; it needs "
           "on = \"name\"");
    }
    return std::nullopt;
  }
  if (const auto position = table.find("position"); position != table.end()) {
    fail(position->first.source(), "'position' and 'on' both place the body; give one of them");
  }
  Placement placement;
  placement.body = index;
  placement.support = readString(*on, "on");
  placement.where = on->source();
  readOptional(table, "offset", placement.offset);
  const toml::node* offset = table.get("offset");
  placement.offsetWhere = offset ? offset->source() : on->source();
  return placement;
}

BodyDef readBody(const toml::table& table, size_t index, std::vector<Placement>& placements) {
  rejectUnknownKeys(table,
                    {"name", "type", "shape", "size", "radius", "vertices", "position", "on",
                     "offset", "angle_deg", "velocity", "angular_velocity_deg", "density",
                     "friction", "restitution", "force", "force_rate", "force_point", "torque"},
                    "[[body]]");
  BodyDef body;
  body.name = "body" + std::to_string(index);
  readOptional(table, "name", body.name);
  if (body.name.empty()) fail(table.get("name")->source(), "'name' must not be empty");
  body.type = readBodyType(table);
  const CentredPolygon shape = readShape(table);
  body.shape = shape.shape;
  double angleDegrees = 0.0;
  double angularVelocityDegrees = 0.0;
  readOptional(table, "position", body.position);
  readOptional(table, "angle_deg", angleDegrees);
  readOptional(table, "velocity", body.velocity);
  readOptional(table, "angular_velocity_deg", angularVelocityDegrees);
  readMaterial(table, body);
  readLoad(table, body);
  body.angle = radians(angleDegrees);
  body.angularVelocity = radians(angularVelocityDegrees);
  // The file places the body's origin; the engine places its centre of mass.
  body.position += rotation(body.angle) * shape.centroid;
  body.load.point -= shape.centroid;
  if (std::optional<Placement> placement = readPlacement(table, index)) {
    placement->turn = body.angle;
    placements.push_back(*placement);
  }
  return body;
}

Vec2 readBoxSize(const toml::table& table) {
  const toml::node& node = requireKey(table, "size", "size = [width, height] of each box");
  return readVec2(node, "size", Range::Positive);
}

Vec2 readBase(const toml::table& table, const std::string& hint) {
  return readVec2(requireKey(table, "base", "base = [x, y], " + hint), "base");
}

void readStack(const toml::table& table, Scene& scene) {
  rejectUnknownKeys(table,
                    {"count", "size", "base", "level_offset", "density", "friction", "restitution"},
                    "[[stack]]");
  const int count = readInteger(requireKey(table, "count", "count = number of boxes"), "count", 1,
                                kMaxGeneratedBoxes);
  const Vec2 size = readBoxSize(table);
  const Vec2 base = readBase(table, "the bottom centre of the lowest box");
  double levelOffset = 0.0;
  readOptional(table, "level_offset", levelOffset);
  BodyDef material;
  readMaterial(table, material);
  addStack(scene, count, size, base, levelOffset, material);
}

void readPyramid(const toml::table& table, Scene& scene) {
  rejectUnknownKeys(table, {"rows", "size", "base", "density", "friction", "restitution"},
                    "[[pyramid]]");
  // rows·(rows + 1)/2 boxes in all.
  const int maxRows = int((std::sqrt(8.0 * kMaxGeneratedBoxes + 1.0) - 1.0) / 2.0);
  const int rows =
      readInteger(requireKey(table, "rows", "rows = number of rows"), "rows", 1, maxRows);
  const Vec2 size = readBoxSize(table);
  const Vec2 base = readBase(table, "the centre of the bottom row's base");
  BodyDef material;
  readMaterial(table, material);
  addPyramid(scene, rows, size, base, material);
}

/// Where a body's name comes from: its name key, else the table that made it.
toml::source_region nameOrigin(const toml::table& table) {
  const toml::node* name = table.get("name");
  return name ? name->source() : table.source();
}

bool positiveAndFinite(double value) {
  return std::isfinite(value) && value > 0.0;
}

/// A body the engine can integrate: a finite place, and for a dynamic body a mass and moment of
/// inertia whose inverses are finite too. Each number in the file can be finite while their
/// product is not: a radius of 1e200 overflows the mass, a size of 1e-160 underflows it to 0
/// (an infinite inverse mass), a stack offset 1e308 m a level places boxes at infinity.
void rejectUnsimulable(const BodyDef& definition, const toml::source_region& origin) {
  const std::string name = "body '" + definition.name + "'";
  if (!definition.position.allFinite()) {
    fail(origin, name + " is placed at a non-finite position; its numbers are too large");
  }
  if (definition.type == BodyType::Static) return;
  const MassProperties mass = computeMass(definition.shape, definition.density);
  if (!positiveAndFinite(mass.mass) || !positiveAndFinite(1.0 / mass.mass) ||
      !positiveAndFinite(mass.inertia) || !positiveAndFinite(1.0 / mass.inertia)) {
    std::ostringstream numbers;
    numbers << "mass " << mass.mass << " kg and moment of inertia " << mass.inertia << " kg m^2";
    fail(origin, name + " has " + numbers.str() +
                     "; both and their inverses must be finite and > 0 (its size or density is "
                     "too large or too small)");
  }
}

void rejectRepeatedNames(const Scene& scene, const std::vector<toml::source_region>& origins) {
  std::map<std::string, size_t> firstUse;
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    const auto [first, isNew] = firstUse.emplace(scene.bodies[i].name, i);
    if (isNew) continue;
    fail(origins[i], "body name '" + scene.bodies[i].name + "' is already used by body " +
                         std::to_string(first->second) + "; names must be unique");
  }
}

}  // namespace

void readBodies(const toml::table& root, Scene& scene) {
  std::vector<toml::source_region> origins;
  std::vector<Placement> placements;
  if (const toml::node* bodies = root.get("body")) {
    for (const toml::table* table : readTableArray(*bodies, "body")) {
      scene.bodies.push_back(readBody(*table, scene.bodies.size(), placements));
      origins.push_back(nameOrigin(*table));
    }
  }
  if (const toml::node* stacks = root.get("stack")) {
    for (const toml::table* table : readTableArray(*stacks, "stack")) {
      readStack(*table, scene);
      origins.resize(scene.bodies.size(), table->source());
    }
  }
  if (const toml::node* pyramids = root.get("pyramid")) {
    for (const toml::table* table : readTableArray(*pyramids, "pyramid")) {
      readPyramid(*table, scene);
      origins.resize(scene.bodies.size(), table->source());
    }
  }
  rejectRepeatedNames(scene, origins);
  placeOnSurfaces(scene, placements);
  for (size_t i = 0; i < scene.bodies.size(); ++i) rejectUnsimulable(scene.bodies[i], origins[i]);
}

}  // namespace impulse2d::scene_file
