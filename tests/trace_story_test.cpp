// A traced step tells each event in the lecture's words (render/trace.h): the closing speed it
// states before an impulse is the one the contact closes with, this step's gravity included (for
// soft step, the first substep's, as its substeps move the bodies).
#include <catch2/catch.hpp>

#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "impulse2d/render/frame.h"
#include "impulse2d/render/trace.h"
#include "impulse2d/scene/scene.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/world.h"
#include "render_fixtures.h"

using namespace impulse2d;
using namespace impulse2d::render;

namespace {

/// A ball of restitution 0.5 dropped 0.2 m onto static ground, at 60 Hz.
const std::string kDrop = R"([world]
gravity = [0.0, -9.81]
dt = 0.0166666667
solver = "micro"

[[body]]
name = "ground"
type = "static"
shape = "box"
size = [4.0, 1.0]
position = [0.0, -0.5]

[[body]]
name = "ball"
shape = "circle"
radius = 0.5
position = [0.0, 0.7]
restitution = 0.5
)";

/// Counts the solver's events of one phase.
struct EventCounter : SolverObserver {
  explicit EventCounter(SolverEvent::Phase counted) : phase(counted) {}
  void onSolverEvent(const SolverEvent& event, const std::vector<Body>&,
                     const std::vector<Manifold>&) override {
    events += event.phase == phase;
  }
  SolverEvent::Phase phase;
  int events = 0;
};

/// The first step whose solve has an event of `phase`, and the ball's speed at the end of the step
/// before.
long firstStepWithEvent(const Scene& scene, double& speedBefore,
                        SolverEvent::Phase phase = SolverEvent::Phase::Velocity) {
  std::unique_ptr<World> world = buildWorld(scene);
  EventCounter counter(phase);
  world->setObserver(&counter);
  while (counter.events == 0 && world->stepCount() < 60) {
    speedBefore = -world->bodies().back().velocity.y();
    world->step();
  }
  return world->stepCount();
}

/// The closing speed and the speed after that `step`'s first event whose label begins with
/// `label` states, tracing `world` through that step into a scratch directory of its own (ctest
/// runs the test cases side by side).
std::pair<double, double> firstClosingSpeeds(World& world, long step, const std::string& scratch,
                                             const std::string& label = "") {
  RenderSettings settings;
  FrameRenderer renderer(fitCamera(world.bodies(), ViewDef{}, settings), "drop", settings);
  DrawingLog log;
  renderer.setLog(&log);
  traceStep(world, step, renderer, test::scratchDirectory(scratch));
  bool labelSeen = label.empty();
  for (const DrawnShape& shape : log) {
    if (shape.kind != DrawnShape::Kind::Text) continue;
    labelSeen = labelSeen || shape.text.rfind(label, 0) == 0;
    double before = 0.0;
    double after = 0.0;
    if (labelSeen &&
        std::sscanf(shape.text.c_str(), "closing speed %lf → %lf m/s", &before, &after) == 2) {
      return {before, after};
    }
  }
  return {-1.0, -1.0};
}

}  // namespace

TEST_CASE("a traced bounce states the closing speed the contact closes with", "[trace]") {
  SceneFile scene = parseScene(kDrop, "drop.toml");
  const double g = 9.81;
  for (const std::string solver : {"micro", "sequential", "reference", "soft_step"}) {
    INFO(solver);
    scene.solver = solver;
    double speedBefore = 0.0;
    const long step = firstStepWithEvent(scene, speedBefore);
    REQUIRE(step < 60);
    std::unique_ptr<World> world = buildWorld(scene);
    const auto [closing, after] = firstClosingSpeeds(*world, step, "trace_story_" + solver);
    // The speed at the end of the last step plus the gravity of this step, g·dt (0.164 m/s), or
    // of soft step's first substep, g·dt/4; to the last digit the line prints (mm/s).
    const double h = solver == "soft_step" ? scene.world.dt / scene.solverSettings.softStep.substeps
                                           : scene.world.dt;
    CHECK(closing == Approx(speedBefore + g * h).margin(1e-3));
    // The step's first impulse at a point only pushes apart: the contact closes no faster after
    // it (soft step's speculative contact may not need one yet: its ball is still above ground).
    CHECK(after <= closing + 1e-3);
  }
}

TEST_CASE("a traced soft step shows its bounce leaving at -e times the closing speed", "[trace]") {
  // Soft step bounces in a pass after its substeps, at −e times the closing speed the contact had
  // before the step (Box2D v3's relax-then-restitution); the trace shows that pass as its own
  // event, the substeps having stopped the ball.
  SceneFile scene = parseScene(kDrop, "drop.toml");
  scene.solver = "soft_step";
  double speedBefore = 0.0;
  const long step = firstStepWithEvent(scene, speedBefore, SolverEvent::Phase::Restitution);
  REQUIRE(step < 60);
  std::unique_ptr<World> traced = buildWorld(scene);
  const auto [closing, after] =
      firstClosingSpeeds(*traced, step, "trace_story_bounce", "restitution: contact");
  const double e = 0.5;
  CHECK(closing == Approx(0.0).margin(1e-3));
  CHECK(after == Approx(-e * speedBefore).margin(1e-3));
  // The substeps' relax sweeps are traced too: the last leaves the ball at rest on the ground.
  std::unique_ptr<World> relaxed = buildWorld(scene);
  const auto [relaxClosing, relaxAfter] =
      firstClosingSpeeds(*relaxed, step, "trace_story_relax", "relax 3: contact");
  CHECK(relaxAfter == Approx(0.0).margin(1e-3));
  // Watching changes nothing: the traced step ends where an untraced one does, to the bit.
  std::unique_ptr<World> untraced = buildWorld(scene);
  while (untraced->stepCount() < traced->stepCount()) untraced->step();
  CHECK(traced->bodies().back().velocity == untraced->bodies().back().velocity);
  CHECK(traced->bodies().back().position == untraced->bodies().back().position);
}

TEST_CASE("a trace names soft step's substeps, and prints round-off below its digits as 0",
          "[trace]") {
  const std::vector<Body> none;
  const std::vector<Manifold> noManifolds;
  SolverEvent event{SolverEvent::Phase::Velocity, 2, 0, 1, 0.0, 0.0, 0.0};
  CHECK(tellEvent(event, none, none, noManifolds, "soft_step", 0.01).label ==
        "substep 2: contact 0.1");
  CHECK(tellEvent(event, none, none, noManifolds, "sequential", 0.01).label ==
        "velocity 2: contact 0.1");
  event.phase = SolverEvent::Phase::Relax;
  CHECK(tellEvent(event, none, none, noManifolds, "soft_step", 0.01).label ==
        "relax 2: contact 0.1");
  event.phase = SolverEvent::Phase::Restitution;
  CHECK(tellEvent(event, none, none, noManifolds, "soft_step", 0.01).label ==
        "restitution: contact 0.1");
  // A position event that removed -1e-9 m prints no "-0.000 mm"; -2 mm keeps its sign.
  event.phase = SolverEvent::Phase::Position;
  event.desiredChange = -1e-9;
  CHECK(tellEvent(event, none, none, noManifolds, "micro", 0.01).lines.back() ==
        "moved the bodies apart: 0.000 mm of penetration removed");
  event.desiredChange = -0.002;
  CHECK(tellEvent(event, none, none, noManifolds, "micro", 0.01).lines.back() ==
        "moved the bodies apart: -2.000 mm of penetration removed");
}

namespace {

/// The lines each frame of a shipped scene's traced step adds under its heads-up, one vector per
/// event, from the drawing log: the lines from the event's label (its "contact" line) on.
std::vector<std::vector<std::string>> tracedStories(const std::string& scene, long step,
                                                    const std::string& scratch) {
  const SceneFile file = loadSceneFile(IMPULSE2D_SOURCE_DIR "/demos/scenes/" + scene);
  std::unique_ptr<World> world = buildWorld(file);
  RenderSettings settings;
  FrameRenderer renderer(fitCamera(world->bodies(), ViewDef{}, settings), scene, settings);
  DrawingLog log;
  renderer.setLog(&log);
  traceStep(*world, step, renderer, test::scratchDirectory(scratch));
  std::vector<std::vector<std::string>> stories;
  for (const DrawnShape& shape : log) {
    if (shape.kind != DrawnShape::Kind::Text || shape.role != "heads-up") continue;
    if (shape.text.find(": contact ") != std::string::npos) stories.emplace_back();
    if (!stories.empty() && shape.text.rfind("step ", 0) != 0) stories.back().push_back(shape.text);
  }
  return stories;
}

bool startsWith(const std::string& text, const std::string& start) {
  return text.rfind(start, 0) == 0;
}

}  // namespace

TEST_CASE("a frictionless contact's trace has no friction line", "[trace][friction]") {
  // The cradle's balls have μ = 0: no line may say friction "holds" at 0 N s.
  const auto stories = tracedStories("cradle.toml", 9, "trace_story_cradle");
  REQUIRE(stories.size() >= 4);
  for (const auto& story : stories) {
    for (const std::string& line : story) {
      INFO(line);
      CHECK(line.find("friction") == std::string::npos);
    }
  }
}

TEST_CASE(
    "only the point closing fastest is called the worst; a pair's second corner starts "
    "where the pair did",
    "[trace][micro]") {
  // The resting box lands flat in step 13: the resolver takes both corners in one impulse and
  // reports each. The second is not "the worst closing speed": it names its pair, and its
  // closing speed before is the speed before the pair's impulse (it closed as fast as the first
  // corner), not the one the impulse left it.
  const auto stories = tracedStories("resting_box.toml", 13, "trace_story_pair");
  REQUIRE(stories.size() == 2);
  CHECK(stories[0][0] == "velocity 0: contact 0.0, the worst closing speed");
  CHECK(stories[1][0] ==
        "velocity 0: contact 0.1, in one impulse with contact 0.0 (a pair of "
        "corners)");
  double before[2] = {};
  double after[2] = {};
  for (int i = 0; i < 2; ++i) {
    REQUIRE(startsWith(stories[i][1], "closing speed "));
    REQUIRE(std::sscanf(stories[i][1].c_str(), "closing speed %lf → %lf", &before[i], &after[i]) ==
            2);
  }
  // Both corners closed at 12 g dt plus this step's g dt, 2.126 m/s, before the pair's impulse.
  CHECK(before[1] == Approx(before[0]).margin(1e-3));
  CHECK(before[1] == Approx(13 * 9.81 / 60.0).margin(2e-3));
  CHECK(after[1] < 0.0);
}
