// Placing a body at rest on a named surface ([[body]] on = "ramp", docs/scene-format.md): the
// placed body is turned to the slope of the surface's top face and its lowest point touches
// that face; a chain of placements is placed bottom up; every misuse is one located error.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "i2d_process.h"
#include "impulse2d/scene/scene_file.h"
#include "scene_errors.h"

using namespace impulse2d;

namespace {

const std::string kRamp = R"([[body]]
name = "ramp"
type = "static"
shape = "box"
size = [20.0, 1.0]
position = [1.0, -2.0]
angle_deg = 20.0
)";

const std::string kBoxOnRamp = kRamp + R"([[body]]
name = "box"
shape = "box"
size = [1.0, 0.5]
on = "ramp"
offset = 3.0
)";

const BodyDef& bodyNamed(const Scene& scene, const std::string& name) {
  return *std::find_if(scene.bodies.begin(), scene.bodies.end(),
                       [&](const BodyDef& body) { return body.name == name; });
}

/// The world-frame vertices of a box or polygon.
std::vector<Vec2> worldVertices(const BodyDef& body) {
  std::vector<Vec2> points;
  for (const Vec2& vertex : body.shape.vertices) {
    points.push_back(body.position + rotation(body.angle) * vertex);
  }
  return points;
}

/// The ramp's top face as a point on it and its upward unit normal, from the ramp's own numbers.
struct Line {
  Vec2 point;
  Vec2 normal;
};

Line rampTop(double angleDegrees, const Vec2& centre, double height) {
  const double a = angleDegrees * kPi / 180.0;
  const Vec2 normal(-std::sin(a), std::cos(a));
  return {centre + height / 2.0 * normal, normal};
}

/// The least height of the body's points above the line: 0 when its lowest point touches it.
double lowestAbove(const std::vector<Vec2>& points, const Line& line) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec2& point : points) lowest = std::min(lowest, line.normal.dot(point - line.point));
  return lowest;
}

using scene_errors::errorOf;

}  // namespace

TEST_CASE("a box placed on a ramp touches its top face, turned to its slope", "[scene-file][on]") {
  const SceneFile scene = parseScene(kBoxOnRamp, "on.toml");
  const BodyDef& box = bodyNamed(scene, "box");
  const Line top = rampTop(20.0, Vec2(1.0, -2.0), 1.0);
  CHECK(box.angle == Approx(20.0 * kPi / 180.0).margin(1e-12));
  CHECK(std::abs(lowestAbove(worldVertices(box), top)) < 1e-9);
  // The centre sits 3 m up the face from its middle, half the box's height above it.
  const Vec2 along(std::cos(box.angle), std::sin(box.angle));
  CHECK((box.position - top.point).dot(along) == Approx(3.0).margin(1e-9));
  CHECK(top.normal.dot(box.position - top.point) == Approx(0.25).margin(1e-9));
}

TEST_CASE("angle_deg turns a placed body from the face's slope, and its corner then touches",
          "[scene-file][on]") {
  const SceneFile scene = parseScene(kBoxOnRamp + "angle_deg = 30.0\n", "on.toml");
  const BodyDef& box = bodyNamed(scene, "box");
  CHECK(box.angle == Approx(50.0 * kPi / 180.0).margin(1e-12));
  CHECK(std::abs(lowestAbove(worldVertices(box), rampTop(20.0, Vec2(1.0, -2.0), 1.0))) < 1e-9);
}

TEST_CASE("a circle rests on a face at its radius, and a box on a placed box on the ramp",
          "[scene-file][on]") {
  // The upper box names the lower one before the lower one is placed: placement is bottom up.
  const std::string text = kRamp + R"([[body]]
name = "upper"
shape = "box"
size = [0.5, 0.5]
on = "lower"
[[body]]
name = "lower"
shape = "box"
size = [1.0, 1.0]
on = "ramp"
[[body]]
name = "ball"
shape = "circle"
radius = 0.3
on = "ramp"
offset = -4.0
)";
  const SceneFile scene = parseScene(text, "on.toml");
  const Line top = rampTop(20.0, Vec2(1.0, -2.0), 1.0);
  const BodyDef& lower = bodyNamed(scene, "lower");
  const BodyDef& upper = bodyNamed(scene, "upper");
  const BodyDef& ball = bodyNamed(scene, "ball");
  CHECK(std::abs(lowestAbove(worldVertices(lower), top)) < 1e-9);
  const Line lowerTop{lower.position + 0.5 * top.normal, top.normal};
  CHECK(std::abs(lowestAbove(worldVertices(upper), lowerTop)) < 1e-9);
  CHECK(upper.angle == Approx(lower.angle).margin(1e-12));
  CHECK(top.normal.dot(ball.position - top.point) == Approx(0.3).margin(1e-9));
}

TEST_CASE("a box placed on a 20 degree ramp with mu 0.6 stays at rest", "[scene-file][on]") {
  // tan 20° = 0.36 < 0.6: static friction holds it, so touching (not sunk, not dropped) it
  // moves less than a millimetre in two seconds.
  SceneFile scene = parseScene("[world]\nsolver = \"micro\"\n" + kBoxOnRamp, "on.toml");
  const Vec2 start = bodyNamed(scene, "box").position;
  const auto world = buildWorld(scene);
  for (int step = 0; step < 120; ++step) world->step();
  CHECK((world->bodies()[1].position - start).norm() < 1e-3);
}

TEST_CASE("each misuse of 'on' is one located error", "[scene-file][on][errors]") {
  CHECK(errorOf(kRamp + "[[body]]\nshape = \"box\"\nsize = [1, 1]\non = \"rampp\"\n") ==
        "bad.toml:11:6: 'on' names 'rampp', and no body has that name (known: ramp, body1)");
  CHECK(errorOf("[[body]]\nname = \"a\"\nshape = \"box\"\nsize = [1, 1]\non = \"b\"\n"
                "[[body]]\nname = \"b\"\nshape = \"box\"\nsize = [1, 1]\non = \"a\"\n") ==
        "bad.toml:5:6: 'on' makes a cycle: a on b on a; a body can rest only on one placed "
        "without it");
  CHECK(errorOf("[[body]]\nname = \"a\"\nshape = \"box\"\nsize = [1, 1]\non = \"a\"\n") ==
        "bad.toml:5:6: 'on' makes a cycle: a on a; a body can rest only on one placed without it");
  CHECK(errorOf("[[body]]\nname = \"ball\"\nshape = \"circle\"\nradius = 1\n"
                "[[body]]\nshape = \"box\"\nsize = [1, 1]\non = \"ball\"\n") ==
        "bad.toml:8:6: body 'body1' cannot rest on 'ball', a circle: 'on' needs a body with "
        "flat faces (a box or polygon)");
  CHECK(
      errorOf(kRamp + "[[body]]\nshape = \"box\"\nsize = [1, 1]\non = \"ramp\"\noffset = 10.5\n") ==
      "bad.toml:12:10: 'offset' = 10.5: must be in [-10, 10], half the length of the top face "
      "of 'ramp' either side of its middle");
  CHECK(errorOf(kRamp + "[[body]]\nshape = \"box\"\nsize = [1, 1]\non = \"ramp\"\n"
                        "position = [0, 1]\n") ==
        "bad.toml:12:1: 'position' and 'on' both place the body; give one of them");
  CHECK(errorOf(kRamp + "[[body]]\nshape = \"box\"\nsize = [1, 1]\noffset = 1\n") ==
        "bad.toml:11:1: 'offset' places a body along the face it rests on; it needs on = \"name\"");
  CHECK(errorOf(kRamp + "[[body]]\nshape = \"box\"\nsize = [1, 1]\non = 3\n") ==
        "bad.toml:11:6: 'on' must be a string, not an integer");
}

TEST_CASE("i2d refuses a misplaced body with one located line and exit code 3",
          "[scene-file][on][errors]") {
  const i2d_process::Scratch scratch;
  i2d_process::writeFile(scratch / "on.toml", kRamp +
                                                  "[[body]]\nname = \"box\"\nshape = \"box\"\n"
                                                  "size = [1, 1]\non = \"ramp \"\n");
  const i2d_process::Outcome outcome = i2d_process::i2d("check " + (scratch / "on.toml"), scratch);
  CHECK(outcome.exitCode == 3);
  CHECK(outcome.out.empty());
  CHECK(outcome.err == "error: " + (scratch / "on.toml") +
                           ":12:6: 'on' names 'ramp ', and no body has that name (known: ramp, "
                           "box)\n");
}
