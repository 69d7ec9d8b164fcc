// Scene files: every key of the format reaches the Scene, omitted keys take their documented
// defaults, generators expand to boxes, --set overrides, and every kind of bad input is one
// located error message (docs/scene-format.md).
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "impulse2d/scene/scene_file.h"
#include "scene_errors.h"

using namespace impulse2d;

namespace {

/// The example of the issue that introduced scene files, verbatim: this exact shape must load.
const char* const kIssueExample = R"(
[world]
gravity = [0.0, -9.81]      # m/s^2
dt = 0.0166666667           # s
steps = 600
solver = "micro"            # micro | sequential | reference | box2d, as each lands

[solver]                    # optional: any field of the chosen solver's settings, by its name
velocity_iterations_per_contact = 8

[[body]]
name = "ground"             # optional; default "body<index>"
type = "static"             # dynamic (default) | static
shape = "box"               # box | circle | polygon
size = [40.0, 1.0]          # box: full width and height
position = [0.0, -0.5]
angle_deg = 0.0

[[body]]
name = "ball"
shape = "circle"
radius = 0.5
position = [0.0, 4.0]
velocity = [1.0, 0.0]
angular_velocity_deg = 0.0  # degrees per second
density = 1.0               # kg/m^2
friction = 0.5
restitution = 0.5

[[body]]
shape = "polygon"
vertices = [[0.0, 0.0], [1.0, 0.0], [0.5, 1.0]]   # body frame, convex
position = [3.0, 0.5]
)";

const char* const kOneBall = "[[body]]\nshape = \"circle\"\nradius = 0.5\n";

std::string fieldNames(const std::vector<SettingField>& fields) {
  std::string names;
  for (const SettingField& field : fields) names += (names.empty() ? "" : ", ") + field.name;
  return names;
}

double degrees(double d) {
  return d * kPi / 180.0;
}

using scene_errors::errorOf;

/// The what() of the SceneError that applying `assignment` to a one-ball scene throws.
std::string errorOfSetting(const std::string& assignment) {
  return scene_errors::errorOfSetting(parseScene(kOneBall, "ball.toml"), assignment);
}

}  // namespace

TEST_CASE("a scene is named after its file, never '.' or '..', which name directories",
          "[scene-file]") {
  CHECK(parseScene(kOneBall, "demos/ball.toml").name == "ball");
  CHECK(parseScene(kOneBall, "ball").name == "ball");
  CHECK(parseScene(kOneBall, "..toml").name == "scene");
  CHECK(parseScene(kOneBall, "demos/...toml").name == "scene");
  CHECK(parseScene(kOneBall, ".toml").name == ".toml");
}

TEST_CASE("the format's example scene loads with every key", "[scene-file][format]") {
  const SceneFile scene = parseScene(kIssueExample, "scenes/example.toml");
  CHECK(scene.name == "example");
  CHECK(scene.world.gravity == Vec2(0.0, -9.81));
  CHECK(scene.world.dt == 0.0166666667);
  CHECK(scene.steps == 600);
  CHECK(scene.solver == "micro");
  CHECK(scene.solverSettings.micro.velocityIterationsPerContact == 8);
  REQUIRE(scene.bodies.size() == 3);

  const BodyDef& ground = scene.bodies[0];
  CHECK(ground.name == "ground");
  CHECK(ground.type == BodyType::Static);
  CHECK(ground.shape.vertices[2] == Vec2(20.0, 0.5));
  CHECK(ground.position == Vec2(0.0, -0.5));

  const BodyDef& ball = scene.bodies[1];
  CHECK(ball.type == BodyType::Dynamic);
  CHECK(ball.shape.type == ShapeType::Circle);
  CHECK(ball.shape.radius == 0.5);
  CHECK(ball.velocity == Vec2(1.0, 0.0));
  CHECK(ball.restitution == 0.5);

  const BodyDef& triangle = scene.bodies[2];
  CHECK(triangle.name == "body2");
  CHECK(triangle.shape.vertices.size() == 3);
}

TEST_CASE("omitted keys take the documented defaults", "[scene-file][defaults]") {
  const SceneFile scene = parseScene(kOneBall, "ball.toml");
  const SceneFile defaults;
  const WorldSettings world;
  const BodyDef body;
  CHECK(scene.world.gravity == world.gravity);
  CHECK(scene.world.dt == world.dt);
  CHECK(scene.world.contactMargin == world.contactMargin);
  CHECK(scene.steps == defaults.steps);
  CHECK(scene.solver == defaults.solver);
  CHECK(scene.view.width == defaults.view.width);
  CHECK_FALSE(scene.view.scale.has_value());
  REQUIRE(scene.bodies.size() == 1);
  const BodyDef& ball = scene.bodies[0];
  CHECK(ball.name == "body0");
  CHECK(ball.type == BodyType::Dynamic);
  CHECK(ball.position == Vec2::Zero());
  CHECK(ball.angle == 0.0);
  CHECK(ball.velocity == Vec2::Zero());
  CHECK(ball.angularVelocity == 0.0);
  CHECK(ball.density == body.density);
  CHECK(ball.friction == body.friction);
  CHECK(ball.restitution == body.restitution);
}

TEST_CASE("angles in files are degrees, in the Scene radians", "[scene-file][units]") {
  const SceneFile scene = parseScene(
      "[[body]]\nshape = \"box\"\nsize = [2, 1]\nangle_deg = 90\nangular_velocity_deg = -180\n",
      "turned.toml");
  CHECK(scene.bodies[0].angle == Approx(degrees(90.0)));
  CHECK(scene.bodies[0].angularVelocity == Approx(-kPi));
}

TEST_CASE("a polygon's position moves from its origin to its centroid", "[scene-file][polygon]") {
  // The triangle's centroid is (0.5, 1/3) in the file's frame; turned 90°, that arm is (-1/3, 0.5).
  const SceneFile scene = parseScene(
      "[[body]]\nshape = \"polygon\"\nvertices = [[0, 0], [1, 0], [0.5, 1]]\n"
      "position = [3, 0.5]\nangle_deg = 90\n",
      "triangle.toml");
  const BodyDef& triangle = scene.bodies[0];
  CHECK(triangle.position.x() == Approx(3.0 - 1.0 / 3.0));
  CHECK(triangle.position.y() == Approx(1.0));
  Vec2 centroid = Vec2::Zero();
  for (const Vec2& v : triangle.shape.vertices) centroid += v / 3.0;
  CHECK(centroid.norm() == Approx(0.0).margin(1e-12));
}

TEST_CASE("[solver] sets the chosen solver's settings, [render] the view", "[scene-file][solver]") {
  const SceneFile scene = parseScene(
      "[world]\nsolver = \"sequential\"\ncontact_margin = 0.01\n"
      "[solver]\nvelocity_iterations = 20\nimpulses = \"accumulated\"\nbias_factor = 0.1\n"
      "[render]\nwidth = 640\nheight = 480\ncentre = [1, 2]\nscale = 50\n" +
          std::string(kOneBall),
      "s.toml");
  CHECK(scene.world.contactMargin == 0.01);
  CHECK(scene.solverSettings.sequential.velocityIterations == 20);
  CHECK(scene.solverSettings.sequential.impulses == ImpulseAccumulation::Accumulated);
  CHECK(scene.solverSettings.sequential.targets.biasFactor == 0.1);
  CHECK(scene.view.width == 640);
  CHECK(scene.view.height == 480);
  CHECK(scene.view.centre == Vec2(1.0, 2.0));
  CHECK(scene.view.scale == 50.0);
}

TEST_CASE("[solver] preset = \"lecture\" turns off every refinement of the micro resolver",
          "[scene-file][solver][preset]") {
  const SceneFile scene = parseScene(std::string("[world]\nsolver = \"micro\"\n[solver]\n"
                                                 "preset = \"lecture\"\nwarm_starting = true\n") +
                                         kOneBall,
                                     "lecture.toml");
  const MicroCollisionSettings& micro = scene.solverSettings.micro;
  CHECK_FALSE(micro.speculativeGaps);
  CHECK(micro.impulses == MicroCollisionImpulses::Separate);
  CHECK_FALSE(micro.severityCountsPushedPoints);
  CHECK(micro.warmStarting);                // a key after the preset still applies
  CHECK(micro.removeAccelerationVelocity);  // the lecture's own fixes stay on
  CHECK(errorOf("[world]\nsolver = \"micro\"\n[solver]\npreset = \"book\"\n" +
                std::string(kOneBall)) ==
        "bad.toml:4:10: unknown preset 'book' for solver 'micro' (known: 'lecture'; i2d presets "
        "lists all)");
}

TEST_CASE("[solver] preset = \"box2d_2_4\" sets Box2D 2.4.1's contact solver",
          "[scene-file][solver][preset]") {
  const SceneFile scene = parseScene(
      std::string("[solver]\npreset = \"box2d_2_4\"\nvelocity_iterations = 10\n") + kOneBall,
      "box2d.toml");
  const SequentialImpulseSettings& sequential = scene.solverSettings.sequential;
  CHECK(scene.preset == "box2d_2_4");
  CHECK(sequential.velocityIterations == 10);  // a key after the preset still applies
  CHECK(sequential.positionPass.iterations == 3);
  CHECK(sequential.frictionFirst);
  CHECK_FALSE(sequential.targets.penetrationBias);
  CHECK_FALSE(sequential.positionPass.blockSolve);
  CHECK(errorOf("[world]\nsolver = \"reference\"\n[solver]\npreset = \"box2d_2_4\"\n" +
                std::string(kOneBall)) ==
        "bad.toml:4:10: unknown preset 'box2d_2_4' for solver 'reference' (known: none; i2d "
        "presets lists all)");
}

TEST_CASE("a choice takes one of its names; another value is refused, listing the names",
          "[scene-file][solver][choice]") {
  const SceneFile scene = parseScene(
      "[world]\nsolver = \"soft_step\"\nsleep = \"box2d\"\n[solver]\n"
      "relaxation = \"friction_in_both\"\nrecycling = \"box2d_v3\"\n" +
          std::string(kOneBall),
      "s.toml");
  CHECK(scene.world.sleep == Sleep::Box2d);
  CHECK(scene.solverSettings.softStep.relaxation == Relaxation::FrictionInBoth);
  CHECK(scene.solverSettings.softStep.recycling.rule == RecyclingRule::Box2dV3);
  CHECK(errorOf("[world]\nsolver = \"micro\"\n[solver]\nimpulses = \"pairs\"\n" +
                std::string(kOneBall)) ==
        "bad.toml:4:12: unknown value 'pairs' for 'impulses' (known: separate, point_totals, "
        "block, block_with_bounces)");
  CHECK(errorOf("[world]\nsleep = true\n" + std::string(kOneBall)) ==
        "bad.toml:2:9: 'sleep' must be a string (one of: off, box2d, keep_speeding_up_awake), "
        "not a boolean");
  CHECK(errorOf("[world]\nsleeping = true\n" + std::string(kOneBall)) ==
        "bad.toml:2:12: 'sleeping' is now 'sleep': sleeping = false is sleep = \"off\", true is "
        "\"keep_speeding_up_awake\" (or \"box2d\", Box2D's rule alone)");
  CHECK(errorOf("[world]\nsolver = \"sequential\"\n[solver]\nwarm_starting = false\n" +
                std::string(kOneBall)) ==
        "bad.toml:4:17: 'warm_starting' is now a value of 'impulses': warm_starting = true is "
        "impulses = \"warm_started\", false is \"accumulated\"");
  CHECK(errorOf("[world]\nsolver = \"reference\"\n[solver]\nbacktrack = false\n" +
                std::string(kOneBall)) ==
        "bad.toml:4:13: 'backtrack' is now a value of 'cycling_safeguard': backtrack = true is "
        "cycling_safeguard = \"backtrack\", false is \"judice_pires\"");
}

TEST_CASE("a renamed or removed solver key is refused with a hint naming what to write",
          "[scene-file][solver][errors]") {
  CHECK(errorOf("[world]\nsolver = \"micro\"\n[solver]\nwarm_start = false\n" +
                std::string(kOneBall)) ==
        "bad.toml:4:14: 'warm_start' is now 'warm_starting', as in soft step");
  CHECK(errorOf("[world]\nsolver = \"soft_step\"\n[solver]\nrecycle_round_normals = true\n" +
                std::string(kOneBall)) ==
        "bad.toml:4:25: 'recycle_round_normals' is now a value of 'recycling': "
        "recycle_round_normals = false is recycling = \"refined\", true is \"box2d_v3\"");
  CHECK(errorOf("[world]\nsolver = \"soft_step\"\n[solver]\nblock_normals = true\n" +
                std::string(kOneBall)) ==
        "bad.toml:4:17: 'block_normals' was removed: it made results worse (docs/soft-step.md, "
        "\"Removed switches\")");
  CHECK(errorOf("[world]\nsolver = \"micro\"\n[solver]\nrestitution_velocity_limit = 0.5\n" +
                std::string(kOneBall)) ==
        "bad.toml:4:30: 'restitution_velocity_limit' is now 'restitution_threshold', Box2D's word");
  CHECK(errorOf("[solver]\nmax_bias_velocity = 2\n" + std::string(kOneBall)) ==
        "bad.toml:2:21: 'max_bias_velocity' is now 'max_push_velocity', Box2D's word");
  CHECK(errorOf("[world]\nsolver = \"reference\"\n[solver]\npivot_tolerance = 1e-9\n" +
                std::string(kOneBall)) ==
        "bad.toml:4:19: 'pivot_tolerance' is now the constant kPivotTolerance in lcp.cpp: it tells "
        "round-off from a pivot");
  // The same key of another method is that method's business: sequential never had warm_start.
  CHECK(errorOf("[solver]\nwarm_start = false\n" + std::string(kOneBall))
            .find("unknown key 'warm_start' in [solver] for solver 'sequential'") !=
        std::string::npos);
}

TEST_CASE("[[stack]] and [[pyramid]] expand to touching boxes", "[scene-file][generators]") {
  const SceneFile scene = parseScene(
      "[[stack]]\ncount = 3\nsize = [1, 0.5]\nbase = [10, 0]\nlevel_offset = 0.1\n"
      "friction = 0.9\n"
      "[[pyramid]]\nrows = 10\nsize = [1, 1]\nbase = [0, 0]\ndensity = 2\n",
      "generated.toml");
  REQUIRE(scene.bodies.size() == 3 + 55);
  CHECK(scene.bodies[0].position == Vec2(10.0, 0.25));
  CHECK(scene.bodies[2].position.x() == Approx(10.2));
  CHECK(scene.bodies[2].position.y() == Approx(1.25));
  CHECK(scene.bodies[2].friction == 0.9);
  CHECK(scene.bodies[3].density == 2.0);
  CHECK(scene.bodies.back().position.y() == Approx(9.5));
}

TEST_CASE("a --set assignment changes one world or solver setting, written as in a file",
          "[scene-file][set]") {
  SceneFile scene = parseScene(kOneBall, "ball.toml");
  applySetting(scene, "world.dt=0.001");
  applySetting(scene, "world.gravity=[0, -1.62]");
  applySetting(scene, "world.steps=42");
  applySetting(scene, "world.solver=micro");
  applySetting(scene, "solver.friction=false");
  applySetting(scene, "solver.velocity_iterations_per_contact = 3");
  CHECK(scene.world.dt == 0.001);
  CHECK(scene.world.gravity == Vec2(0.0, -1.62));
  CHECK(scene.steps == 42);
  CHECK(scene.solver == "micro");
  CHECK_FALSE(scene.solverSettings.micro.friction);
  CHECK(scene.solverSettings.micro.velocityIterationsPerContact == 3);
}

TEST_CASE("a --set render.KEY changes the view as the [render] table would", "[scene-file][set]") {
  SceneFile scene = parseScene(kOneBall, "ball.toml");
  CHECK_FALSE(scene.view.fixed());
  applySetting(scene, "render.scale=300");
  applySetting(scene, "render.zoom=2");
  applySetting(scene, "render.follow=" + scene.bodies.back().name);
  CHECK(scene.view.scale == 300.0);
  CHECK(scene.view.zoom == 2.0);
  CHECK(scene.view.follow == scene.bodies.back().name);
  CHECK_FALSE(scene.view.fixed());  // a scale alone still fits the centre
  applySetting(scene, "render.view=[[-1, 0], [3, 2]]");
  REQUIRE(scene.view.window);
  CHECK(scene.view.window->lower == Vec2(-1.0, 0.0));
  CHECK(scene.view.window->upper == Vec2(3.0, 2.0));
  CHECK(scene.view.fixed());
}

TEST_CASE("a bad --set is one located error", "[scene-file][set][errors]") {
  CHECK(errorOfSetting("dt=1") ==
        "--set:1:1: expected section.key=value, such as solver.velocity_iterations=12, not 'dt=1'");
  CHECK(errorOfSetting("foo.bar=1") ==
        "--set:1:1: unknown key 'foo' in --set (known: world, solver, render)");
  CHECK(errorOfSetting("render.follow=nobody") ==
        "--set:1:15: the view follows body 'nobody', which the scene does not have");
  CHECK(errorOfSetting("render.view=[[1, 0], [0, 1]]") ==
        "--set:1:13: 'view' must go from its lower left corner [x0, y0] to its upper right "
        "[x1, y1], with x0 < x1 and y0 < y1");
  CHECK(errorOfSetting("world.dt=-1") == "--set:1:10: dt = -1: must be in [1e-06, 1]");
  CHECK(errorOfSetting("world.steps=many") ==
        "--set:1:13: 'steps' must be an integer, not a string");
  CHECK(
      errorOfSetting("world.solver=nope") ==
      "--set:1:14: unknown solver 'nope' (known: micro, sequential, reference, soft_step, box2d)");
}

TEST_CASE("each kind of bad input is one error at its place", "[scene-file][errors]") {
  const std::string ball = kOneBall;
  SECTION("TOML syntax error") {
    CHECK(errorOf("[world\ndt = 1\n") ==
          "bad.toml:1:7: Error while parsing table header: expected ']', saw '\\n'");
  }
  SECTION("unknown key, naming it and the known keys") {
    CHECK(errorOf(ball + "fricton = 0.5\n") ==
          "bad.toml:4:1: unknown key 'fricton' in [[body]] (known: name, type, shape, size, "
          "radius, vertices, position, on, offset, angle_deg, velocity, angular_velocity_deg, "
          "density, friction, restitution, force, force_rate, force_point, torque)");
    MicroCollisionSettings micro;
    CHECK(errorOf("[world]\nsolver = \"micro\"\n[solver]\naccumulate_impulses = true\n" + ball) ==
          "bad.toml:4:1: unknown key 'accumulate_impulses' in [solver] for solver 'micro' "
          "(known: " +
              fieldNames(describe(micro)) + ", preset)");
    CHECK(errorOf("[bodies]\nx = 1\n") ==
          "bad.toml:1:2: unknown key 'bodies' in the scene file (known: world, solver, render, "
          "body, stack, pyramid)");
    CHECK(errorOf(ball + "size = [1, 1]\n") ==
          "bad.toml:4:1: key 'size' does not apply to a circle (a circle takes 'radius')");
  }
  SECTION("wrong type") {
    CHECK(errorOf(ball + "friction = \"high\"\n") ==
          "bad.toml:4:12: 'friction' must be a number, not a string");
    CHECK(errorOf("[world]\nsteps = 1.5\n" + ball) ==
          "bad.toml:2:9: 'steps' must be an integer, not a floating-point number");
    CHECK(errorOf("[world]\ngravity = [0]\n" + ball) ==
          "bad.toml:2:11: 'gravity' must have 2 numbers [x, y], not 1");
    CHECK(errorOf("world = 3\n" + ball) ==
          "bad.toml:1:9: 'world' must be a table [world], not an integer");
  }
  SECTION("missing required key") {
    CHECK(errorOf("[[body]]\nshape = \"box\"\n") ==
          "bad.toml:1:1: missing required key 'size' (a box needs size = [width, height])");
    CHECK(errorOf("[[body]]\nradius = 1\n") ==
          "bad.toml:1:1: missing required key 'shape' (shape = box, circle or polygon)");
    CHECK(errorOf("[[stack]]\nsize = [1, 1]\nbase = [0, 0]\n") ==
          "bad.toml:1:1: missing required key 'count' (count = number of boxes)");
  }
  SECTION("non-finite or out-of-range number") {
    CHECK(errorOf("[world]\ndt = nan\n" + ball) == "bad.toml:2:6: 'dt' must be finite, not nan");
    CHECK(errorOf(ball + "position = [0, inf]\n") ==
          "bad.toml:4:16: 'position' must be finite, not inf");
    CHECK(errorOf(ball + "density = 0\n") == "bad.toml:4:11: 'density' must be > 0, not 0");
    CHECK(errorOf("[[body]]\nshape = \"box\"\nsize = [1, -1]\n") ==
          "bad.toml:3:12: 'size' must be > 0, not -1");
    CHECK(errorOf("[[body]]\nshape = \"circle\"\nradius = 0\n") ==
          "bad.toml:3:10: 'radius' must be > 0, not 0");
    CHECK(errorOf(ball + "friction = -0.1\n") ==
          "bad.toml:4:12: 'friction' must be >= 0, not -0.1");
    CHECK(errorOf(ball + "restitution = 1.5\n") ==
          "bad.toml:4:15: 'restitution' must be in [0, 1], not 1.5");
    CHECK(errorOf("[world]\ndt = 0\n" + ball) == "bad.toml:2:6: dt = 0: must be in [1e-06, 1]");
    CHECK(errorOf("[world]\nsteps = -1\n" + ball) ==
          "bad.toml:2:9: steps = -1: must be an integer in [0, 10000000]");
  }
  SECTION("degenerate or non-convex polygon") {
    CHECK(errorOf("[[body]]\nshape = \"polygon\"\nvertices = [[0, 0], [1, 0], [2, 0]]\n") ==
          "bad.toml:3:12: 'vertices': polygon has zero area");
    CHECK(errorOf("[[body]]\nshape = \"polygon\"\n"
                  "vertices = [[0, 0], [2, 0], [1, 0.5], [2, 2], [0, 2]]\n") ==
          "bad.toml:3:12: 'vertices': polygon is not convex at vertex 2 (1, 0.5)");
    CHECK(errorOf("[[body]]\nshape = \"polygon\"\nvertices = [[0, 0], [1, 0]]\n") ==
          "bad.toml:3:12: 'vertices': polygon has 2 vertices; it needs at least 3");
  }
  SECTION("unknown solver or shape name") {
    CHECK(errorOf("[world]\nsolver = \"fast\"\n" + ball) ==
          "bad.toml:2:10: unknown solver 'fast' (known: micro, sequential, reference, soft_step, "
          "box2d)");
    CHECK(errorOf("[[body]]\nshape = \"triangle\"\n") ==
          "bad.toml:2:9: unknown shape 'triangle' (known: box, circle, polygon)");
  }
  SECTION("empty file, or a scene without bodies") {
    CHECK(errorOf("") == "bad.toml:1:1: scene file is empty");
    CHECK(errorOf("# nothing but a comment\n") == "bad.toml:1:1: scene file is empty");
    CHECK(errorOf("[world]\ndt = 0.01\n") ==
          "bad.toml:1:1: scene has no bodies (add [[body]], [[stack]] or [[pyramid]])");
  }
  SECTION("a body name used twice") {
    CHECK(errorOf("[[body]]\nname = \"a\"\n" + ball.substr(9) + "[[body]]\nname = \"a\"\n" +
                  ball.substr(9)) ==
          "bad.toml:6:8: body name 'a' is already used by body 0; names must be unique");
  }
}

TEST_CASE("a file that cannot be read is a SceneError naming it", "[scene-file][errors]") {
  CHECK_THROWS_WITH(loadSceneFile("/nonexistent/scene.toml"),
                    "/nonexistent/scene.toml: cannot read the file: No such file or directory");
}

TEST_CASE("a scene file beyond 16 MiB is refused, even one that never ends",
          "[scene-file][errors]") {
  // /dev/zero was read until memory ran out (std::bad_alloc after gigabytes).
  CHECK_THROWS_WITH(loadSceneFile("/dev/zero"),
                    "/dev/zero: is larger than 16 MiB, the most a scene file may hold");
  const std::filesystem::path padded =
      std::filesystem::temp_directory_path() /
      ("scene_file_test_padded_" + std::to_string(getpid()) + ".toml");  // one per process
  {
    std::ofstream out(padded);
    out << kOneBall << std::string(kLargestSceneFileBytes - std::string(kOneBall).size(), '\n');
  }
  CHECK(loadSceneFile(padded.string()).bodies.size() == 1);  // at the limit: read whole
  std::ofstream(padded, std::ios::app) << '\n';
  CHECK_THROWS_WITH(loadSceneFile(padded.string()), Catch::Contains("is larger than 16 MiB"));
  std::filesystem::remove(padded);
}
