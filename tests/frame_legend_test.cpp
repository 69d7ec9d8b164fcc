// Frames that explain themselves (issue 16): forces at a scale fitted to the run, the friction
// gauge of each contact filling towards its limit, and the legend strip under the scene.
#include <catch2/catch.hpp>

#include <algorithm>

#include "impulse2d/render/frame.h"
#include "impulse2d/render/legend.h"
#include "render_fixtures.h"

using namespace impulse2d;
using namespace impulse2d::render;

namespace {

/// Sets every point's friction impulse to `use` of its limit μ λn, dynamic when on the limit.
void useFriction(test::FixedSimulation& simulation, double use) {
  Manifold& manifold = simulation.manifoldList[0];
  for (int i = 0; i < manifold.pointCount; ++i) {
    ContactPoint& point = manifold.points[i];
    point.tangentImpulse = use * manifold.friction * point.normalImpulse;
    point.friction = use >= 1.0 ? FrictionState::Dynamic : FrictionState::Static;
  }
}

/// The pixel a quarter along the gauge under the box's contact: filled from a use of 0.25 on.
Vec2 gaugeQuarter(const Camera& camera, const RenderSettings& settings, int width) {
  const double scale = frameTextScale(settings, width);
  return camera.toPixels(Vec2::Zero()) +
         Vec2(-0.25 * settings.gaugeLength * scale,
              settings.contactPointRadius + 2.0 + 0.5 * settings.gaugeThickness * scale);
}

}  // namespace

TEST_CASE("the force scale draws a resting box's contact force a fixed part of the frame",
          "[frame][forces]") {
  RenderSettings settings;
  const test::FixedSimulation simulation = test::boxOnGround();
  const Camera camera = fitCamera(simulation.bodies(), ViewDef{}, settings);
  // 1 kg on two points: m g / 2 = 4.905 N each.
  CHECK(restingForceEstimate(simulation.bodies(), Vec2(0.0, -9.81)) == Approx(4.905));
  const ForceScale forces =
      fitForceScale(simulation.bodies(), Vec2(0.0, -9.81), 0.01, camera, settings);
  CHECK(forces.dt == 0.01);
  CHECK(forces.metresPerNewton * camera.scale * 4.905 ==
        Approx(settings.restingForceLength * camera.height));
  settings.forceScale = 0.02;
  CHECK(fitForceScale(simulation.bodies(), Vec2(0.0, -9.81), 0.01, camera, settings)
            .metresPerNewton == 0.02);
}

TEST_CASE("the sample arrow's force is the 1-2-5 value nearest the resting force", "[legend]") {
  CHECK(roundForce(4.905) == Approx(5.0));
  CHECK(roundForce(1.4) == Approx(1.0));
  CHECK(roundForce(1.5) == Approx(2.0));
  CHECK(roundForce(7.5) == Approx(10.0));
  CHECK(roundForce(0.03) == Approx(0.02));
}

TEST_CASE("the friction gauge fills to |sum lt| / (mu sum ln) and turns red on the limit",
          "[frame][gauge]") {
  RenderSettings settings;
  test::FixedSimulation simulation = test::boxOnGround();
  simulation.manifoldList[0].friction = 0.5;
  const Camera camera = fitCamera(simulation.bodies(), ViewDef{}, settings);
  const Vec2 quarter = gaugeQuarter(camera, settings, camera.width);
  auto gaugeColour = [&] {
    FrameRenderer renderer(camera, "box", settings);
    const Canvas& frame = renderer.draw(simulation);
    return frame.at(int(quarter.x()), int(quarter.y()));
  };
  useFriction(simulation, 0.1);
  CHECK(frictionUse(simulation.manifoldList[0]) == Approx(0.1));
  CHECK(gaugeColour() == settings.colours.gaugeBackground);  // filled to 0.1: not a quarter
  useFriction(simulation, 0.6);
  CHECK(frictionUse(simulation.manifoldList[0]) == Approx(0.6));
  CHECK(gaugeColour() == settings.colours.staticFriction);
  useFriction(simulation, 1.0);
  CHECK(gaugeColour() == settings.colours.dynamicFriction);
  CHECK(classifyBodies(simulation.bodies(), simulation.manifolds(), settings)[1] ==
        BodyState::Sliding);
}

TEST_CASE("the legend strip goes under the scene and shows the states in the frame", "[legend]") {
  RenderSettings settings;
  const test::FixedSimulation simulation = test::boxOnGround();
  const Camera camera = fitCamera(simulation.bodies(), ViewDef{}, settings);
  FrameRenderer renderer(camera, "box", settings);
  const Canvas& frame = renderer.draw(simulation);
  REQUIRE(frame.height() == camera.height + legendHeight(settings, camera.width));
  const auto stripHas = [&](Color colour) {
    for (int y = camera.height; y < frame.height(); ++y) {
      for (int x = 0; x < frame.width(); ++x) {
        if (frame.at(x, y) == colour) return true;
      }
    }
    return false;
  };
  CHECK(stripHas(settings.colours.legendBackground));
  CHECK(stripHas(settings.colours.restingBody));  // the box rests: its swatch is there
  CHECK(stripHas(settings.colours.staticBody));
  CHECK_FALSE(stripHas(settings.colours.slidingBody));  // nothing slides: no swatch
  CHECK(stripHas(settings.colours.normalImpulse));      // the normal arrows and the sample

  settings.overlays.legend = false;
  FrameRenderer plain(camera, "box", settings);
  CHECK(plain.draw(simulation).height() == camera.height);
}
