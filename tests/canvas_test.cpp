// The canvas, camera and frame contents: coverage of shapes to the pixel, colours by body state,
// overlays that can be turned off.
#include <cmath>

#include <catch2/catch.hpp>

#include "impulse2d/render/camera.h"
#include "impulse2d/render/canvas.h"
#include "impulse2d/render/frame.h"
#include "render_fixtures.h"

using namespace impulse2d;
using namespace impulse2d::render;

namespace {

const Color white{255, 255, 255, 255};
const Color black{0, 0, 0, 255};

/// How much of pixel (x, y) black ink covers on a white canvas, in [0, 1].
double inkCoverage(const Canvas& canvas, int x, int y) {
  return 1.0 - canvas.at(x, y).r / 255.0;
}

double totalInk(const Canvas& canvas) {
  double sum = 0.0;
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) sum += inkCoverage(canvas, x, y);
  }
  return sum;
}

/// Signed distance (pixels, positive inside) of point p from the convex polygon's nearest edge
/// line; the polygon is counter-clockwise in pixel coordinates.
double insideDistance(const std::vector<Vec2>& polygon, const Vec2& p) {
  double inside = 1e9;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 edge = polygon[(i + 1) % polygon.size()] - polygon[i];
    inside = std::min(inside, cross(edge, Vec2(p - polygon[i])) / edge.norm());
  }
  return inside;
}

}  // namespace

TEST_CASE("A box on pixel boundaries covers exactly its pixels", "[canvas][polygon]") {
  Canvas canvas(64, 48, white);
  fillConvexPolygon(canvas, {{10, 20}, {30, 20}, {30, 35}, {10, 35}}, black, black, 0.0);
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      const bool inside = x >= 10 && x < 30 && y >= 20 && y < 35;
      REQUIRE(canvas.at(x, y) == (inside ? black : white));
    }
  }
}

TEST_CASE("A rotated box covers every pixel inside, none outside, its area in all",
          "[canvas][polygon][antialiasing]") {
  Canvas canvas(120, 120, white);
  const Mat2 turn = rotation(0.3);
  std::vector<Vec2> box;
  for (const Vec2& corner : {Vec2(-30, -20), Vec2(30, -20), Vec2(30, 20), Vec2(-30, 20)}) {
    box.push_back(Vec2(60.3, 59.8) + turn * corner);
  }
  fillConvexPolygon(canvas, box, black, black, 0.0);
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      const double inside = insideDistance(box, Vec2(x + 0.5, y + 0.5));
      if (inside > 0.75) REQUIRE(canvas.at(x, y) == black);   // edges aside: a pixel's half
      if (inside < -0.75) REQUIRE(canvas.at(x, y) == white);  // diagonal is ~0.71
    }
  }
  CHECK(totalInk(canvas) == Approx(60.0 * 40.0).epsilon(0.005));
}

TEST_CASE("A circle's covered area is within 1% of pi r^2", "[canvas][circle][antialiasing]") {
  for (const double radius : {3.0, 7.3, 20.5, 55.0}) {
    Canvas canvas(128, 128, white);
    fillCircle(canvas, Vec2(64.37, 63.81), radius, black, black, 0.0);
    CHECK(totalInk(canvas) == Approx(std::acos(-1.0) * radius * radius).epsilon(0.01));
  }
}

TEST_CASE("An outline lines the inside of a shape's edge", "[canvas][outline]") {
  const Color fill{0, 200, 0, 255};
  Canvas canvas(40, 40, white);
  fillConvexPolygon(canvas, {{10, 10}, {30, 10}, {30, 30}, {10, 30}}, fill, black, 2.0);
  CHECK(canvas.at(10, 20) == black);  // first pixel column inside the left edge
  CHECK(canvas.at(11, 20) == black);
  CHECK(canvas.at(12, 20) == fill);
  CHECK(canvas.at(20, 20) == fill);
  CHECK(canvas.at(9, 20) == white);
}

TEST_CASE("A line covers a band of its width; an arrow ends at its tip", "[canvas][line]") {
  Canvas canvas(60, 60, white);
  drawLine(canvas, Vec2(10, 20), Vec2(50, 20), 2.0, black);
  for (int x = 10; x < 50; ++x) {
    REQUIRE(canvas.at(x, 19) == black);
    REQUIRE(canvas.at(x, 20) == black);
    REQUIRE(canvas.at(x, 18) == white);
    REQUIRE(canvas.at(x, 21) == white);
  }
  drawArrow(canvas, Vec2(10, 40), Vec2(40, 40), 2.0, 8.0, 8.0, black);
  CHECK(inkCoverage(canvas, 38, 39) > 0.5);  // inside the head, near the tip
  CHECK(canvas.at(41, 39) == white);         // beyond the tip
  CHECK(canvas.at(33, 37) == black);         // the head is wider than the shaft
  CHECK(canvas.at(20, 37) == white);
}

TEST_CASE("Text is drawn inside its measured box", "[canvas][text]") {
  Canvas canvas(200, 40, white);
  const std::string text = "step 120";
  const Vec2 corner(5, 5);
  drawText(canvas, text, corner, 2.0, black);
  const double right = corner.x() + textWidth(text, 2.0);
  const double bottom = corner.y() + textHeight(2.0);
  double inside = 0.0;
  for (int y = 0; y < canvas.height(); ++y) {
    for (int x = 0; x < canvas.width(); ++x) {
      const bool inBox = x >= corner.x() && x < right && y >= corner.y() && y < bottom;
      if (inBox) inside += inkCoverage(canvas, x, y);
      if (!inBox) REQUIRE(canvas.at(x, y) == white);
    }
  }
  CHECK(inside > 50.0);  // eight glyphs of ~2×2-pixel strokes
}

TEST_CASE("The camera maps metres, y up, to pixels, y down", "[camera]") {
  Camera camera;
  camera.width = 200;
  camera.height = 100;
  camera.centre = Vec2(1.0, 2.0);
  camera.scale = 10.0;
  CHECK(camera.toPixels(Vec2(1.0, 2.0)).isApprox(Vec2(100.0, 50.0)));
  CHECK(camera.toPixels(Vec2(2.0, 3.0)).isApprox(Vec2(110.0, 40.0)));  // up is smaller y
  CHECK(camera.toWorld(camera.toPixels(Vec2(-3.5, 7.25))).isApprox(Vec2(-3.5, 7.25)));
}

TEST_CASE("A fitted camera shows the dynamic bodies and the ground under them", "[camera]") {
  RenderSettings settings;
  const test::FixedSimulation simulation = test::boxOnGround();
  const Camera camera = fitCamera(simulation.bodies(), ViewDef{}, settings);
  const Vec2 boxTop = camera.toPixels(Vec2(0.5, 1.0));
  const Vec2 inGround = camera.toPixels(Vec2(0.0, -0.2));
  const double headsUp = 2.0 * headsUpHeight(settings, camera.width);
  CHECK(boxTop.y() >= headsUp);  // below the two heads-up lines
  CHECK(inGround.y() < camera.height);
  // The 10 m ground is cut to the box's surroundings (a quarter of its 1 m size either side:
  // staticFitReach), so the box fills most of the height rather than a tenth of the width.
  const double boxHeight = camera.toPixels(Vec2(0.0, 0.0)).y() - boxTop.y();
  CHECK(boxHeight > 0.6 * (camera.height - headsUp));

  // A traced step's frame has a third heads-up line (the solver event): the fit leaves room for
  // it, so the scene starts as far below the third line as it did below the second.
  RenderSettings traced = settings;
  traced.headsUpLines = 3;
  const Camera tracedCamera = fitCamera(simulation.bodies(), ViewDef{}, traced);
  const double lineHeight = headsUpHeight(settings, camera.width);
  CHECK(tracedCamera.toPixels(Vec2(0.5, 1.0)).y() - 3.0 * lineHeight ==
        Approx(boxTop.y() - 2.0 * lineHeight).margin(1.0));

  ViewDef view;
  view.centre = Vec2(3.0, 4.0);
  view.scale = 25.0;
  const Camera given = fitCamera(simulation.bodies(), view, settings);
  CHECK(given.toPixels(Vec2(3.0, 4.0)).isApprox(Vec2(400.0, 300.0)));
  CHECK(given.scale == 25.0);
}

TEST_CASE("Bodies are classed static, flying, resting, touching or sliding", "[frame][state]") {
  RenderSettings settings;
  test::FixedSimulation simulation = test::boxOnGround();
  simulation.bodyList.push_back(
      makeBody("ball", BodyType::Dynamic, makeCircle(0.5), 1.0, Vec2(3.0, 3.0), 0.0));
  auto states = [&] {
    return classifyBodies(simulation.bodies(), simulation.manifolds(), settings);
  };
  CHECK(states()[0] == BodyState::Static);
  CHECK(states()[1] == BodyState::Resting);
  CHECK(states()[2] == BodyState::Flying);
  simulation.bodyList[1].velocity = Vec2(0.0, 1.0);  // lifting off: moving, not slipping
  CHECK(states()[1] == BodyState::Touching);
  simulation.bodyList[1].velocity = Vec2(1.0, 0.0);  // slipping along the ground
  CHECK(states()[1] == BodyState::Sliding);
  simulation.bodyList[1].velocity = Vec2::Zero();
  simulation.manifoldList[0].points[1].friction = FrictionState::Dynamic;
  CHECK(states()[1] == BodyState::Resting);  // one point of two at its limit: the pair holds
  simulation.manifoldList[0].points[0].friction = FrictionState::Dynamic;
  CHECK(states()[1] == BodyState::Sliding);
}

TEST_CASE("A frame colours each body by its state; overlays can be turned off", "[frame]") {
  RenderSettings settings;
  const test::FixedSimulation simulation = test::boxOnGround();
  const Camera camera = fitCamera(simulation.bodies(), ViewDef{}, settings);
  FrameRenderer renderer(camera, "box", settings);
  const Canvas& frame = renderer.draw(simulation);
  const Vec2 inBox = camera.toPixels(Vec2(-0.25, 0.75));
  const Vec2 inGround = camera.toPixels(Vec2(-0.6, -0.1));
  CHECK(frame.at(int(inBox.x()), int(inBox.y())) == settings.colours.restingBody);
  CHECK(frame.at(int(inGround.x()), int(inGround.y())) == settings.colours.staticBody);
  const Vec2 impulseArrow = camera.toPixels(Vec2(0.5, 0.04));
  CHECK(frame.at(int(impulseArrow.x()), int(impulseArrow.y())) == settings.colours.normalImpulse);

  Overlays& show = settings.overlays;
  show.rotationMarks = show.contactPoints = show.contactNormals = false;
  show.normalImpulses = show.frictionImpulses = show.velocities = show.headsUp = false;
  show.frictionGauges = show.legend = false;
  FrameRenderer plain(camera, "box", settings);
  const Canvas& bare = plain.draw(simulation);
  const std::vector<Color> allowed{settings.colours.background, settings.colours.restingBody,
                                   settings.colours.staticBody, settings.colours.outline};
  int foreign = 0;
  for (const Color& pixel : bare.pixels()) {
    foreign += std::find(allowed.begin(), allowed.end(), pixel) == allowed.end();
  }
  // Only edge pixels mix colours: no arrows, dots, marks or text remain.
  CHECK(foreign < 4 * (camera.width + camera.height));
  CHECK(bare.at(int(impulseArrow.x()), int(impulseArrow.y())) != settings.colours.normalImpulse);
}
