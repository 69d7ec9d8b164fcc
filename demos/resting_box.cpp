// Console demo of lecture 3.6: a box with restitution 0.5 dropped onto the ground, resolved by
// micro-collisions. Prints, every few steps, the box's height and vertical speed with the
// accelerative-velocity fix on and with both fixes off, side by side: the first settles, the
// second keeps making mini-bounces.
#include <cstdio>

#include "impulse2d/scene/scene.h"

using namespace impulse2d;

namespace {

Scene droppedBox(bool fixesOn) {
  Scene scene;
  scene.solver = "micro";
  scene.solverSettings.micro.removeAccelerationVelocity = fixesOn;
  scene.solverSettings.micro.lowerRestitutionAtLowSpeed = fixesOn;
  BodyDef ground;
  ground.name = "ground";
  ground.type = BodyType::Static;
  ground.shape = makeBox(20.0, 1.0);
  ground.position = Vec2(0.0, -0.5);
  scene.bodies.push_back(ground);
  BodyDef box;
  box.name = "box";
  box.shape = makeBox(1.0, 1.0);
  box.position = Vec2(0.0, 1.0);
  box.restitution = 0.5;
  scene.bodies.push_back(box);
  return scene;
}

}  // namespace

int main() {
  auto fixed = buildWorld(droppedBox(true));
  auto unfixed = buildWorld(droppedBox(false));
  std::printf("micro-collisions: a box (restitution 0.5) dropped 0.5 m onto the ground\n");
  std::printf("%6s %8s | %12s %12s | %12s %12s\n", "step", "t (s)", "height fixed", "vy fixed",
              "height no-fix", "vy no-fix");
  constexpr int kSteps = 240;
  constexpr int kPrintEvery = 10;
  for (int step = 1; step <= kSteps; ++step) {
    fixed->step();
    unfixed->step();
    if (step % kPrintEvery != 0) continue;
    const Body& a = fixed->bodies()[1];
    const Body& b = unfixed->bodies()[1];
    std::printf("%6d %8.3f | %12.6f %12.6f | %12.6f %12.6f\n", step, step * fixed->settings().dt,
                a.position.y() - 0.5, a.velocity.y(), b.position.y() - 0.5, b.velocity.y());
  }
  return 0;
}
