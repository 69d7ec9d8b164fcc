// Stacks and pyramids of resting contacts under the micro-collision resolver: many contacts
// sharing bodies, resolved worst first, must hold still.
#include <catch2/catch.hpp>

#include <iostream>

#include "lecture_scenes.h"

using namespace impulse2d;

namespace {

constexpr double kDt = 1.0 / 60.0;

/// Largest distance any dynamic body moved from its start over `seconds`.
double largestDrift(const Scene& scene, double seconds) {
  auto world = buildWorld(scene);
  std::vector<Vec2> start;
  for (const Body& body : world->bodies()) start.push_back(body.position);
  while (world->stepCount() * kDt < seconds - 1e-9) world->step();
  double largest = 0.0;
  for (size_t i = 0; i < start.size(); ++i) {
    largest = std::max(largest, (world->bodies()[i].position - start[i]).norm());
  }
  return largest;
}

BodyDef unitBox() {
  BodyDef material;
  material.friction = 0.6;
  return material;
}

}  // namespace

TEST_CASE("a 10-box stack stands for 10 s", "[stack][micro]") {
  Scene scene = lecture::sceneWith("micro", kDt);
  scene.bodies.push_back(lecture::ground(0.6));
  addStack(scene, 10, Vec2(1.0, 1.0), Vec2::Zero(), 0.0, unitBox());
  const double drift = largestDrift(scene, 10.0);
  std::cout << "figure: 10-box stack, micro: largest drift in 10 s " << drift << " m\n";
  CHECK(drift < 0.05);
}

TEST_CASE("a 10-row pyramid stands for 10 s", "[stack][pyramid][micro]") {
  Scene scene = lecture::sceneWith("micro", kDt);
  scene.bodies.push_back(lecture::ground(0.6));
  addPyramid(scene, 10, Vec2(1.0, 1.0), Vec2::Zero(), unitBox());
  const double drift = largestDrift(scene, 10.0);
  std::cout << "figure: 10-row pyramid, micro: largest drift in 10 s " << drift << " m\n";
  CHECK(drift < 0.05);
}
