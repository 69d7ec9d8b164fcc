// The figures the docs state about a run are the run's: each figure of docs/demos.md,
// docs/tutorial.md, docs/rendering.md or a demo scene's header comment that says where a body
// gets, how fast, when or with what energy is found on its page (by the phrase that states it, so
// a reworded page fails here instead of going unchecked) and compared with the run, to the
// rounding the page prints it with ("about" widens it, by a stated tolerance). A failure names
// the page, the line and both numbers: when a default changes the run, the page's figure shows up
// here. The trace lines the pages quote must be what a trace draws, and rendering.md's gnuplot
// line must plot friction equal to the push until it gives way.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "doc_blocks.h"
#include "i2d_process.h"
#include "impulse2d/render/frame.h"
#include "impulse2d/render/trace.h"
#include "impulse2d/scene/scene.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/simulation.h"
#include "impulse2d/world.h"

using namespace impulse2d;

namespace {

/// A page's prose as one line, runs of white space made one space (a phrase may break across
/// lines), with the line each character came from. A scene file's page is its header comment.
struct Page {
  std::string path;
  std::string text;
  std::vector<int> lineOf;
};

Page readPage(const std::string& path) {
  std::ifstream in(IMPULSE2D_SOURCE_DIR "/" + path);
  if (!in) throw std::runtime_error("cannot read " + path);
  const bool scene = path.size() > 5 && path.compare(path.size() - 5, 5, ".toml") == 0;
  Page page{path, "", {}};
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (scene) {
      if (line.rfind("#", 0) != 0) break;  // the header ends at the first line not a comment
      line = line.substr(1);
    }
    for (char c : line + " ") {
      const bool space = c == ' ' || c == '\t';
      if (space && (page.text.empty() || page.text.back() == ' ')) continue;
      page.text += space ? ' ' : c;
      page.lineOf.push_back(number);
    }
  }
  return page;
}

/// The figure a phrase states: the number between its braces, "6.5 m by t = {5} s" states 5.
struct Stated {
  std::string phrase;  ///< without the braces, as the page has it
  double value = 0.0;
  double rounding = 0.0;  ///< half a unit of its last printed digit
};

Stated stated(const std::string& marked) {
  const std::size_t open = marked.find('{');
  const std::size_t close = marked.find('}', open);
  if (open == std::string::npos || close == std::string::npos) {
    throw std::runtime_error("no {figure} in the phrase " + marked);
  }
  const std::string number = marked.substr(open + 1, close - open - 1);
  // "7e-6" is printed to its mantissa's digits, at its exponent.
  const std::size_t exponentAt = number.find('e');
  const std::string mantissa = number.substr(0, exponentAt);
  const int exponent =
      exponentAt == std::string::npos ? 0 : std::stoi(number.substr(exponentAt + 1));
  const std::size_t point = mantissa.find('.');
  const int decimals = point == std::string::npos ? 0 : int(mantissa.size() - point - 1);
  std::string phrase = marked;
  phrase.erase(close, 1);
  phrase.erase(open, 1);
  // The pages write minus as U+2212.
  std::string ascii = number;
  if (ascii.rfind("\u2212", 0) == 0) ascii = "-" + ascii.substr(3);
  return {phrase, std::stod(ascii), 0.5 * std::pow(10.0, exponent - decimals)};
}

/// Checks that `page` states `marked` ("... {figure} ...") and that the run's `value` rounds to
/// it; `tolerance` widens the rounding for a figure the page calls "about".
void checkFigure(const Page& page, const std::string& marked, double value,
                 double tolerance = 0.0) {
  const Stated figure = stated(marked);
  const std::size_t at = page.text.find(figure.phrase);
  if (at == std::string::npos) {
    FAIL(page.path << " does not say \"" << figure.phrase << "\" (reworded? update this test)");
  }
  INFO(page.path << ":" << page.lineOf[at] << " states " << figure.value << " (\"" << figure.phrase
                 << "\"); the run gives " << value);
  CHECK(std::abs(value - figure.value) <= std::max(figure.rounding, tolerance) + 1e-12);
}

/// A shipped scene, loaded, with `change` applied before the world is built.
SceneFile demoScene(const std::string& name, const std::function<void(SceneFile&)>& change = {}) {
  SceneFile scene = loadSceneFile(IMPULSE2D_SOURCE_DIR "/demos/scenes/" + name);
  if (change) change(scene);
  return scene;
}

std::unique_ptr<World> runFor(const Scene& scene, long steps) {
  std::unique_ptr<World> world = buildWorld(scene);
  while (world->stepCount() < steps) world->step();
  return world;
}

const Body& bodyNamed(const Simulation& simulation, const std::string& name) {
  for (const Body& body : simulation.bodies()) {
    if (body.name == name) return body;
  }
  throw std::runtime_error("no body " + name);
}

double totalEnergy(const Simulation& simulation) {
  return kineticEnergy(simulation) + potentialEnergy(simulation);
}

}  // namespace

TEST_CASE("pushed box: where the box is and how fast it goes at t = 5 s", "[docs][friction]") {
  // x = (t − ts)³ / 3 after the slip at ts = 2.4525 s: 5.51 m and 6.45 m/s at t = 5 s.
  const SceneFile scene = demoScene("pushed_box.toml");
  const Body start = buildBodies(scene).back();
  const std::unique_ptr<World> world = runFor(scene, 300);
  const Body& box = bodyNamed(*world, "box");
  const double distance = box.position.x() - start.position.x();
  for (const char* path : {"docs/demos.md", "demos/scenes/pushed_box.toml"}) {
    const Page page = readPage(path);
    checkFigure(page, "{5.51} m by t = 5 s", distance);
    checkFigure(page, "{6.45} m/s", box.velocity.x());
  }
}

TEST_CASE("incline: the sliding box's distance in 3 s", "[docs][friction]") {
  const SceneFile scene = demoScene("incline_friction.toml");
  const std::vector<Body> start = buildBodies(scene);
  const std::unique_ptr<World> world = runFor(scene, scene.steps);
  double farthest = 0.0;
  for (std::size_t i = 0; i < start.size(); ++i) {
    farthest = std::max(farthest, (world->bodies()[i].position - start[i].position).norm());
  }
  checkFigure(readPage("docs/demos.md"), "{7.8} m in 3 s", farthest);
  checkFigure(readPage("demos/scenes/incline_friction.toml"), "{7.8} m down the slope in the 3 s",
              farthest);
}

TEST_CASE("incline_slides and rolling_disk: speed and distance after 2 s", "[docs][friction]") {
  const SceneFile slides = demoScene("incline_slides.toml");
  const Body slidesStart = buildBodies(slides).back();
  const std::unique_ptr<World> slid = runFor(slides, slides.steps);
  const Body& box = slid->bodies().back();
  const Page slidesPage = readPage("demos/scenes/incline_slides.toml");
  checkFigure(slidesPage, "{6.41} m/s after the 2 s run", box.velocity.norm());
  checkFigure(slidesPage, "{6.47} m after the run", (box.position - slidesStart.position).norm());
  const SceneFile rolling = demoScene("rolling_disk.toml");
  const std::unique_ptr<World> rolled = runFor(rolling, long(std::lround(2.0 / rolling.world.dt)));
  checkFigure(readPage("demos/scenes/rolling_disk.toml"), "{4.47} m/s after 2 s",
              rolled->bodies().back().velocity.norm(), 0.01);
}

TEST_CASE("spinning disk: it rolls on at ω₀r/3", "[docs][friction]") {
  const SceneFile scene = demoScene("spinning_disk.toml");
  const std::unique_ptr<World> world = runFor(scene, scene.steps);
  const Body& disk = world->bodies().back();
  checkFigure(readPage("docs/demos.md"), "steady {2.5} m/s = ω₀r/3", disk.velocity.x());
  const Page header = readPage("demos/scenes/spinning_disk.toml");
  checkFigure(header, "ends at omega = omega0 / 3 = {-5} rad/s", disk.angularVelocity);
  checkFigure(header, "v = {2.5} m/s", disk.velocity.x());
}

TEST_CASE("bouncing ball: the apexes and the energy at the end", "[docs][restitution]") {
  const SceneFile scene = demoScene("bouncing_ball.toml");
  // Each apex: the highest the ball's bottom gets between leaving the ground and touching it
  // again.
  std::unique_ptr<World> world = buildWorld(scene);
  const double radius = world->bodies().back().shape.radius;
  std::vector<double> apexes;
  bool wasTouching = false;
  bool touched = false;
  while (world->stepCount() < scene.steps && apexes.size() < 4) {
    world->step();
    const bool touching = contactPointCount(*world) > 0;
    touched = touched || touching;
    if (touched && wasTouching && !touching) apexes.push_back(0.0);
    if (!touching && !apexes.empty()) {
      apexes.back() = std::max(apexes.back(), world->bodies().back().position.y() - radius);
    }
    wasTouching = touching;
  }
  REQUIRE(apexes.size() >= 3);
  const Page demos = readPage("docs/demos.md");
  const Page header = readPage("demos/scenes/bouncing_ball.toml");
  checkFigure(demos, "rises to about e²h = {1.28} m", apexes[0], 0.02);
  checkFigure(header, "rises to e^2 h: {1.28} m", apexes[0], 0.02);
  checkFigure(header, "1.28 m here, then {0.82} m", apexes[1], 0.02);
  checkFigure(header, "then 0.82 m, {0.52} m", apexes[2], 0.02);
  checkFigure(demos, "E = {3.91} J at step 330", totalEnergy(*runFor(scene, 330)));
  checkFigure(demos, "(purple, E = {3.87} J)", totalEnergy(*runFor(scene, scene.steps)));
}

TEST_CASE("resting box and spinning disk: the colour a page says a body has at a step",
          "[docs][render]") {
  // The colour is the body's state (render::classifyBodies), drawn from the world at that step.
  const auto stateAt = [](const SceneFile& scene, long step) {
    const std::unique_ptr<World> world = runFor(scene, step);
    return render::classifyBodies(world->bodies(), world->manifolds(), render::RenderSettings{})
        .back();
  };
  const Page page = readPage("docs/demos.md");
  const SceneFile resting = demoScene("resting_box.toml");
  CHECK(page.text.find("restitution 0.5 (purple, step 25), and from about step 50 is green") !=
        std::string::npos);
  CHECK(stateAt(resting, 25) == render::BodyState::Touching);
  for (long step = 55; step <= 300; step += 5) {
    INFO("docs/demos.md: the resting box is green from about step 50; at step " << step);
    CHECK(stateAt(resting, step) == render::BodyState::Resting);
  }
  CHECK(page.text.find("lands and slips (orange at step 30:") != std::string::npos);
  CHECK(stateAt(demoScene("spinning_disk.toml"), 30) == render::BodyState::Sliding);
}

TEST_CASE("resting box and cradle: the energy and speeds at the end", "[docs]") {
  const SceneFile resting = demoScene("resting_box.toml");
  checkFigure(readPage("docs/demos.md"), "E = {4.91} J to step 300",
              totalEnergy(*runFor(resting, 300)));
  const std::unique_ptr<World> one = runFor(demoScene("cradle.toml"), 9);
  const double far = one->bodies().back().velocity.x();
  checkFigure(readPage("demos/scenes/cradle.toml"), "after step 9 the far ball moves at {2} m/s",
              far);
  checkFigure(readPage("docs/demos.md"), "the far ball moves at {2} m/s and every other", far);
  const std::unique_ptr<World> two = runFor(demoScene("cradle_two.toml"), 9);
  const std::vector<Body>& balls = two->bodies();
  for (std::size_t i = balls.size() - 2; i < balls.size(); ++i) {
    checkFigure(readPage("demos/scenes/cradle_two.toml"),
                "after step 9 the two far balls move at {2} m/s", balls[i].velocity.x());
  }
}

namespace {

/// The tutorial's first.toml, as the page writes it.
SceneFile tutorialScene() {
  return parseScene(
      doc_blocks::namedBlock(doc_blocks::readBlocks("docs/tutorial.md"), "first.toml"),
      "first.toml");
}

/// How far down the ramp the tutorial's box has gone after `steps` of `dt`.
double slideDistance(SceneFile scene, double dt, int steps) {
  scene.world.dt = dt;
  const Body start = buildBodies(scene).back();
  const std::unique_ptr<World> world = runFor(scene, steps);
  return (world->bodies().back().position - start.position).norm();
}

}  // namespace

TEST_CASE("tutorial: the slide against a t²/2, at dt and at dt/2", "[docs][tutorial]") {
  const SceneFile scene = tutorialScene();
  const Page page = readPage("docs/tutorial.md");
  const double dt = scene.world.dt;
  const double ran = slideDistance(scene, dt, scene.steps);
  checkFigure(page, "The last point is {6.82} m", ran);
  const double mu = std::sqrt(0.8 * 0.2);
  const double a = 9.81 * (std::sin(kPi / 6) - mu * std::cos(kPi / 6));
  const double formula = a * 9.0 / 2.0;
  checkFigure(page, "against the formula's {6.78} m", formula);
  // Half the step, twice the steps: the same 3 s, and the gap to the formula halves.
  const double halved = slideDistance(scene, dt / 2.0, 2 * scene.steps);
  checkFigure(page, "and the gap halves: {6.80} m", halved);
  CHECK((halved - formula) / (ran - formula) == Approx(0.5).margin(0.01));
}

TEST_CASE("tutorial: the energies of the first scene after 3 s", "[docs][tutorial]") {
  const SceneFile scene = tutorialScene();
  const Page page = readPage("docs/tutorial.md");
  const std::unique_ptr<World> start = buildWorld(scene);
  checkFigure(page, "{25.99} J at the start", totalEnergy(*start));
  const std::unique_ptr<World> world = runFor(scene, scene.steps);
  checkFigure(page, "at the start, {2.77} J", totalEnergy(*world));
  checkFigure(page, "({10.22} J kinetic", kineticEnergy(*world));
  checkFigure(page, "J kinetic, {−7.45} J potential", potentialEnergy(*world));
}

namespace {

/// The heads-up text of every frame of a demo's traced step, one line each, subscripts' '_'
/// dropped as the pages print them.
std::string tracedText(const SceneFile& scene, long step) {
  std::unique_ptr<World> world = buildWorld(scene);
  render::RenderSettings settings;
  render::FrameRenderer renderer(render::fitCamera(world->bodies(), ViewDef{}, settings),
                                 scene.name, settings);
  render::DrawingLog log;
  renderer.setLog(&log);
  const i2d_process::Scratch scratch;
  render::traceStep(*world, step, renderer, scratch.path);
  std::string drawn;
  for (const render::DrawnShape& shape : log) {
    if (shape.kind != render::DrawnShape::Kind::Text || shape.role != "heads-up") continue;
    std::string text = shape.text;
    for (std::size_t at; (at = text.find('_')) != std::string::npos;) text.erase(at, 1);
    drawn += text + "\n";
  }
  return drawn;
}

/// Checks that the page says `phrase` and the trace drew `drawn` (a closing speed line's part).
void checkTraced(const Page& page, const std::string& phrase, const std::string& trace,
                 const std::string& drawn) {
  INFO(page.path << " says \"" << phrase << "\"; the trace draws:\n" << trace);
  CHECK(page.text.find(phrase) != std::string::npos);
  CHECK(trace.find(drawn) != std::string::npos);
}

}  // namespace

TEST_CASE("tutorial: the trace frame's heads-up lines are the trace's", "[docs][tutorial][trace]") {
  // The page quotes the heads-up lines of the resting box's first event in step 13.
  const std::string drawn = tracedText(demoScene("resting_box.toml"), 13);
  std::istringstream quoted(
      doc_blocks::namedBlock(doc_blocks::readBlocks("docs/tutorial.md"), "trace"));
  int lines = 0;
  for (std::string line; std::getline(quoted, line); ++lines) {
    INFO("docs/tutorial.md quotes a trace line the trace does not draw: " << line);
    CHECK(drawn.find(line + "\n") != std::string::npos);
  }
  CHECK(lines == 3);
}

TEST_CASE("rendering.md's gnuplot line plots the push and friction of pushed_box",
          "[docs][friction]") {
  // The page's command, run on the contacts of pushed_box with gnuplot's plot sent to a table:
  // friction (summed over the step's points) equals the push while static friction holds, and
  // stays at μ m g = 4.905 N once the box slides.
  const std::vector<doc_blocks::Block> blocks = doc_blocks::readBlocks("docs/rendering.md");
  std::string command;
  for (const doc_blocks::Block& block : blocks) {
    if (block.language == "sh" && block.text.rfind("gnuplot ", 0) == 0) command = block.text;
  }
  REQUIRE_FALSE(command.empty());
  command.pop_back();  // the newline
  const std::string plot = "; plot ";
  const std::size_t at = command.find(plot);
  REQUIRE(at != std::string::npos);
  command.insert(at + 2, "set table 'table.txt'; ");
  const i2d_process::Scratch scratch;
  REQUIRE(i2d_process::i2d("run " + i2d_process::kScenes +
                               "pushed_box.toml --every 30 --contacts " + (scratch / "c.csv"),
                           scratch)
              .exitCode == 0);
  const std::string run = "cd " + scratch.path.string() + " && " + command + " 2>/dev/null";
  REQUIRE(std::system(run.c_str()) == 0);
  // The table: one block per curve, "t value flag" rows; the push's rows of other points are NaN.
  std::istringstream table(i2d_process::readFile(scratch / "table.txt"));
  std::vector<std::vector<std::pair<double, double>>> curves(1);
  for (std::string line; std::getline(table, line);) {
    if (line.rfind("#", 0) == 0) continue;
    std::istringstream fields(line);
    double t = 0.0;
    std::string value;
    if (!(fields >> t >> value)) {
      if (!curves.back().empty()) curves.emplace_back();
      continue;
    }
    if (value != "NaN") curves.back().push_back({t, std::stod(value)});
  }
  if (curves.back().empty()) curves.pop_back();
  REQUIRE(curves.size() == 2);
  const auto& push = curves[0];
  const auto& friction = curves[1];
  REQUIRE(push.size() == friction.size());
  for (std::size_t i = 0; i < push.size(); ++i) {
    INFO("t = " << push[i].first << ": push " << push[i].second << " N, friction "
                << friction[i].second << " N");
    CHECK(friction[i].first == Approx(push[i].first));
    CHECK(friction[i].second == Approx(std::min(push[i].second, 4.905)).margin(1e-3));
  }
}

TEST_CASE("demos.md's traced steps: the closing speeds each frame shows", "[docs][trace]") {
  const Page page = readPage("docs/demos.md");
  const std::string landing = tracedText(demoScene("resting_box.toml"), 13);
  checkTraced(page, "corner closing speed 2.126 → -0.981 m/s (Δv wanted 3.107 m/s", landing,
              "closing speed 2.126 → -0.981 m/s; Δv wanted 3.107 m/s");
  checkTraced(page, "`contact 0.1, in one impulse with contact 0.0`", landing,
              "velocity 0: contact 0.1, in one impulse with contact 0.0");
  const std::string soft = tracedText(
      demoScene("bouncing_ball.toml", [](SceneFile& scene) { scene.solver = "soft_step"; }), 39);
  for (const char* speeds : {"6.254 → 4.705", "4.705 → 0.000", "0.041 → 0.001", "0.000 → -4.970"}) {
    const std::string pair = speeds;
    std::string printed = pair;  // the page writes the minus sign as U+2212
    if (const std::size_t at = printed.find("-"); at != std::string::npos) {
      printed.replace(at, 1, "\u2212");
    }
    checkTraced(page, printed + " m/s", soft, "closing speed " + pair + " m/s");
  }
}

namespace {

/// A demo scene with `settings` ("solver.KEY=VALUE", as a --panel gives them) applied.
SceneFile withSettings(const std::string& name, const std::vector<std::string>& settings) {
  return demoScene(name, [&](SceneFile& scene) {
    for (const std::string& setting : settings) applySetting(scene, setting);
  });
}

/// The index of the body named `name`.
int indexOf(const Simulation& simulation, const std::string& name) {
  const std::vector<Body>& bodies = simulation.bodies();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].name == name) return int(i);
  }
  throw std::runtime_error("no body " + name);
}

}  // namespace

TEST_CASE("jitter: the energy a resting box gains with the removal off", "[docs][micro]") {
  const Page page = readPage("docs/demos.md");
  const SceneFile off = withSettings(
      "jitter.toml",
      {"solver.remove_acceleration_velocity=false", "solver.lower_restitution_at_low_speed=false"});
  std::unique_ptr<World> world = buildWorld(off);
  double most = 0.0;
  while (world->stepCount() < off.steps) {
    world->step();
    most = std::max(most, totalEnergy(*world));
  }
  checkFigure(page, "rises to about {5.8} J", most);
  const SceneFile on = demoScene("jitter.toml");
  const double kept = totalEnergy(*runFor(on, on.steps));
  checkFigure(page, "\"removal on\": green throughout, E = {4.91} J", kept);
  checkFigure(readPage("demos/scenes/jitter.toml"), "with E = {4.9} J throughout", kept);
}

TEST_CASE("heavy box on light ones: the energy and depth at the end, both ways", "[docs][micro]") {
  const Page page = readPage("docs/demos.md");
  const SceneFile pairs = demoScene("heavy_on_light.toml");
  const std::unique_ptr<World> held = runFor(pairs, pairs.steps);
  checkFigure(page, "(kinetic energy {8e-6} J at the end", kineticEnergy(*held));
  checkFigure(page, "deepest contact {0.2} mm)", 1000.0 * largestPenetration(*held));
  const SceneFile single = withSettings(
      "heavy_on_light.toml", {"solver.impulses=point_totals", "solver.block_moves=false"});
  const std::unique_ptr<World> squeezed = runFor(single, single.steps);
  checkFigure(page, "(kinetic energy {305} J at the end)", kineticEnergy(*squeezed));
}

TEST_CASE("ladder: the wall's push on the standing one, the other flat by 1.5 s",
          "[docs][friction]") {
  const SceneFile scene = demoScene("ladder.toml");
  const std::unique_ptr<World> world = runFor(scene, long(std::lround(1.5 / scene.world.dt)));
  const int wall = indexOf(*world, "wall_holds");
  const int ladder = indexOf(*world, "holds");
  double push = 0.0;
  for (const Manifold& manifold : world->manifolds()) {
    if ((manifold.bodyA == wall && manifold.bodyB == ladder) ||
        (manifold.bodyA == ladder && manifold.bodyB == wall)) {
      for (int i = 0; i < manifold.pointCount; ++i) push += manifold.points[i].normalImpulse;
    }
  }
  const Body& standing = world->bodies()[std::size_t(ladder)];
  const double weight = standing.mass * 9.81;
  const double share = push / scene.world.dt / weight;
  checkFigure(readPage("docs/demos.md"), "the wall pushing {0.264} m g", share, 0.002);
  checkFigure(readPage("demos/scenes/ladder.toml"), "the wall pushing {0.264} m g", share, 0.002);
  // "by t = 1.5 s it lies flat at the foot of its wall": its long side within 3° of the floor.
  const double angle = bodyNamed(*world, "slides").angle;
  INFO("docs/demos.md: the sliding ladder lies flat by t = 1.5 s; its angle is " << angle);
  CHECK(std::abs(std::sin(angle)) < std::sin(3.0 * kPi / 180.0));
}

TEST_CASE("soft step: the stack's settling and, without warm starting, its lean", "[docs][soft]") {
  const Page header = readPage("demos/scenes/soft_step.toml");
  const SceneFile scene = demoScene("soft_step.toml");
  const std::vector<Body> start = buildBodies(scene);
  std::size_t top = 0;  // the stack's top box: the highest of the generated boxes
  for (std::size_t i = 0; i < start.size(); ++i) {
    if (start[i].name.rfind("box", 0) == 0 && start[i].position.y() > start[top].position.y()) {
      top = i;
    }
  }
  const std::unique_ptr<World> settled = runFor(scene, scene.steps);
  const double sink = start[top].position.y() - settled->bodies()[top].position.y();
  checkFigure(header, "(about {3} cm over its 10 contacts", 100.0 * sink, 1.0);
  const SceneFile cold = withSettings("soft_step.toml", {"solver.warm_starting=false"});
  const std::unique_ptr<World> leaning = runFor(cold, cold.steps);
  checkFigure(header, "box {7.6} m off the axis at 5 s",
              std::abs(leaning->bodies()[top].position.x() - start[top].position.x()));
}

TEST_CASE("stack and pyramid: the energies at the end, each method", "[docs][stacking]") {
  const Page page = readPage("docs/demos.md");
  const SceneFile stack = demoScene("stack.toml");
  const std::unique_ptr<World> micro = runFor(stack, stack.steps);
  checkFigure(page, "(490.50 → {490.49} J", totalEnergy(*micro));
  checkFigure(page, "`micro` is the lowest ({490.49} J", totalEnergy(*micro));
  checkFigure(page, "({0.04} mm at the deepest", 1000.0 * largestPenetration(*micro));
  const SceneFile sequential =
      demoScene("stack.toml", [](SceneFile& scene) { scene.solver = "sequential"; });
  const std::unique_ptr<World> swept = runFor(sequential, sequential.steps);
  checkFigure(page, "against sequential's {490.50} J)", totalEnergy(*swept));
  checkFigure(page, "against sequential's {0.002} mm)", 1000.0 * largestPenetration(*swept));
  const SceneFile pyramid = demoScene("pyramid.toml");
  checkFigure(page, "490.49 J, {1888.43} →", totalEnergy(*runFor(pyramid, 0)));
  checkFigure(page, "1888.43 → {1888.40} J", totalEnergy(*runFor(pyramid, 300)));
}

TEST_CASE("incline and seesaw: the accelerations the pages derive, from the runs",
          "[docs][friction]") {
  // The lower box on incline_friction slides from rest: its speed after the 3 s over 3 s.
  const SceneFile incline = demoScene("incline_friction.toml");
  const std::unique_ptr<World> slid = runFor(incline, incline.steps);
  double fastest = 0.0;
  for (const Body& body : slid->bodies()) fastest = std::max(fastest, body.velocity.norm());
  const double slide = fastest / (incline.steps * incline.world.dt);
  checkFigure(readPage("docs/demos.md"), "g(sin θ − μ cos θ) = {1.73} m/s²", slide);
  checkFigure(readPage("demos/scenes/incline_friction.toml"), "* 0.866) = {1.73} m/s^2", slide);
  // The tipping seesaw from rest: its turning rate after a tenth of a second over that time.
  const SceneFile seesaw = demoScene("seesaw.toml");
  const long steps = 6;
  const std::unique_ptr<World> turning = runFor(seesaw, steps);
  const double alpha =
      std::abs(bodyNamed(*turning, "plank_tips").angularVelocity) / (steps * seesaw.world.dt);
  checkFigure(readPage("docs/demos.md"), "Σ m g d / I = {0.56} rad/s²", alpha, 0.01);
  checkFigure(readPage("demos/scenes/seesaw.toml"), "(alpha = {0.56} rad/s^2)", alpha, 0.01);
  // "lands its end on the ground after about 1.4 s": the plank's turn stops then.
  std::unique_ptr<World> world = buildWorld(seesaw);
  double landed = 0.0;
  double fastestTurn = 0.0;
  while (world->stepCount() < seesaw.steps && landed == 0.0) {
    world->step();
    const double turn = std::abs(bodyNamed(*world, "plank_tips").angularVelocity);
    fastestTurn = std::max(fastestTurn, turn);
    if (turn < 0.5 * fastestTurn) landed = world->stepCount() * seesaw.world.dt;
  }
  checkFigure(readPage("docs/demos.md"), "end on the ground after about {1.2} s", landed, 0.1);
}

TEST_CASE("tipping: the tall box on 16° lands on its side", "[docs][friction]") {
  // Landed: the first step its turn, fast while it falls, is stopped by the ramp.
  const SceneFile scene = demoScene("tipping.toml");
  std::unique_ptr<World> world = buildWorld(scene);
  double fastestTurn = 0.0;
  long landed = 0;
  while (world->stepCount() < scene.steps && landed == 0) {
    world->step();
    const double turn = std::abs(bodyNamed(*world, "tips").angularVelocity);
    fastestTurn = std::max(fastestTurn, turn);
    if (turn < 0.25 * fastestTurn) landed = world->stepCount();
  }
  const Page page = readPage("docs/demos.md");
  checkFigure(page, "lands on its side by step {105}", double(landed), 5.0);
  checkFigure(page, "(t = {1.75} s, a short slide", landed * scene.world.dt, 0.05);
}
