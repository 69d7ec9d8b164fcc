// What a frame draws, read back from the drawing calls (DrawingLog) and from the files: forces to
// one scale, the friction limit on its arrow, a legend naming only what is drawn, the heads-up
// strip never over a body, symbols as text in the PDF, and the PNG and SVG of a frame agreeing.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include "impulse2d/render/frame.h"
#include "impulse2d/render/legend.h"
#include "impulse2d/render/png.h"
#include "impulse2d/render/trace.h"
#include "render_fixtures.h"

using namespace impulse2d;
using namespace impulse2d::render;
namespace fs = std::filesystem;

namespace {

std::vector<DrawnShape> withRole(const DrawingLog& log, const std::string& role) {
  std::vector<DrawnShape> shapes;
  for (const DrawnShape& shape : log) {
    if (shape.role == role) shapes.push_back(shape);
  }
  return shapes;
}

double length(const DrawnShape& arrow) {
  return (arrow.points[1] - arrow.points[0]).norm();
}

/// The box on the ground, pushed with 3 N at its left side's middle, its friction `use` of μ λn.
test::FixedSimulation pushedBox(double use) {
  test::FixedSimulation simulation = test::boxOnGround();
  simulation.bodyList[1].load.force = Vec2(3.0, 0.0);
  simulation.bodyList[1].load.point = Vec2(-0.5, 0.0);
  Manifold& manifold = simulation.manifoldList[0];
  manifold.friction = 0.5;
  for (int i = 0; i < manifold.pointCount; ++i) {
    manifold.points[i].tangentImpulse = -use * manifold.friction * manifold.points[i].normalImpulse;
  }
  return simulation;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("the force scale draws a resting box's contact force a fixed part of the scene",
          "[frame][forces]") {
  RenderSettings settings;
  const test::FixedSimulation simulation = test::boxOnGround();
  const Camera camera = fitCamera(simulation.bodies(), ViewDef{}, settings);
  // 1 kg on two points: m g / 2 = 4.905 N each.
  CHECK(restingForceEstimate(simulation.bodies(), Vec2(0.0, -9.81)) == Approx(4.905));
  const ForceScale forces =
      fitForceScale(simulation.bodies(), Vec2(0.0, -9.81), 0.01, camera, settings);
  CHECK(forces.metresPerNewton * camera.scale * 4.905 ==
        Approx(settings.restingForceLength * camera.height));
  CHECK(roundForce(4.905) == Approx(5.0));
  CHECK(roundForce(1.5) == Approx(2.0));
  CHECK(roundForce(0.03) == Approx(0.02));
}

TEST_CASE("a load arrow ends at its point and is its force times the scale long",
          "[frame][forces][load]") {
  const test::FixedSimulation simulation = pushedBox(0.5);
  FrameRenderer renderer(fitCamera(simulation.bodies(), ViewDef{}, RenderSettings{}), "box");
  DrawingLog log;
  renderer.setLog(&log);
  renderer.draw(simulation);
  const std::vector<DrawnShape> loads = withRole(log, "load");
  REQUIRE(loads.size() == 2);  // the arrow and its value
  const double pixelsPerNewton = renderer.forces().metresPerNewton * renderer.camera().scale;
  CHECK(length(loads[0]) == Approx(3.0 * pixelsPerNewton).epsilon(1e-9));
  const Vec2 point = renderer.camera().toPixels(Vec2(-0.5, 0.5));
  CHECK((loads[0].points[1] - point).norm() < 1e-9);       // its tip at the load's point
  CHECK(loads[0].points[1].x() > loads[0].points[0].x());  // pushing to the right
  CHECK(loads[1].text == "F = 3 N");
}

TEST_CASE("the friction limit is marked at μN times the scale along each friction arrow",
          "[frame][forces][friction]") {
  const test::FixedSimulation simulation = pushedBox(0.5);
  FrameRenderer renderer(fitCamera(simulation.bodies(), ViewDef{}, RenderSettings{}), "box");
  DrawingLog log;
  renderer.setLog(&log);
  renderer.draw(simulation);
  const std::vector<DrawnShape> friction = withRole(log, "static friction");
  const std::vector<DrawnShape> marks = withRole(log, "friction limit");
  REQUIRE(friction.size() == 2);
  REQUIRE(marks.size() == 2);
  const double pixelsPerNewton = renderer.forces().metresPerNewton * renderer.camera().scale;
  const double normalForce = 0.08 / renderer.forces().dt;  // λn / dt of each point
  for (std::size_t i = 0; i < 2; ++i) {
    // Half the limit used: the arrow reaches half way to its mark.
    const Vec2 start = friction[i].points[0];
    const Vec2 middle = 0.5 * (marks[i].points[0] + marks[i].points[1]);
    CHECK((middle - start).norm() == Approx(0.5 * normalForce * pixelsPerNewton));
    CHECK(length(friction[i]) == Approx(0.5 * (middle - start).norm()));
  }
  // The normal arrows stand outside the box's sides, not on them.
  const std::vector<DrawnShape> normals = withRole(log, "normal force");
  REQUIRE(normals.size() == 2);
  const double left = renderer.camera().toPixels(Vec2(-0.5, 0.0)).x();
  const double right = renderer.camera().toPixels(Vec2(0.5, 0.0)).x();
  CHECK(std::min(normals[0].points[0].x(), normals[1].points[0].x()) < left);
  CHECK(std::max(normals[0].points[0].x(), normals[1].points[0].x()) > right);
}

TEST_CASE("the legend names each kind drawn once, and nothing that is not drawn", "[legend]") {
  test::FixedSimulation simulation = pushedBox(0.5);
  FrameRenderer renderer(fitCamera(simulation.bodies(), ViewDef{}, RenderSettings{}), "box");
  DrawingLog log;
  renderer.setLog(&log);
  renderer.draw(simulation);
  std::vector<std::string> words;
  for (const DrawnShape& shape : withRole(log, "legend")) {
    if (shape.kind == DrawnShape::Kind::Text) words.push_back(shape.text);
  }
  for (const char* drawn : {"static", "resting", "applied load F", "normal force λ_n/Δt",
                            "static friction", "limit μN", "5 N (force scale)"}) {
    INFO(drawn);
    CHECK(std::count(words.begin(), words.end(), drawn) == 1);
  }
  for (const char* absent : {"sliding", "flying", "dynamic friction", "velocity", "weight m g"}) {
    INFO(absent);
    CHECK(std::count(words.begin(), words.end(), absent) == 0);
  }
  // Without loads or friction drawn, their entries go.
  simulation.bodyList[1].load = AppliedLoad{};
  RenderSettings plain;
  plain.overlays.frictionImpulses = false;
  const std::vector<std::string> fewer =
      legendWords(DrawnKinds{}, renderer.forces(), renderer.camera(), plain);
  CHECK(fewer.empty());
}

TEST_CASE("the heads-up and legend strips lie outside the scene area; no body is under them",
          "[frame][camera]") {
  RenderSettings settings;
  const test::FixedSimulation simulation = test::boxOnGround();
  for (const auto& [width, height] : {std::pair<int, int>(800, 600), {960, 540}, {320, 240}}) {
    const Camera camera = fitCamera(simulation.bodies(), ViewDef{}, settings, width, height);
    FrameRenderer renderer(camera, "box", settings);
    const Frame frame = renderer.draw(simulation);
    INFO(width << " x " << height);
    CHECK(frame.picture.width() == width);
    CHECK(frame.picture.height() == height);
    CHECK(camera.headsUpHeight + camera.height + camera.legendHeight == height);
    CHECK(camera.textSize >= settings.minimumTextSize);
    // The box, fitted into the scene area, lies inside it.
    for (const Vec2& corner : {Vec2(-0.5, 0.0), Vec2(0.5, 1.0)}) {
      const Vec2 pixel = camera.toPixels(corner);
      CHECK(pixel.y() >= 0.0);
      CHECK(pixel.y() <= camera.height);
    }
  }
}

TEST_CASE("a box set down on the ground is resting at step 0, before any contact is solved",
          "[frame][state]") {
  test::FixedSimulation simulation = test::boxOnGround();
  simulation.manifoldList.clear();
  const std::vector<Manifold> contacts = startingContacts(simulation.bodies(), 1e-3);
  REQUIRE(contacts.size() == 1);
  CHECK(classifyBodies(simulation.bodies(), contacts, RenderSettings{})[1] == BodyState::Resting);
  CHECK(classifyBodies(simulation.bodies(), {}, RenderSettings{})[1] == BodyState::Flying);
}

TEST_CASE("the PDF's text layer holds the lecture's symbols as text", "[frame][pdf]") {
  const fs::path directory = test::scratchDirectory("pdf_text");
  const test::FixedSimulation simulation = pushedBox(0.5);
  FrameRenderer renderer(fitCamera(simulation.bodies(), ViewDef{}, RenderSettings{}), "box");
  writePicture(directory / "frame.pdf", renderer.draw(simulation).picture, ImageFormat::Pdf);
  const std::string text = (directory / "frame.txt").string();
  REQUIRE(std::system(
              ("pdftotext -enc UTF-8 '" + (directory / "frame.pdf").string() + "' '" + text + "'")
                  .c_str()) == 0);
  const std::string words = readText(text);
  for (const char* symbol : {"μ", "λ", "Δt", "|λ"}) {
    INFO(symbol);
    CHECK(words.find(symbol) != std::string::npos);
  }
}

TEST_CASE("the PNG and the SVG of one frame agree", "[frame][svg][png]") {
  const fs::path directory = test::scratchDirectory("png_svg");
  const test::FixedSimulation simulation = pushedBox(0.5);
  RenderSettings settings;
  FrameRenderer renderer(fitCamera(simulation.bodies(), ViewDef{}, settings), "box", settings);
  const Frame frame = renderer.draw(simulation);
  writePicture(directory / "frame.png", frame.picture, ImageFormat::Png);
  writePicture(directory / "frame.svg", frame.picture, ImageFormat::Svg);
  const Image png = readPng(directory / "frame.png");
  const std::string svg = readText(directory / "frame.svg");
  // The same size.
  CHECK(svg.find("width=\"" + std::to_string(png.width()) + "px\"") != std::string::npos);
  CHECK(svg.find("height=\"" + std::to_string(png.height()) + "px\"") != std::string::npos);
  // The box's colour fills a path in the SVG (Cairo writes rgb(r%,g%,b%)) and the pixel at its
  // centre in the PNG.
  const Color resting = settings.colours.restingBody;
  const std::regex fill("fill:rgb\\(([0-9.]+)%,([0-9.]+)%,([0-9.]+)%\\)");
  bool found = false;
  for (auto match = std::sregex_iterator(svg.begin(), svg.end(), fill);
       match != std::sregex_iterator(); ++match) {
    const auto channel = [&](int k) { return std::lround(2.55 * std::stod((*match)[k].str())); };
    found |= channel(1) == resting.r && channel(2) == resting.g && channel(3) == resting.b;
  }
  CHECK(found);
  const Vec2 centre =
      renderer.camera().toPixels(Vec2(0.1, 0.6)) + Vec2(0.0, renderer.camera().headsUpHeight);
  CHECK(png.at(int(centre.x()), int(centre.y())) == resting);
}

TEST_CASE("a ball drawn after the boxes shows its state's colour, as in i2d", "[frame][png]") {
  // The library's example adds its ball after a stack; i2d's scene lists it first. Where a body
  // comes in the list must not change its colour: the ball, resting like the box, is green.
  const fs::path directory = test::scratchDirectory("ball_last");
  test::FixedSimulation simulation = test::boxOnGround();
  simulation.bodyList.push_back(
      makeBody("ball", BodyType::Dynamic, makeCircle(0.5), 1.0, Vec2(-2.0, 0.5), 0.0));
  Manifold manifold = simulation.manifoldList[0];
  manifold.bodyB = 2;
  manifold.pointCount = 1;
  manifold.points[0].point = Vec2(-2.0, 0.0);
  simulation.manifoldList.push_back(manifold);
  RenderSettings settings;
  FrameRenderer renderer(fitCamera(simulation.bodies(), ViewDef{}, settings), "ball", settings);
  writePicture(directory / "frame.png", renderer.draw(simulation).picture, ImageFormat::Png);
  const Image png = readPng(directory / "frame.png");
  const Vec2 insideBall =
      renderer.camera().toPixels(Vec2(-2.0, 0.75)) + Vec2(0.0, renderer.camera().headsUpHeight);
  CHECK(png.at(int(insideBall.x()), int(insideBall.y())) == settings.colours.restingBody);
}

TEST_CASE("a rotation mark stays short on a long plank", "[frame][rotation]") {
  test::FixedSimulation simulation = test::boxOnGround();
  simulation.bodyList[1] =
      makeBody("plank", BodyType::Dynamic, makeBox(5.0, 0.2), 1.0, Vec2(0.0, 0.1), 0.0);
  RenderSettings settings;
  FrameRenderer renderer(fitCamera(simulation.bodies(), ViewDef{}, settings), "plank", settings);
  DrawingLog log;
  renderer.setLog(&log);
  renderer.draw(simulation);
  const std::vector<DrawnShape> marks = withRole(log, "rotation mark");
  REQUIRE(marks.size() == 1);
  // Half the plank would be 2.5 m; the mark stops at 1.5 text sizes.
  CHECK(length(marks[0]) == Approx(settings.rotationMarkLength * renderer.camera().textSize));
  CHECK(2.5 * renderer.camera().scale > 2.0 * length(marks[0]));
}

TEST_CASE("a trace frame draws the event's impulse at the run's force scale", "[trace][forces]") {
  const fs::path root = test::scratchDirectory("trace_scale");
  test::FixedSimulation simulation = test::boxOnGround();
  SolverEvent event;
  event.manifold = 0;
  event.point = 1;
  event.desiredChange = 0.1;
  event.normalImpulse = 0.02;
  simulation.events.push_back(event);
  RenderSettings settings;
  FrameRenderer renderer(fitCamera(simulation.bodies(), ViewDef{}, settings), "box", settings);
  renderer.fitForces(simulation);
  const double pixelsPerNewton = renderer.forces().metresPerNewton * renderer.camera().scale;
  DrawingLog log;
  renderer.setLog(&log);
  const FrameWriter writer = traceStep(simulation, 1, renderer, root);
  REQUIRE(writer.frameCount() == 1);
  std::vector<DrawnShape> impulses;
  for (const DrawnShape& shape : withRole(log, "highlight")) {
    if (shape.kind == DrawnShape::Kind::Arrow) impulses.push_back(shape);
  }
  REQUIRE(impulses.size() == 1);
  CHECK(length(impulses[0]) == Approx(0.02 / renderer.forces().dt * pixelsPerNewton).epsilon(1e-9));
}

TEST_CASE("text that is not UTF-8 is drawn with replacement marks, and drawing goes on after it",
          "[frame][text]") {
  // A scene named after a file in another encoding: Cairo refuses such text, and after a refusal
  // it draws nothing more on the frame.
  Picture picture(200, 40);
  {
    Drawing drawing(picture);
    drawing.text("bad \xff name \xe2\x82", Vec2(2.0, 2.0), 14.0, Color{0, 0, 0, 255});
    drawing.rectangle(Vec2(150.0, 0.0), Vec2(50.0, 40.0), Color{255, 0, 0, 255});
  }
  const Image image = rasterise(picture);
  CHECK(image.at(175, 20) == Color{255, 0, 0, 255});
  int inked = 0;
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 140; ++x) inked += image.at(x, y).a > 0;
  }
  CHECK(inked > 100);
}
