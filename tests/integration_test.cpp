// Time stepping: semi-implicit (symplectic) Euler, v += a·dt then x += v·dt (world.h).
#include <catch2/catch.hpp>

#include "lecture_scenes.h"

using namespace impulse2d;

namespace {

/// The discrete solution of semi-implicit Euler after n steps from x0, v0 under constant a:
/// v_n = v0 + n·a·dt, x_n = x0 + n·dt·v0 + a·dt²·n(n+1)/2.
Vec2 discretePosition(const Vec2& x0, const Vec2& v0, const Vec2& a, double dt, int n) {
  return x0 + n * dt * v0 + a * dt * dt * (0.5 * n * (n + 1));
}

std::unique_ptr<World> worldWithOneBody(const Vec2& position, const Vec2& velocity, double omega) {
  Scene scene = lecture::sceneWith("micro", 1.0 / 60.0);
  BodyDef body;
  body.shape = makeBox(0.5, 0.25);
  body.position = position;
  body.velocity = velocity;
  body.angularVelocity = omega;
  scene.bodies.push_back(body);
  return buildWorld(scene);
}

}  // namespace

TEST_CASE("free fall equals the discrete semi-implicit Euler solution", "[integration]") {
  auto world = worldWithOneBody(Vec2(0.0, 10.0), Vec2::Zero(), 0.0);
  const Vec2 g = world->settings().gravity;
  for (int n = 1; n <= 100; ++n) {
    world->step();
    const Body& body = world->bodies()[0];
    CHECK((body.velocity - n * world->settings().dt * g).norm() < 1e-12);
    CHECK((body.position -
           discretePosition(Vec2(0.0, 10.0), Vec2::Zero(), g, world->settings().dt, n))
              .norm() < 1e-12);
  }
}

TEST_CASE("a projectile follows the discrete solution and spins at a constant rate",
          "[integration]") {
  const Vec2 x0(-3.0, 1.0);
  const Vec2 v0(4.0, 7.0);
  const double omega = 2.5;
  auto world = worldWithOneBody(x0, v0, omega);
  const double dt = world->settings().dt;
  for (int n = 1; n <= 100; ++n) {
    world->step();
    const Body& body = world->bodies()[0];
    CHECK((body.position - discretePosition(x0, v0, world->settings().gravity, dt, n)).norm() <
          1e-12);
    CHECK(body.angle == Approx(n * dt * omega).margin(1e-12));
    CHECK(body.angularVelocity == omega);
  }
}

TEST_CASE("a force and a torque act for one step and the acceleration is remembered",
          "[integration][acceleration]") {
  auto world = worldWithOneBody(Vec2(0.0, 10.0), Vec2::Zero(), 0.0);
  Body& body = world->bodies()[0];
  const Vec2 force(3.0, 1.0);
  const Vec2 arm(0.1, 0.0);
  body.applyForce(force, body.position + arm);
  const double dt = world->settings().dt;
  const Vec2 expectedAcceleration = world->settings().gravity + force / body.mass;
  const double expectedOmega = dt * cross(arm, force) / body.inertia;
  world->step();
  const Body& after = world->bodies()[0];
  CHECK((after.lastAcceleration - expectedAcceleration).norm() < 1e-12);
  CHECK((after.velocity - dt * expectedAcceleration).norm() < 1e-12);
  CHECK(after.angularVelocity == Approx(expectedOmega).epsilon(1e-12));
  world->step();
  CHECK((world->bodies()[0].lastAcceleration - world->settings().gravity).norm() < 1e-12);
}

TEST_CASE("static bodies do not move and have no inverse mass", "[integration][static]") {
  Scene scene = lecture::sceneWith("micro", 1.0 / 60.0);
  scene.bodies.push_back(lecture::ground(0.5));
  auto world = buildWorld(scene);
  for (int n = 0; n < 10; ++n) world->step();
  const Body& ground = world->bodies()[0];
  CHECK(ground.inverseMass == 0.0);
  CHECK(ground.inverseInertia == 0.0);
  CHECK(ground.position == scene.bodies[0].position);
  CHECK(ground.velocity == Vec2::Zero());
}
