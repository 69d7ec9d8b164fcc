// Internal edges (internal_edges.h, docs/contact-generation.md): a body moving across the seam of
// two static boxes laid flush meets one surface, under every method, for a disc and a box. Each
// run is compared with the same body on one box as long as both: the seam may not make it hop,
// change its speed or turn it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "impulse2d/internal_edges.h"
#include "solver_scenes.h"

using namespace impulse2d;

namespace {

constexpr double kFloorLength = 8.0;  ///< m, from x = −4 to 4; the seam at x = 0
constexpr double kStartX = -1.5;      ///< m: the body crosses the seam within its run
constexpr int kSteps = 60;            ///< 1 s: the body ends 1.5–3.5 m past the seam

/// m. A hop no larger than this, and m/s: a change of speed of the body's centre or of its
/// farthest point's turning speed (|Δω| × its reach) no larger than this, is meeting one surface.
constexpr double kHopBound = 1e-4;
constexpr double kSpeedBound = 1e-3;

/// The floor as one box or as two boxes of half its length meeting flush at x = 0; top at y = 0.
std::vector<BodyDef> floorPieces(bool seam, double friction) {
  const int pieces = seam ? 2 : 1;
  const double length = kFloorLength / pieces;
  std::vector<BodyDef> floor;
  for (int i = 0; i < pieces; ++i) {
    BodyDef piece;
    piece.type = BodyType::Static;
    piece.shape = makeBox(length, 1.0);
    piece.position = Vec2(-0.5 * kFloorLength + (i + 0.5) * length, -0.5);
    piece.friction = friction;
    floor.push_back(piece);
  }
  return floor;
}

/// A 0.25 m disc rolling at 3 m/s (ω = −v/r) on a floor of friction 0.5.
Scene rollingDisc(const std::string& solver, bool seam) {
  Scene scene;
  scene.solver = solver;
  scene.bodies = floorPieces(seam, 0.5);
  BodyDef disc;
  disc.shape = makeCircle(0.25);
  disc.position = Vec2(kStartX, 0.25);
  disc.velocity = Vec2(3.0, 0.0);
  disc.angularVelocity = -3.0 / 0.25;
  scene.bodies.push_back(disc);
  return scene;
}

/// A 0.5 m box sliding at 5 m/s on a floor of friction `friction`.
Scene slidingBox(const std::string& solver, bool seam, double friction) {
  Scene scene;
  scene.solver = solver;
  scene.bodies = floorPieces(seam, friction);
  BodyDef box;
  box.shape = makeBox(0.5, 0.5);
  box.position = Vec2(kStartX, 0.25);
  box.velocity = Vec2(5.0, 0.0);
  box.friction = friction;
  scene.bodies.push_back(box);
  return scene;
}

/// How far the seam moves the body from where the one-piece floor takes it, at worst over the
/// run: its rise, its change of speed, and its change of turning speed at its farthest point.
struct SeamEffect {
  double hop = 0.0;
  double speedChange = 0.0;
  double turnChange = 0.0;
};

/// m. The distance of the shape's farthest point from its centre.
double reach(const Shape& shape) {
  double farthest = shape.radius;
  for (const Vec2& vertex : shape.vertices) farthest = std::max(farthest, vertex.norm());
  return farthest;
}

SeamEffect seamEffect(const Scene& seamed, const Scene& whole) {
  auto withSeam = buildWorld(seamed);
  auto withoutSeam = buildWorld(whole);
  const double arm = reach(whole.bodies.back().shape);
  SeamEffect effect;
  for (int step = 0; step < kSteps; ++step) {
    withSeam->step();
    withoutSeam->step();
    const Body& a = withSeam->bodies().back();
    const Body& b = withoutSeam->bodies().back();
    effect.hop = std::max(effect.hop, a.position.y() - b.position.y());
    effect.speedChange = std::max(effect.speedChange, (a.velocity - b.velocity).norm());
    effect.turnChange =
        std::max(effect.turnChange, std::abs(a.angularVelocity - b.angularVelocity) * arm);
  }
  return effect;
}

void checkMeetsOneSurface(const SeamEffect& effect) {
  CHECK(effect.hop <= kHopBound);
  CHECK(effect.speedChange <= kSpeedBound);
  CHECK(effect.turnChange <= kSpeedBound);
}

const std::vector<std::string> kMethods = {"micro", "sequential", "soft_step", "reference"};

}  // namespace

TEST_CASE("a disc rolling at 3 m/s across the seam of two flush boxes meets one surface",
          "[internal-edges][circle]") {
  for (const std::string& method : kMethods) {
    INFO(method);
    checkMeetsOneSurface(seamEffect(rollingDisc(method, true), rollingDisc(method, false)));
  }
}

TEST_CASE("a box sliding at 5 m/s across the seam of two flush boxes meets one surface",
          "[internal-edges][polygon]") {
  for (const double friction : {0.0, 0.3}) {
    for (const std::string& method : kMethods) {
      INFO(method << ", friction " << friction);
      checkMeetsOneSurface(
          seamEffect(slidingBox(method, true, friction), slidingBox(method, false, friction)));
    }
  }
}

TEST_CASE(
    "with internal edges not refused, the disc hops off the seam's corner and the box "
    "catches on the second box's side",
    "[internal-edges][switched-off]") {
  Scene disc = rollingDisc("micro", true);
  disc.world.refuseInternalEdges = false;
  const SeamEffect hop = seamEffect(disc, rollingDisc("micro", false));
  CHECK(hop.hop > 10 * kHopBound);
  CHECK(hop.speedChange > 10 * kSpeedBound);
  Scene box = slidingBox("soft_step", true, 0.0);
  box.world.refuseInternalEdges = false;
  const SeamEffect catchOnSide = seamEffect(box, slidingBox("soft_step", false, 0.0));
  CHECK(catchOnSide.turnChange > 1.0);
  CHECK(catchOnSide.speedChange > 1.0);
}

TEST_CASE(
    "a box resting in the corner of a wall standing flush on the floor keeps its contacts "
    "and stays put",
    "[internal-edges][polygon]") {
  Scene scene = solvers::groundScene("sequential", 0.5);
  BodyDef wall;
  wall.type = BodyType::Static;
  wall.shape = makeBox(0.2, 2.0);
  wall.position = Vec2(1.1, 1.0);  // its left face at x = 1, its foot on the ground
  scene.bodies.push_back(wall);
  BodyDef box = solvers::unitBoxMaterial(0.5);
  box.shape = makeBox(1.0, 1.0);
  box.position = Vec2(0.5, 0.5);  // touching the ground and the wall
  scene.bodies.push_back(box);
  auto world = buildWorld(scene);
  world->findContacts();
  int groundPoints = 0;
  int wallPoints = 0;
  for (const Manifold& manifold : world->manifolds()) {
    if (manifold.bodyA == 0 || manifold.bodyB == 0) groundPoints += manifold.pointCount;
    if (manifold.bodyA == 1 || manifold.bodyB == 1) wallPoints += manifold.pointCount;
  }
  CHECK(groundPoints == 2);
  CHECK(wallPoints == 2);
  solvers::runSteps(*world, solvers::stepsIn(1.0));
  const Body& rested = world->bodies().back();
  // It settles into the slop and no further, and does not turn.
  CHECK(rested.position.y() > 0.5 - ContactTargetSettings{}.allowedPenetration);
  CHECK(std::abs(rested.angle) < 1e-3);
}
