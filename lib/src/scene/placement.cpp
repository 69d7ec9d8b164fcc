// Placing a body at rest on a named surface: turned to the slope of the surface's top face, its
// lowest point touching the face, so a box on a tilted ramp needs no trigonometry in the file.
#include "placement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "toml_reading.h"

namespace impulse2d::scene_file {
namespace {

/// How far a body at `angle` reaches below its centre of mass along −normal.
double depthBelowCentre(const Shape& shape, double angle, const Vec2& normal) {
  if (shape.type == ShapeType::Circle) return shape.radius;
  const Mat2 turn = rotation(angle);
  double depth = -std::numeric_limits<double>::infinity();
  for (const Vec2& vertex : shape.vertices) depth = std::max(depth, -normal.dot(turn * vertex));
  return depth;
}

std::string numberText(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

void place(BodyDef& body, const BodyDef& support, const Placement& placement) {
  if (support.shape.type == ShapeType::Circle) {
    fail(placement.where, "body '" + body.name + "' cannot rest on '" + support.name +
                              "', a circle: 'on' needs a body with flat faces (a box or polygon)");
  }
  const TopFace face = topFace(support);
  const double half = face.length / 2.0;
  if (std::abs(placement.offset) > half) {
    fail(placement.offsetWhere, "'offset' = " + numberText(placement.offset) + ": must be in [" +
                                    numberText(-half) + ", " + numberText(half) +
                                    "], half the length of the top face of '" + support.name +
                                    "' either side of its middle");
  }
  body.angle = std::atan2(face.along.y(), face.along.x()) + placement.turn;
  const double depth = depthBelowCentre(body.shape, body.angle, face.normal);
  body.position = face.middle + placement.offset * face.along + depth * face.normal;
}

/// "a on b on c on a": the cycle that starts and ends at `first`.
std::string cycleText(const Scene& scene, const std::vector<size_t>& chain, size_t first) {
  std::string text;
  const auto start = std::find(chain.begin(), chain.end(), first);
  for (auto link = start; link != chain.end(); ++link) text += scene.bodies[*link].name + " on ";
  return text + scene.bodies[first].name;
}

/// The scene's first body names, enough to spot a misspelt one.
std::string someNames(const Scene& scene) {
  constexpr size_t kNamesShown = 12;
  std::vector<std::string> names;
  for (size_t i = 0; i < std::min(scene.bodies.size(), kNamesShown); ++i) {
    names.push_back(scene.bodies[i].name);
  }
  if (scene.bodies.size() > kNamesShown) names.push_back("...");
  return joinNames(names);
}

}  // namespace

TopFace topFace(const BodyDef& body) {
  const Mat2 turn = rotation(body.angle);
  const std::vector<Vec2>& vertices = body.shape.vertices;
  size_t best = 0;
  for (size_t i = 1; i < vertices.size(); ++i) {
    if ((turn * body.shape.normals[i]).y() > (turn * body.shape.normals[best]).y()) best = i;
  }
  const Vec2 start = body.position + turn * vertices[best];
  const Vec2 end = body.position + turn * vertices[(best + 1) % vertices.size()];
  const Vec2 normal = turn * body.shape.normals[best];
  // Counter-clockwise vertices run right to left along a top face; `along` runs left to right.
  return {(start + end) / 2.0, Vec2(normal.y(), -normal.x()), normal, (end - start).norm()};
}

void placeOnSurfaces(Scene& scene, const std::vector<Placement>& placements) {
  std::map<std::string, size_t> index;
  for (size_t i = 0; i < scene.bodies.size(); ++i) index.emplace(scene.bodies[i].name, i);
  std::map<size_t, const Placement*> placementOf;
  for (const Placement& placement : placements) placementOf[placement.body] = &placement;
  std::vector<bool> placed(scene.bodies.size(), false);
  for (const Placement& first : placements) {
    // Follow the chain down to a body that is not placed on another (or already placed), then
    // place the chain from the bottom up.
    std::vector<size_t> chain;
    std::set<size_t> onChain;
    for (const Placement* link = &first; link && !placed[link->body];) {
      const auto support = index.find(link->support);
      if (support == index.end()) {
        fail(link->where, "'on' names '" + link->support +
                              "', and no body has that name (known: " + someNames(scene) + ")");
      }
      chain.push_back(link->body);
      onChain.insert(link->body);
      if (onChain.count(support->second)) {
        fail(placementOf.at(support->second)->where,
             "'on' makes a cycle: " + cycleText(scene, chain, support->second) +
                 "; a body can rest only on one placed without it");
      }
      const auto next = placementOf.find(support->second);
      link = next == placementOf.end() ? nullptr : next->second;
    }
    for (auto body = chain.rbegin(); body != chain.rend(); ++body) {
      const Placement& placement = *placementOf.at(*body);
      place(scene.bodies[*body], scene.bodies[index.at(placement.support)], placement);
      placed[*body] = true;
    }
  }
}

}  // namespace impulse2d::scene_file
