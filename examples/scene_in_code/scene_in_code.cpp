// A first program on impulse2d: a scene built in code (a ball thrown at a stack of three boxes),
// stepped for three seconds by sequential impulses, every tenth step written as a PNG frame,
// then a contact sheet of them all.
//   scene_in_code [FRAMES]    frames go to FRAMES/scene_in_code/ (FRAMES defaults to "frames")
#include <cstdio>
#include <exception>
#include <string>

#include "impulse2d/render/camera.h"
#include "impulse2d/render/frame.h"
#include "impulse2d/render/frame_writer.h"
#include "impulse2d/scene/scene.h"

using namespace impulse2d;

namespace {

constexpr int kSteps = 180;      // 3 s at the default 60 Hz
constexpr int kFrameEvery = 10;  // steps between frames

Scene ballAndStack() {
  Scene scene;
  scene.name = "scene_in_code";
  scene.solver = "sequential";

  BodyDef ground;
  ground.name = "ground";
  ground.type = BodyType::Static;
  ground.shape = makeBox(20.0, 1.0);
  ground.position = Vec2(0.0, -0.5);  // top face at y = 0
  scene.bodies.push_back(ground);

  BodyDef box;
  box.friction = 0.6;
  addStack(scene, 3, Vec2(1.0, 1.0), Vec2(2.0, 0.0), 0.0, box);

  BodyDef ball;
  ball.name = "ball";
  ball.shape = makeCircle(0.3);
  ball.position = Vec2(-4.0, 1.5);
  ball.velocity = Vec2(8.0, 2.0);  // m/s: thrown at the stack
  ball.density = 4.0;
  scene.bodies.push_back(ball);
  return scene;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string frames = argc > 1 ? argv[1] : "frames";
  try {
    const Scene scene = ballAndStack();
    auto world = buildWorld(scene);
    const render::RenderSettings settings;
    const render::Camera camera = render::fitCamera(world->bodies(), ViewDef{}, settings);
    render::FrameRenderer renderer(camera, scene.name, settings);
    render::FrameWriter writer(frames, scene.name, kFrameEvery, "", settings);
    for (long step = 0; step <= kSteps; ++step) {
      if (step > 0) world->step();
      if (writer.wants(step)) writer.write(step, renderer.draw(*world));
    }
    const auto sheet = writer.writeContactSheet();
    for (const Body& body : world->bodies()) {
      std::printf("%-8s x = %6.3f m  y = %6.3f m  angle = %6.3f rad\n", body.name.c_str(),
                  body.position.x(), body.position.y(), body.angle);
    }
    std::printf("%d frames in %s, contact sheet %s\n", writer.frameCount(),
                writer.directory().c_str(), sheet.c_str());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
  return 0;
}
