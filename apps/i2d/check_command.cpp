// `i2d check`: validate a scene and print what it holds, as the engine will see it.
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>
#include <type_traits>
#include <variant>

#include "commands.h"
#include "failures.h"
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

void printSettings(const std::string& title, const std::vector<impulse2d::SettingField>& fields) {
  std::cout << title << "\n";
  for (const impulse2d::SettingField& field : fields) {
    std::cout << "  " << field.name << " = ";
    std::visit(
        [](auto* value) {
          if constexpr (std::is_same_v<decltype(value), Vec2*>) {
            std::cout << formatVec2(*value);
          } else {
            std::cout << std::boolalpha << *value;
          }
        },
        field.value);
    std::cout << "\n";
  }
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
            << " m, angle " << body.angle * 180.0 / M_PI << " deg";
  if (!isStatic) std::cout << ", density " << body.density << " kg/m^2";
  std::cout << ", friction " << body.friction << ", restitution " << body.restitution << "\n";
}

}  // namespace

int checkCommand(const CheckOptions& options) {
  impulse2d::SceneFile scene = impulse2d::loadSceneFile(options.scenePath);
  std::cout << "scene " << scene.name << " (" << options.scenePath << "): valid\n"
            << "solver " << scene.solver << ", " << scene.steps << " steps of " << scene.world.dt
            << " s = " << scene.steps * scene.world.dt << " s\n";
  printSettings("[world]", impulse2d::describe(scene.world));
  printSettings("[solver] " + scene.solver,
                impulse2d::solverSettingFields(scene.solverSettings, scene.solver));
  printBodyCounts(scene.bodies);
  for (const BodyDef& body : scene.bodies) printBody(body);
  warnAboutStartingOverlaps(scene, std::cerr);
  return kSuccess;
}

}  // namespace i2d
