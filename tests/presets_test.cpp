// Presets: each method as its authors published it. What a preset sets is the published
// method's, shown by what the method does: Box2D 2.4.1 moves overlaps out by its position pass
// alone and holds a 40-row pyramid at 8 + 3 iterations; Box2D-Lite does not bounce.
#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>

#include "impulse2d/presets.h"
#include "impulse2d/world.h"
#include "solver_scenes.h"

using namespace impulse2d;
using namespace solvers;

namespace {

Scene withPreset(Scene scene, const std::string& name) {
  const Preset* preset = findPreset(scene.solver, name);
  REQUIRE(preset != nullptr);
  preset->apply(scene.solverSettings);
  scene.preset = name;
  return scene;
}

/// A unit box at rest whose bottom face sits `overlap` below the ground's top face.
Scene overlappingBox(double overlap) {
  Scene scene = groundScene("sequential", 0.6);
  BodyDef box = unitBoxMaterial(0.6);
  box.position = Vec2(0.0, 0.5 - overlap);
  scene.bodies.push_back(box);
  return scene;
}

/// m. The largest distance any box moved between `settle` and `end` seconds; looked at once a
/// second, the run stops early once that passes `enough`.
double settledDrift(const Scene& scene, double settle, double end,
                    double enough = std::numeric_limits<double>::infinity()) {
  auto world = buildWorld(scene);
  runSteps(*world, stepsIn(settle));
  const std::vector<Body> settled = world->bodies();
  double drift = 0.0;
  for (double time = settle; time < end && drift <= enough; time += 1.0) {
    runSteps(*world, stepsIn(std::min(1.0, end - time)));
    for (size_t i = 0; i < settled.size(); ++i) {
      drift = std::max(drift, (world->bodies()[i].position - settled[i].position).norm());
    }
  }
  return drift;
}

}  // namespace

TEST_CASE("every preset names a solver, and each solver's first preset is its published method",
          "[preset]") {
  for (const Preset& preset : presets()) {
    INFO(preset.solver << " " << preset.name);
    CHECK(findPreset(preset.solver, preset.name) == &preset);
    CHECK(publishedMethod(preset.solver, preset.name) == &preset);
    CHECK_FALSE(preset.summary.empty());
  }
  CHECK(publishedMethod("micro", "")->name == "lecture");
  CHECK(publishedMethod("sequential", "")->name == "box2d_lite");
  CHECK(publishedMethod("soft_step", "")->name == "box2d_v3");
  CHECK(publishedMethod("reference", "") == nullptr);
  CHECK(findPreset("micro", "box2d_2_4") == nullptr);
  CHECK(presetNames("sequential") == "'box2d_lite', 'box2d_2_4'");
}

TEST_CASE("box2d_2_4 leaves an overlap to the position pass: the solve adds no velocity",
          "[preset][box2d_2_4][bias]") {
  constexpr double kOverlap = 0.05;
  const Scene ours = overlappingBox(kOverlap);
  const Scene box2d = withPreset(ours, "box2d_2_4");
  const SequentialImpulseSettings& settings = ours.solverSettings.sequential;
  // Our default asks the overlap beyond the slop back at the bias rate: 0.2 × 0.045 m / dt.
  auto biased = buildWorld(ours);
  biased->step();
  const double biasVelocity =
      settings.targets.biasFactor * (kOverlap - settings.targets.allowedPenetration) / kDt;
  CHECK(biased->bodies()[1].velocity.y() == Approx(biasVelocity).epsilon(1e-6));
  // Box2D 2.4.1 targets zero normal velocity and moves the box out by positions alone.
  auto unbiased = buildWorld(box2d);
  unbiased->step();
  CHECK(std::abs(unbiased->bodies()[1].velocity.y()) < 1e-9);
  CHECK(unbiased->bodies()[1].position.y() > 0.5 - kOverlap + 0.01);
}

TEST_CASE("box2d_2_4 holds a 40-row pyramid at 8 + 3 iterations; with the velocity bias it falls",
          "[preset][box2d_2_4][pyramid]") {
  const Scene box2d = withPreset(pyramidScene("sequential", 40, 0.6), "box2d_2_4");
  // Box2D 2.4.1 itself drifts 0.45 m from 1 s to 10 s on this pyramid (benchmarks/solver_benchmark
  // --speed); the preset holds within that.
  const double drift = settledDrift(box2d, 1.0, 10.0);
  INFO("drift " << drift);
  CHECK(drift < 0.45);
  Scene biased = box2d;
  biased.solverSettings.sequential.targets.penetrationBias = true;
  const double biasedDrift = settledDrift(biased, 1.0, 10.0, 1.0);
  INFO("biased drift " << biasedDrift);
  CHECK(biasedDrift > 1.0);
}

TEST_CASE("box2d_lite has no bounce and no position pass", "[preset][box2d_lite]") {
  Scene scene = groundScene("sequential", 0.6);
  scene.world.gravity = Vec2::Zero();
  BodyDef ball = unitBoxMaterial(0.6);
  ball.shape = makeCircle(0.5);
  ball.position = Vec2(0.0, 0.5);
  ball.velocity = Vec2(0.0, -5.0);
  ball.restitution = 1.0;
  scene.bodies.push_back(ball);
  auto ours = buildWorld(scene);
  auto lite = buildWorld(withPreset(scene, "box2d_lite"));
  ours->step();
  lite->step();
  CHECK(ours->bodies()[1].velocity.y() == Approx(5.0).epsilon(1e-9));  // e = 1 above 1 m/s
  CHECK(std::abs(lite->bodies()[1].velocity.y()) < 1e-9);
  CHECK(SequentialImpulseSettings::box2dLite().positionPass.iterations == 0);
}
