// Stacks and pyramids of resting contacts under the micro-collision resolver: many contacts
// sharing bodies, resolved worst first, must hold still.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

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

/// A column of unit boxes of the given densities (from the bottom) after 5 s: how far any box
/// moved from 1 s on, and the worst relative error of the support under a box (the normal
/// impulses of the manifold between it and the body below, over the step) against the weight of
/// it and every box above it.
struct MassRatioStack {
  double drift = 0.0;
  double worstSupportError = 0.0;
};

MassRatioStack runMassRatioStack(Scene scene, const std::vector<double>& densities) {
  scene.bodies.push_back(lecture::ground(0.6));
  for (size_t i = 0; i < densities.size(); ++i) {
    BodyDef box = lecture::boxOnSlope(Vec2(1.0, 1.0), 0.0, 0.6, double(i));
    box.density = densities[i];
    scene.bodies.push_back(box);
  }
  auto world = buildWorld(scene);
  while (world->stepCount() * kDt < 1.0 - 1e-9) world->step();
  std::vector<Vec2> start;
  for (const Body& body : world->bodies()) start.push_back(body.position);
  while (world->stepCount() * kDt < 5.0 - 1e-9) world->step();
  MassRatioStack result;
  for (size_t i = 0; i < start.size(); ++i) {
    result.drift = std::max(result.drift, (world->bodies()[i].position - start[i]).norm());
  }
  std::vector<double> support(world->bodies().size(), 0.0);
  for (const Manifold& manifold : world->manifolds()) {
    const int upper = std::max(manifold.bodyA, manifold.bodyB);  // the ground is body 0
    for (int p = 0; p < manifold.pointCount; ++p) {
      support[upper] += manifold.points[p].normalImpulse / kDt;
    }
  }
  for (size_t k = 1; k < support.size(); ++k) {
    double weightAbove = 0.0;
    for (size_t j = k; j < support.size(); ++j) {
      weightAbove += lecture::kGravity / world->bodies()[j].inverseMass;
    }
    result.worstSupportError =
        std::max(result.worstSupportError, std::abs(support[k] / weightAbove - 1.0));
  }
  return result;
}

BodyDef unitBox() {
  BodyDef material;
  material.friction = 0.6;
  return material;
}

/// m. How far a box `height` contacts above the ground may move while the stack stands: the boxes
/// start touching, and penetration resolution leaves each contact below it overlapping by at
/// most positionEpsilon, so the box sinks by at most height·positionEpsilon and moves no other
/// way. A stack that slides, leans or sinks further fails it.
double settlingBound(int height) {
  return height * MicroCollisionSettings{}.positionEpsilon;
}

}  // namespace

TEST_CASE("a 10-box stack stands for 10 s", "[stack][micro]") {
  Scene scene = lecture::sceneWith("micro", kDt);
  scene.bodies.push_back(lecture::ground(0.6));
  addStack(scene, 10, Vec2(1.0, 1.0), Vec2::Zero(), 0.0, unitBox());
  const double drift = largestDrift(scene, 10.0);
  std::cout << "figure: 10-box stack, micro: largest drift in 10 s " << drift << " m\n";
  CHECK(drift < settlingBound(10));
}

TEST_CASE("a 10-row pyramid stands for 10 s", "[stack][pyramid][micro]") {
  Scene scene = lecture::sceneWith("micro", kDt);
  scene.bodies.push_back(lecture::ground(0.6));
  addPyramid(scene, 10, Vec2(1.0, 1.0), Vec2::Zero(), unitBox());
  const double drift = largestDrift(scene, 10.0);
  std::cout << "figure: 10-row pyramid, micro: largest drift in 10 s " << drift << " m\n";
  CHECK(drift < settlingBound(10));  // the top box rests on a column of 10 contacts
}

// Mass ratios: a light box under a heavy one is where an iterative solver struggles (the heavy
// box's weight must pass through the light one). Box2D 2.4.1 at its defaults lets light-under-
// heavy columns (1, 10, 100; 1, 100; 1, 30, 1, 30) settle by 1.0 to 3.9 cm between 1 s and 5 s at
// 60 and 240 Hz and holds heavy-under-light ones (a probe outside the repository);
// micro and the reference hold them all still with every contact carrying the weight above it.
// Sequential impulses hold the graded columns; the alternating one is its failure mode (next test).
TEST_CASE("columns with mass ratios of 100 stand, every contact carrying the weight above it",
          "[stack][mass-ratio]") {
  const std::vector<std::vector<double>> graded = {{1, 10, 100}, {100, 10, 1}};
  const std::vector<double> alternating = {1, 100, 1, 100};
  for (const std::string solver : {"micro", "sequential", "reference"}) {
    std::vector<std::vector<double>> columns = graded;
    if (solver != "sequential") columns.push_back(alternating);
    for (const std::vector<double>& densities : columns) {
      const MassRatioStack column = runMassRatioStack(lecture::sceneWith(solver, kDt), densities);
      INFO(solver << ", densities from the bottom " << densities.front() << " ... "
                  << densities.back() << " (" << densities.size() << " boxes): drift 1-5 s "
                  << column.drift << " m, worst support error " << column.worstSupportError);
      CHECK(column.drift < 1e-3);
      CHECK(column.worstSupportError < 0.02);
    }
  }
}

// Sequential impulses pass a heavy box's weight through a light one only a fraction per sweep:
// with light and heavy boxes alternating (1, 100, 1, 100), 40 plain sweeps a step leave the
// contacts short, the column sinks past the slop and the bias pushes it back: it bobs by
// centimetres. Ten times the sweeps hold it, and so does the conjugate gradient's push at 40.
TEST_CASE(
    "sequential impulses: an alternating 1:100 column bobs at 40 plain sweeps, holds at 400 or "
    "with the conjugate gradient",
    "[stack][mass-ratio][sequential][failure-mode]") {
  const std::vector<double> alternating = {1, 100, 1, 100};
  Scene scene = lecture::sceneWith("sequential", kDt);
  const MassRatioStack pushed = runMassRatioStack(scene, alternating);
  scene.solverSettings.sequential.conjugateGradient = false;
  const MassRatioStack plain = runMassRatioStack(scene, alternating);
  scene.solverSettings.sequential.velocityIterations = 400;
  const MassRatioStack more = runMassRatioStack(scene, alternating);
  std::cout << "figure: alternating 1:100 column, sequential: drift 1-5 s " << plain.drift
            << " m at 40 plain sweeps, " << more.drift << " m at 400, " << pushed.drift
            << " m at 40 with the push\n";
  CHECK(plain.drift > 0.01);
  for (const MassRatioStack& held : {more, pushed}) {
    CHECK(held.drift < 1e-3);
    CHECK(held.worstSupportError < 0.02);
  }
}
