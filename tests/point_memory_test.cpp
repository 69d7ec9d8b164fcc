// What a method keeps per contact point between steps (solvers/point_memory.h) follows the rules
// the world follows for impulses: a point keeps its state while the same features touch, a new
// point starts from nothing, a sleeping pair keeps its states until it wakes, and a pair that
// stopped touching forgets them.
#include <catch2/catch.hpp>

#include <vector>

#include "impulse2d/body.h"
#include "impulse2d/contact.h"
#include "impulse2d/solvers/point_memory.h"

using namespace impulse2d;

namespace {

/// Three dynamic bodies and the static ground (body 3).
std::vector<Body> bodies() {
  std::vector<Body> all;
  for (int i = 0; i < 3; ++i) {
    all.push_back(makeBody("box", BodyType::Dynamic, makeBox(1.0, 1.0), 1.0, Vec2(i, 0.5), 0.0));
  }
  all.push_back(makeBody("ground", BodyType::Static, makeBox(10.0, 1.0), 1.0, Vec2::Zero(), 0.0));
  return all;
}

Manifold manifold(int bodyA, int bodyB, std::vector<FeatureId> ids) {
  Manifold result;
  result.bodyA = bodyA;
  result.bodyB = bodyB;
  result.pointCount = static_cast<int>(ids.size());
  for (int i = 0; i < result.pointCount; ++i) result.points[i].id = ids[i];
  return result;
}

/// One solve: recalls, then stores `value` + the recalled value at every point.
std::vector<int> solve(PointMemory<int>& memory, const std::vector<Manifold>& manifolds,
                       const std::vector<Body>& all, int value) {
  memory.recall(manifolds);
  std::vector<int> recalled;
  for (int m = 0; m < static_cast<int>(manifolds.size()); ++m) {
    for (int i = 0; i < manifolds[m].pointCount; ++i) {
      recalled.push_back(memory.recalled(m, i));
      memory.store(m, i, value + memory.recalled(m, i));
    }
  }
  memory.remember(manifolds, all);
  return recalled;
}

}  // namespace

TEST_CASE("a point keeps its state by feature id; a new point starts from nothing",
          "[point-memory]") {
  const std::vector<Body> all = bodies();
  PointMemory<int> memory;
  CHECK(solve(memory, {manifold(0, 3, {7, 8}), manifold(1, 3, {7})}, all, 10) ==
        std::vector<int>{0, 0, 0});
  // Box 0 now touches with feature 8 and a new feature 9; box 1's point keeps its feature.
  CHECK(solve(memory, {manifold(0, 3, {9, 8}), manifold(1, 3, {7})}, all, 1) ==
        std::vector<int>{0, 10, 10});
}

TEST_CASE("a pair that stops touching forgets its states; a sleeping pair keeps them",
          "[point-memory][sleeping]") {
  std::vector<Body> all = bodies();
  PointMemory<int> memory;
  solve(memory, {manifold(0, 3, {1}), manifold(1, 3, {1}), manifold(2, 3, {1})}, all, 5);
  // Box 1 falls asleep; box 2 is awake but lifted off: neither pair is solved this step.
  all[1].asleep = true;
  solve(memory, {manifold(0, 3, {1})}, all, 5);
  // Both touch again: box 1 (woken) finds its state, box 2 starts from nothing.
  all[1].asleep = false;
  CHECK(solve(memory, {manifold(0, 3, {1}), manifold(1, 3, {1}), manifold(2, 3, {1})}, all, 0) ==
        std::vector<int>{10, 5, 0});
}

TEST_CASE("manifolds in any order find their states", "[point-memory]") {
  const std::vector<Body> all = bodies();
  PointMemory<int> memory;
  solve(memory, {manifold(2, 3, {4}), manifold(0, 1, {2}), manifold(1, 2, {3})}, all, 1);
  CHECK(solve(memory, {manifold(1, 2, {3}), manifold(2, 3, {4}), manifold(0, 1, {2})}, all, 0) ==
        std::vector<int>{1, 1, 1});
  CHECK(solve(memory, {manifold(0, 1, {2}), manifold(1, 2, {3}), manifold(2, 3, {4})}, all, 0) ==
        std::vector<int>{1, 1, 1});
}
