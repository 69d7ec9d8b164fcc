// No allocation inside a step once a scene has settled: contacts, manifolds and solver states
// reuse their storage. This program replaces the global operator new to count allocations.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <new>

#include "solver_scenes.h"

namespace {

/// Allocations made while `counting` is set.
long allocations = 0;
bool counting = false;

/// Allocations made by `steps` steps of the world.
long allocationsDuring(impulse2d::World& world, int steps) {
  allocations = 0;
  counting = true;
  solvers::runSteps(world, steps);
  counting = false;
  return allocations;
}

}  // namespace

void* operator new(std::size_t size) {
  if (counting) ++allocations;
  if (void* memory = std::malloc(size == 0 ? 1 : size)) return memory;
  throw std::bad_alloc();
}

void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  if (counting) ++allocations;
  return std::malloc(size == 0 ? 1 : size);
}

// Every other form is replaced too, so that no block allocated by one allocator is freed by
// another (AddressSanitizer reports that as alloc-dealloc-mismatch).
void* operator new[](std::size_t size) {
  return operator new(size);
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
  return operator new(size, tag);
}
void operator delete(void* memory) noexcept {
  std::free(memory);
}
void operator delete(void* memory, std::size_t) noexcept {
  std::free(memory);
}
void operator delete(void* memory, const std::nothrow_t&) noexcept {
  std::free(memory);
}
void operator delete[](void* memory) noexcept {
  std::free(memory);
}
void operator delete[](void* memory, std::size_t) noexcept {
  std::free(memory);
}
void operator delete[](void* memory, const std::nothrow_t&) noexcept {
  std::free(memory);
}

using namespace impulse2d;

TEST_CASE("the counter sees the first step of a fresh world allocate its contacts",
          "[allocation]") {
  auto world = buildWorld(solvers::pyramidScene("sequential", 5, 0.6));
  CHECK(allocationsDuring(*world, 1) > 0);
}

TEST_CASE("a settled awake pyramid steps without allocating", "[allocation]") {
  for (const std::string solver : {"micro", "sequential"}) {
    Scene scene = solvers::pyramidScene(solver, 5, 0.6);
    scene.world.sleep = Sleep::Off;
    auto world = buildWorld(scene);
    solvers::runSteps(*world, solvers::stepsIn(2.0));
    INFO(solver);
    CHECK(allocationsDuring(*world, 100) == 0);
  }
}

TEST_CASE("a pyramid falling asleep and sleeping steps without allocating", "[allocation]") {
  for (const std::string solver : {"micro", "sequential"}) {
    Scene scene = solvers::pyramidScene(solver, 5, 0.6);
    scene.world.sleep = Sleep::KeepSpeedingUpAwake;
    auto world = buildWorld(scene);
    solvers::runSteps(*world, solvers::stepsIn(0.5));
    INFO(solver);
    CHECK(allocationsDuring(*world, 100) == 0);
    CHECK(world->lastStepStatistics().awakeBodies == 0);
  }
}
