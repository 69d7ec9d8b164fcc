// Scenes nobody wrote: random boxes, circles and polygons dropped and thrown into a walled box,
// each run by every method. What a new user's scene must get from any of them: the run ends
// without an error (the reference answers every step to its tolerance), every body stays finite,
// and none passes through the floor or a wall. The scenes come from a fixed seed, so a failure
// names a scene that fails the same way every run.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "impulse2d/scene/scene.h"
#include "impulse2d/world.h"

using namespace impulse2d;

namespace {

constexpr double kWallInside = 5.5;  ///< m: the walls' inner faces are x = ±5.5, the floor y = 0
constexpr int kScenes = 100;
constexpr int kSteps = 240;

BodyDef staticBox(const Vec2& size, const Vec2& position) {
  BodyDef box;
  box.type = BodyType::Static;
  box.shape = makeBox(size.x(), size.y());
  box.position = position;
  return box;
}

Shape randomShape(std::mt19937& random) {
  std::uniform_real_distribution<double> size(0.3, 1.2);
  switch (std::uniform_int_distribution<int>(0, 2)(random)) {
    case 0:
      return makeBox(size(random), size(random));
    case 1:
      return makeCircle(0.5 * size(random));
    default: {
      const int corners = std::uniform_int_distribution<int>(3, 7)(random);
      const double radius = 0.5 * size(random);
      std::vector<Vec2> vertices;
      for (int k = 0; k < corners; ++k) {
        const double at = 2.0 * kPi * k / corners;
        vertices.emplace_back(radius * std::cos(at), radius * std::sin(at));
      }
      return makePolygon(vertices).shape;
    }
  }
}

/// Up to 12 bodies of random shape, friction and restitution over a floor and between two walls,
/// at random heights, some thrown; a random step of 1/30 to 1/120 s.
Scene randomScene(const std::string& solver, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Scene scene;
  scene.solver = solver;
  scene.world.dt = 1.0 / std::vector<double>{30.0, 60.0, 120.0}[random() % 3];
  scene.bodies.push_back(staticBox(Vec2(40.0, 1.0), Vec2(0.0, -0.5)));
  scene.bodies.push_back(staticBox(Vec2(1.0, 30.0), Vec2(-kWallInside - 0.5, 10.0)));
  scene.bodies.push_back(staticBox(Vec2(1.0, 30.0), Vec2(kWallInside + 0.5, 10.0)));
  for (BodyDef& wall : scene.bodies) wall.friction = unit(random);
  const int count = 1 + static_cast<int>(random() % 12);
  for (int k = 0; k < count; ++k) {
    BodyDef body;
    body.shape = randomShape(random);
    body.position = Vec2(8.0 * unit(random) - 4.0, 0.8 + 3.0 * unit(random) + 0.9 * k);
    body.angle = 2.0 * kPi * unit(random);
    body.friction = unit(random);
    body.restitution = unit(random) < 0.5 ? 0.0 : 0.8 * unit(random);
    if (unit(random) < 0.3) body.velocity = Vec2(4.0 * unit(random) - 2.0, -3.0 * unit(random));
    scene.bodies.push_back(body);
  }
  return scene;
}

/// Dynamic bodies not finite, or with the centre below the floor or past a wall.
int bodiesOutside(const World& world) {
  int outside = 0;
  for (const Body& body : world.bodies()) {
    if (body.isStatic()) continue;
    const bool inside = body.position.allFinite() && std::isfinite(body.angle) &&
                        std::abs(body.position.x()) < kWallInside && body.position.y() > 0.0;
    if (!inside) ++outside;
  }
  return outside;
}

}  // namespace

TEST_CASE("random scenes run under every method, and no body leaves the walled box",
          "[robustness][reference]") {
  for (const std::string solver : {"micro", "sequential", "soft_step", "reference"}) {
    for (unsigned seed = 1; seed <= kScenes; ++seed) {
      auto world = buildWorld(randomScene(solver, seed));
      INFO(solver << ", scene seed " << seed);
      for (int step = 0; step < kSteps; ++step) REQUIRE_NOTHROW(world->step());
      CHECK(bodiesOutside(*world) == 0);
    }
  }
}
