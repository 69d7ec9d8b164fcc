// `i2d check`: validate a scene and print what it holds, as the engine will see it.
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>
#include <type_traits>
#include <variant>

#include "commands.h"
#include "failures.h"
#include "impulse2d/presets.h"
#include "impulse2d/scene/scene_file.h"
#include "scene_setup.h"

namespace i2d {
namespace {

using impulse2d::BodyDef;
using impulse2d::Shape;
using impulse2d::Vec2;

std::string formatVec2(const Vec2& v) {
  std::ostringstream out;
  out << "[" << v.x() << ", " << v.y() << "]";
  return out.str();
}

/// A polygon exactly as makeBox builds it: corners (±w/2, ±h/2) from the lower left.
bool isBox(const Shape& shape) {
  if (shape.type != impulse2d::ShapeType::Polygon || shape.vertices.size() != 4) return false;
  const Vec2& corner = shape.vertices[2];
  return shape.vertices[0] == -corner && shape.vertices[1] == Vec2(corner.x(), -corner.y()) &&
         shape.vertices[3] == Vec2(-corner.x(), corner.y());
}

std::string shapeKind(const Shape& shape) {
  if (shape.type == impulse2d::ShapeType::Circle) return "circle";
  return isBox(shape) ? "box" : "polygon";
}

std::string describeShape(const Shape& shape) {
  std::ostringstream out;
  out << shapeKind(shape) << " ";
  if (shape.type == impulse2d::ShapeType::Circle) {
    out << "radius " << shape.radius << " m";
  } else if (isBox(shape)) {
    out << 2.0 * shape.vertices[2].x() << " x " << 2.0 * shape.vertices[2].y() << " m";
  } else {
    out << shape.vertices.size() << " vertices";
  }
  return out.str();
}

std::string formatValue(const impulse2d::SettingField& field) {
  std::ostringstream out;
  std::visit(
      [&out](const auto& value) {
        using Value = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<Value, Vec2*>) {
          out << formatVec2(*value);
        } else if constexpr (std::is_same_v<Value, impulse2d::SettingChoice>) {
          out << '"' << value.current() << '"';
        } else {
          out << std::boolalpha << *value;
        }
      },
      field.value);
  return out.str();
}

/// The fields, each as `name = value`; with `published` (the same fields of the published
/// method), a value that differs is marked with `*` and the published value.
void printSettings(const std::string& title, const std::vector<impulse2d::SettingField>& fields,
                   const std::vector<impulse2d::SettingField>& published = {}) {
  std::cout << title << "\n";
  for (size_t i = 0; i < fields.size(); ++i) {
    const std::string value = formatValue(fields[i]);
    std::cout << "  " << fields[i].name << " = " << value;
    if (i < published.size() && formatValue(published[i]) != value) {
      std::cout << "  * published: " << formatValue(published[i]);
    }
    std::cout << "\n";
  }
}

/// The solver's settings beside those of the method as published (presets.h).
void printSolverSettings(impulse2d::SceneFile& scene) {
  const std::string title = "[solver] " + scene.solver;
  std::vector<impulse2d::SettingField> fields =
      impulse2d::solverSettingFields(scene.solverSettings, scene.solver);
  const impulse2d::Preset* method = impulse2d::publishedMethod(scene.solver, scene.preset);
  if (!method) {
    printSettings(title, fields);
    return;
  }
  impulse2d::SolverSettings published;
  method->apply(published);
  std::cout << "* marks a value that differs from preset " << method->name << ": "
            << method->summary << "\n";
  printSettings(title + (scene.preset.empty() ? "" : " (preset " + scene.preset + ")"), fields,
                impulse2d::solverSettingFields(published, scene.solver));
}

void printBodyCounts(const std::vector<BodyDef>& bodies) {
  std::map<std::string, int> byShape;
  int staticCount = 0;
  for (const BodyDef& body : bodies) {
    ++byShape[shapeKind(body.shape)];
    if (body.type == impulse2d::BodyType::Static) ++staticCount;
  }
  std::cout << "bodies " << bodies.size() << " (" << staticCount << " static, "
            << bodies.size() - staticCount << " dynamic):";
  for (const auto& [kind, count] : byShape) std::cout << " " << count << " " << kind;
  std::cout << "\n";
}

void printBody(const BodyDef& body) {
  const bool isStatic = body.type == impulse2d::BodyType::Static;
  std::cout << "  " << body.name << ": " << (isStatic ? "static" : "dynamic") << " "
            << describeShape(body.shape) << ", centre of mass " << formatVec2(body.position)
            << " m, angle " << body.angle * 180.0 / impulse2d::kPi << " deg";
  if (!isStatic) std::cout << ", density " << body.density << " kg/m^2";
  std::cout << ", friction " << body.friction << ", restitution " << body.restitution << "\n";
}

}  // namespace

int checkCommand(const CheckOptions& options) {
  impulse2d::SceneFile scene = loadScene(options.scene);
  std::cout << "scene " << scene.name << " (" << options.scene.scenePath << "): valid\n"
            << "solver " << scene.solver << ", " << scene.steps << " steps of " << scene.world.dt
            << " s = " << scene.steps * scene.world.dt << " s\n";
  printSettings("[world]", impulse2d::describe(scene.world));
  printSolverSettings(scene);
  printBodyCounts(scene.bodies);
  for (const BodyDef& body : scene.bodies) printBody(body);
  warnAboutStartingOverlaps(scene, std::cerr);
  return kSuccess;
}

}  // namespace i2d
