// The analytic checks (analytic_checks.h). Each runs its shipped scene for the scene's steps.
#include "analytic_checks.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "benchmark_scenes.h"
#include "impulse2d/box2d/box2d_simulation.h"

using namespace impulse2d;

namespace benchmarks {

namespace {

int bodyIndex(const Scene& scene, const std::string& name) {
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].name == name) return static_cast<int>(i);
  }
  throw std::invalid_argument("scene " + scene.name + " has no body " + name);
}

/// Unit vector down the slope of a ramp turned by `angle` (counter-clockwise, rising right).
Vec2 downSlope(double angle) {
  return Vec2(-std::cos(angle), -std::sin(angle));
}

struct SlopeRun {
  Scene scene;
  double angle = 0.0;  ///< rad, of the ramp
  double time = 0.0;   ///< s, of the run
  Vec2 displacement;   ///< m, of the body over the run
  Vec2 finalVelocity;  ///< m/s
};

SlopeRun runOnSlope(const std::string& sceneName, const std::string& solver,
                    const std::string& bodyName) {
  SlopeRun run{withMethod(shippedScene(sceneName), solver, 0), 0.0, 0.0, Vec2::Zero(),
               Vec2::Zero()};
  const int body = bodyIndex(run.scene, bodyName);
  run.angle = run.scene.bodies[bodyIndex(run.scene, "ramp")].angle;
  run.time = run.scene.steps * run.scene.world.dt;
  std::unique_ptr<Simulation> simulation = makeSimulation(run.scene);
  const Vec2 start = simulation->bodies()[body].position;
  for (int step = 0; step < run.scene.steps; ++step) simulation->step();
  run.displacement = simulation->bodies()[body].position - start;
  run.finalVelocity = simulation->bodies()[body].velocity;
  return run;
}

/// Slides from rest at g(sin θ − μ cos θ): d = ½ a t².
AnalyticCheck inclineSlide(const std::string& solver) {
  const SlopeRun run = runOnSlope("incline_slides", solver, "box");
  const double mu = mixFriction(run.scene.bodies[bodyIndex(run.scene, "ramp")].friction,
                                run.scene.bodies[bodyIndex(run.scene, "box")].friction);
  const double g = -run.scene.world.gravity.y();
  const double acceleration = g * (std::sin(run.angle) - mu * std::cos(run.angle));
  return {"incline_slides", "slide distance (m)", 0.5 * acceleration * run.time * run.time,
          run.displacement.dot(downSlope(run.angle))};
}

/// Rolls without slipping at (2/3) g sin θ: measured as the final speed over the time.
AnalyticCheck rollingAcceleration(const std::string& solver) {
  const SlopeRun run = runOnSlope("rolling_disk", solver, "disk");
  const double g = -run.scene.world.gravity.y();
  return {"rolling_disk", "acceleration (m/s²)", 2.0 / 3.0 * g * std::sin(run.angle),
          run.finalVelocity.dot(downSlope(run.angle)) / run.time};
}

/// Static friction holds the box: it should not move at all.
AnalyticCheck staticHold(const std::string& solver) {
  const SlopeRun run = runOnSlope("incline_holds", solver, "box");
  return {"incline_holds", "drift (m)", 0.0, run.displacement.norm()};
}

/// The first bounce rises to e²h (h the drop height of the ball's bottom).
AnalyticCheck bounceApex(const std::string& solver) {
  const Scene scene = withMethod(shippedScene("bouncing_ball"), solver, 0);
  const int ball = bodyIndex(scene, "ball");
  const BodyDef& definition = scene.bodies[ball];
  const double radius = definition.shape.radius;
  std::unique_ptr<Simulation> simulation = makeSimulation(scene);
  bool bounced = false;
  double apex = 0.0;
  for (int step = 0; step < scene.steps; ++step) {
    simulation->step();
    const Body& body = simulation->bodies()[ball];
    if (body.velocity.y() > 0.0) bounced = true;
    if (bounced) apex = std::max(apex, body.position.y() - radius);
    if (bounced && body.velocity.y() <= 0.0) break;
  }
  const double dropHeight = definition.position.y() - radius;
  const double e = definition.restitution;
  return {"bouncing_ball", "bounce apex (m)", e * e * dropHeight, apex};
}

}  // namespace

std::vector<AnalyticCheck> analyticChecks(const std::string& solver) {
  return {inclineSlide(solver), bounceApex(solver), rollingAcceleration(solver),
          staticHold(solver)};
}

}  // namespace benchmarks
