// Scene descriptions -> bodies and worlds; the stack and pyramid generators.
#include "impulse2d/scene/scene.h"

namespace impulse2d {

std::vector<Body> buildBodies(const Scene& scene) {
  std::vector<Body> bodies;
  bodies.reserve(scene.bodies.size());
  for (const BodyDef& def : scene.bodies) {
    Body body = makeBody(def.name, def.type, def.shape, def.density, def.position, def.angle);
    body.friction = def.friction;
    body.restitution = def.restitution;
    body.load = def.load;
    if (!body.isStatic()) {
      body.velocity = def.velocity;
      body.angularVelocity = def.angularVelocity;
    }
    bodies.push_back(std::move(body));
  }
  return bodies;
}

std::unique_ptr<World> buildWorld(const Scene& scene) {
  auto world = std::make_unique<World>(scene.world, makeSolver(scene.solver, scene.solverSettings));
  for (Body& body : buildBodies(scene)) world->addBody(std::move(body));
  return world;
}

namespace {

BodyDef boxAt(const BodyDef& material, const Vec2& size, const Vec2& centre, size_t index) {
  BodyDef box = material;
  box.name = "box" + std::to_string(index);
  box.shape = makeBox(size.x(), size.y());
  box.position = centre;
  return box;
}

}  // namespace

void addStack(Scene& scene, int count, const Vec2& size, const Vec2& base, double levelOffset,
              const BodyDef& material) {
  for (int level = 0; level < count; ++level) {
    const Vec2 centre(base.x() + level * levelOffset, base.y() + (level + 0.5) * size.y());
    scene.bodies.push_back(boxAt(material, size, centre, scene.bodies.size()));
  }
}

void addPyramid(Scene& scene, int rows, const Vec2& size, const Vec2& baseCentre,
                const BodyDef& material) {
  for (int row = 0; row < rows; ++row) {
    const int boxes = rows - row;
    for (int i = 0; i < boxes; ++i) {
      const Vec2 centre(baseCentre.x() + (i - 0.5 * (boxes - 1)) * size.x(),
                        baseCentre.y() + (row + 0.5) * size.y());
      scene.bodies.push_back(boxAt(material, size, centre, scene.bodies.size()));
    }
  }
}

}  // namespace impulse2d
