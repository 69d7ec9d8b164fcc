// The stress catalogue: each scene as a function of its knob, with its probe and its limit.
// docs/stability.md explains each one; the numbers below are the scenes' documented constants.
#include <cmath>
#include <stdexcept>

#include "probes.h"
#include "stress_scene.h"

namespace impulse2d::stress {
namespace {

/// s. The time step of every scene but large_dt: 60 updates a second.
constexpr double kDt = 1.0 / 60.0;
/// m/s². Earth's gravity.
constexpr double kGravity = 9.81;
/// Friction of boxes and ground where friction is not the knob (as the stacking tests).
constexpr double kFriction = 0.6;
/// Steps of a run that is not a structure's: 4 s.
constexpr int kRunSteps = 240;
/// A structure's horizon (Horizon): at least 20 s, then windows of 5 s until its motion is
/// bounded, 40 s at most. Slow failures show only late: a 40-box stack under soft step sways
/// over tens of seconds, Box2D v3's default topples a 20-box stack by 10 s.
constexpr long kHorizonLeast = 1200;
constexpr long kHorizonWindow = 300;
constexpr long kHorizonMost = 2400;
/// m. The settling sink allowed per contact between the top body and the ground: the 2 cm a
/// student sees a contact sag on a 1 m box (as heavy_on_light's penetration limit).
constexpr double kSinkPerContact = 0.02;
/// m. A structure fails when a body strays this far from its start: a tenth of a 1 m box, ten
/// times what a standing stack settles by.
constexpr double kDisplacementLimit = 0.1;
/// Boxes and balls of the structures are 1 m wide.
constexpr double kUnit = 1.0;
/// Displacement is measured from the positions at this step (0.5 s): structures start exactly
/// touching, and Box2D first lifts every box by its 1.5 cm of polygon skin, 15 cm at the top of
/// a 10-box stack; a settled structure has done that by then, and a falling one has not fallen.
constexpr long kSkinStep = 30;
/// Penetration and energy are watched from this step on (2 s): structures start exactly
/// touching, which Box2D's 1 cm polygon skin turns into overlaps it spends the first second
/// pushing out.
constexpr long kSettledStep = 120;

const std::string kDisplacementMeasure = "largest sideways displacement of a body after 0.5 s (m)";
const std::string kFallsByEye =
    "a body visibly leaves its place sideways (10 cm is a tenth of a box)";

Scene baseScene(const std::string& name, int steps) {
  Scene scene;
  scene.name = name;
  scene.world.gravity = Vec2(0.0, -kGravity);
  scene.world.dt = kDt;
  scene.steps = steps;
  return scene;
}

BodyDef material(double friction, double density = 1.0, double restitution = 0.0) {
  BodyDef def;
  def.friction = friction;
  def.density = density;
  def.restitution = restitution;
  return def;
}

/// m. The ground: a static box this wide and deep.
constexpr double kGroundWidth = 40.0;
constexpr double kGroundDepth = 1.0;

/// The ground with its top face centred on `top`.
BodyDef ground(const BodyDef& surface, const Vec2& top = Vec2::Zero()) {
  BodyDef def = surface;
  def.name = "ground";
  def.type = BodyType::Static;
  def.shape = makeBox(kGroundWidth, kGroundDepth);
  def.position = top - Vec2(0.0, 0.5 * kGroundDepth);
  return def;
}

/// Where the top face of the scene's ground (body 0) is centred.
Vec2 groundTop(const Scene& scene) {
  return scene.bodies[0].position + Vec2(0.0, 0.5 * kGroundDepth);
}

BodyDef ball(const std::string& name, double radius, const Vec2& centre, const BodyDef& surface) {
  BodyDef def = surface;
  def.name = name;
  def.shape = makeCircle(radius);
  def.position = centre;
  return def;
}

Scene boxStack(double boxes) {
  Scene scene = baseScene("box_stack", kHorizonMost);
  scene.bodies.push_back(ground(material(kFriction)));
  addStack(scene, int(boxes), Vec2(kUnit, kUnit), Vec2::Zero(), 0.0, material(kFriction));
  return scene;
}

Scene circleStack(double balls) {
  Scene scene = baseScene("circle_stack", kHorizonMost);
  scene.bodies.push_back(ground(material(kFriction)));
  for (int k = 0; k < int(balls); ++k) {
    const Vec2 centre(0.0, (k + 0.5) * kUnit);
    scene.bodies.push_back(
        ball("ball" + std::to_string(k), 0.5 * kUnit, centre, material(kFriction)));
  }
  return scene;
}

/// Rows to which micro without warm starting (its variants without a bounce fix) is searched on
/// the pyramid: it spends its 200 impulses per contact every step, and a 20-row run over the
/// horizon costs minutes of CPU, several times the rest of the catalogue.
constexpr double kColdMicroRows = 10;

Scene pyramid(double rows) {
  Scene scene = baseScene("pyramid", kHorizonMost);
  scene.bodies.push_back(ground(material(kFriction)));
  addPyramid(scene, int(rows), Vec2(kUnit, kUnit), Vec2::Zero(), material(kFriction));
  return scene;
}

/// The last body becomes the heavy one: `ratio` times the density of the others.
void makeTopHeavy(Scene& scene, double ratio) {
  scene.bodies.back().name = "heavy";
  scene.bodies.back().density = ratio;
}

/// Light boxes under the heavy one in heavy_on_light.
constexpr int kLightBoxes = 3;
/// m. heavy_on_light fails when a contact sinks deeper than this: four times the slop the
/// sequential solvers leave (0.005 m), a sag a student sees on a 1 m box.
constexpr double kPenetrationLimit = 0.02;

/// m. A box this far sideways from where it started has left the stack it was in: half a box.
constexpr double kSqueezedOut = 0.5 * kUnit;

/// m. The deepest contact from step `from` on, as PenetrationProbe; but a stack whose boxes were
/// squeezed out (a body more than half a box sideways from where it started) has collapsed, and
/// the figure is then that sideways distance: a collapsed stack has no deep contact left to show.
class SinkProbe : public Probe {
 public:
  explicit SinkProbe(long from) : penetration_(from) {}
  void observe(const Simulation& simulation) override {
    penetration_.observe(simulation);
    const std::vector<Body>& bodies = simulation.bodies();
    if (starts_.empty()) {
      for (const Body& body : bodies) starts_.push_back(body.position.x());
    }
    for (size_t i = 0; i < bodies.size(); ++i) {
      const double sideways = std::abs(bodies[i].position.x() - starts_[i]);
      if (sideways > kSqueezedOut) collapse_ = std::max(collapse_, sideways);
    }
  }
  double measure() const override { return std::max(penetration_.measure(), collapse_); }

 private:
  PenetrationProbe penetration_;
  std::vector<double> starts_;
  double collapse_ = 0.0;
};

Scene heavyOnLight(double ratio) {
  Scene scene = baseScene("heavy_on_light", kHorizonMost);
  scene.bodies.push_back(ground(material(kFriction)));
  addStack(scene, kLightBoxes + 1, Vec2(kUnit, kUnit), Vec2::Zero(), 0.0, material(kFriction));
  makeTopHeavy(scene, ratio);
  return scene;
}

/// Rows of the pyramid under the heavy top box in heavy_pyramid (the heavy box is its top row).
constexpr int kHeavyPyramidRows = 4;

Scene heavyPyramid(double ratio) {
  Scene scene = baseScene("heavy_pyramid", kHorizonMost);
  scene.bodies.push_back(ground(material(kFriction)));
  addPyramid(scene, kHeavyPyramidRows, Vec2(kUnit, kUnit), Vec2::Zero(), material(kFriction));
  makeTopHeavy(scene, ratio);
  return scene;
}

/// Boxes of the stack in large_dt and far_from_origin.
constexpr int kSmallStack = 6;
/// s. Simulated time of a large_dt run, whatever its step.
constexpr double kLargeDtDuration = 4.0;
/// m. In large_dt the boxes are dropped with this gap under each, so they land on each other.
constexpr double kDropGap = 0.25;

Scene largeTimeStep(double dt) {
  Scene scene = baseScene("large_dt", int(std::lround(kLargeDtDuration / dt)));
  scene.world.dt = dt;
  scene.bodies.push_back(ground(material(kFriction)));
  for (int k = 0; k < kSmallStack; ++k) {
    addStack(scene, 1, Vec2(kUnit, kUnit), Vec2(0.0, k * (kUnit + kDropGap) + kDropGap), 0.0,
             material(kFriction));
  }
  return scene;
}

/// Where the boxes of a stack of unit boxes on the ground at the origin come to rest.
std::vector<Vec2> stackPlaces(int boxes) {
  std::vector<Vec2> places;
  for (int k = 0; k < boxes; ++k) places.emplace_back(0.0, (k + 0.5) * kUnit);
  return places;
}

/// Tunnelling: a ball of this radius (m) flies at a static wall this thick and tall, starting
/// this gap short of it (beyond the contact margin and Box2D's skin), without gravity, for this
/// many steps. Without continuous collision it tunnels once one step carries its centre past the
/// wall's mid-plane: v·dt > gap + radius + thickness/2, v > 12 m/s at 60 Hz.
constexpr double kBulletRadius = 0.1;
constexpr double kWallThickness = 0.1;
constexpr double kWallHeight = 4.0;
constexpr double kBulletGap = 0.05;
constexpr int kBulletSteps = 30;
/// m. The wall probe's cap: beyond this the ball is simply through.
constexpr double kThroughCap = 1.0;

Scene tunnelling(double speed) {
  Scene scene = baseScene("tunnelling", kBulletSteps);
  scene.world.gravity = Vec2::Zero();
  BodyDef wall = material(kFriction);
  wall.name = "wall";
  wall.type = BodyType::Static;
  wall.shape = makeBox(kWallThickness, kWallHeight);
  scene.bodies.push_back(wall);
  const Vec2 start(-(0.5 * kWallThickness + kBulletRadius + kBulletGap), 0.0);
  scene.bodies.push_back(ball("bullet", kBulletRadius, start, material(kFriction)));
  scene.bodies.back().velocity = Vec2(speed, 0.0);
  return scene;
}

/// Rows of the overlapping pyramid; m/s, its failure speed: a box flung faster than this has been
/// thrown, not pushed apart (it would rise over 20 cm).
constexpr int kOverlapRows = 3;
constexpr double kThrownSpeed = 2.0;

/// Row k of the pyramid sits lower by (k + 1)·overlap box heights, and neighbours in a row are
/// closer by `overlap` box widths, so every contact starts overlapping by that fraction.
Scene overlapRecovery(double overlap) {
  Scene scene = baseScene("overlap_recovery", kRunSteps);
  scene.bodies.push_back(ground(material(kFriction)));
  const double pitch = kUnit * (1.0 - overlap);
  for (int row = 0; row < kOverlapRows; ++row) {
    const int boxes = kOverlapRows - row;
    for (int i = 0; i < boxes; ++i) {
      BodyDef box = material(kFriction);
      box.name = "box" + std::to_string(scene.bodies.size());
      box.shape = makeBox(kUnit, kUnit);
      box.position =
          Vec2((i - 0.5 * (boxes - 1)) * pitch, (row + 0.5) * kUnit - (row + 1) * overlap * kUnit);
      scene.bodies.push_back(box);
    }
  }
  return scene;
}

/// m/s, largest speed of any dynamic body over the run.
class SpeedProbe : public Probe {
 public:
  void observe(const Simulation& simulation) override {
    for (const Body& body : simulation.bodies())
      largest_ = std::max(largest_, body.velocity.norm());
  }
  double measure() const override { return largest_; }

 private:
  double largest_ = 0.0;
};

/// Boxes of the bouncy stack; m, its energy limit: the whole stack lifted by 1 cm.
constexpr int kBouncyStack = 5;
constexpr double kEnergyRiseLimit = 0.01;

Scene restitutionStack(double restitution) {
  Scene scene = baseScene("restitution_stack", kRunSteps);
  scene.bodies.push_back(ground(material(kFriction, 1.0, restitution)));
  addStack(scene, kBouncyStack, Vec2(kUnit, kUnit), Vec2::Zero(), 0.0,
           material(kFriction, 1.0, restitution));
  return scene;
}

/// Newton's cradle without gravity: a striker at this speed (m/s, above every method's bounce
/// threshold) starts this gap (m) short of a row of touching balls, elastic and frictionless.
constexpr double kStrikeSpeed = 2.0;
constexpr double kStrikeGap = 0.25;
constexpr int kCradleSteps = 60;
/// The cradle fails when the far ball leaves with less than 90% of the striker's speed.
constexpr double kCradleLoss = 0.1;

Scene newtonsCradle(double balls) {
  Scene scene = baseScene("newtons_cradle", kCradleSteps);
  scene.world.gravity = Vec2::Zero();
  const BodyDef elastic = material(0.0, 1.0, 1.0);
  scene.bodies.push_back(ball("striker", 0.5 * kUnit, Vec2(-kUnit - kStrikeGap, 0.0), elastic));
  scene.bodies.back().velocity = Vec2(kStrikeSpeed, 0.0);
  for (int k = 0; k < int(balls); ++k) {
    scene.bodies.push_back(
        ball("ball" + std::to_string(k), 0.5 * kUnit, Vec2(k * kUnit, 0.0), elastic));
  }
  return scene;
}

/// Landing on a slope: unit boxes dropped flat from about this height (m, the knob) onto a static
/// slope of this angle, friction kSlopeFriction on both, more than tan 20° = 0.36, so each box
/// must stop where it lands: an inelastic impact with Coulomb friction removes a vertical fall's
/// tangential speed whenever μ ≥ tan θ. How deep a box is when its landing step is found depends
/// on where in a step it reaches the slope, so kLandingBoxes boxes, kLandingSpacing (m) apart
/// along the slope, fall from heights that differ by a fraction of a step's fall.
constexpr double kSlopeAngle = 20.0 * kPi / 180.0;
constexpr double kSlopeFriction = 0.5;
constexpr int kLandingBoxes = 8;
constexpr double kLandingSpacing = 3.0;
/// m. Landing fails when a box slides this far down the slope after its first contact.
constexpr double kSlideLimit = 0.01;

Vec2 slopeTangent() {
  return Vec2(std::cos(kSlopeAngle), std::sin(kSlopeAngle));
}
Vec2 slopeNormal() {
  return Vec2(-std::sin(kSlopeAngle), std::cos(kSlopeAngle));
}

Scene slopeLanding(double drop) {
  Scene scene = baseScene("slope_landing", kRunSteps);
  BodyDef slope = ground(material(kSlopeFriction));
  slope.name = "slope";
  slope.angle = kSlopeAngle;
  slope.position = -0.5 * kGroundDepth * slopeNormal();
  scene.bodies.push_back(slope);
  const double stepFall = std::sqrt(2.0 * kGravity * drop) * kDt;  // the last step's fall
  for (int k = 0; k < kLandingBoxes; ++k) {
    BodyDef box = material(kSlopeFriction);
    box.name = "box" + std::to_string(k);
    box.shape = makeBox(kUnit, kUnit);
    box.angle = kSlopeAngle;
    const double along = (k - 0.5 * (kLandingBoxes - 1)) * kLandingSpacing;
    const double height = drop + stepFall * k / kLandingBoxes;
    box.position = along * slopeTangent() + (0.5 * kUnit + height) * slopeNormal();
    scene.bodies.push_back(box);
  }
  return scene;
}

/// m. The farthest any dynamic body moved down the slope after the step in which it first
/// stopped falling freely (its velocity changed by other than g·dt): the slide after landing.
class LandingSlideProbe : public Probe {
 public:
  void observe(const Simulation& simulation) override {
    const std::vector<Body>& bodies = simulation.bodies();
    boxes_.resize(bodies.size());
    const Vec2 gravityStep = simulation.settings().dt * simulation.settings().gravity;
    for (size_t i = 0; i < bodies.size(); ++i) {
      if (bodies[i].isStatic()) continue;
      Box& box = boxes_[i];
      const double along = bodies[i].position.dot(slopeTangent());
      if (simulation.stepCount() > 0 && !box.landed) {
        box.landed = (bodies[i].velocity - box.lastVelocity - gravityStep).norm() > kTolerance;
        box.landedAt = along;
      }
      box.lastVelocity = bodies[i].velocity;
      if (box.landed) largest_ = std::max(largest_, box.landedAt - along);
    }
  }
  double measure() const override { return largest_; }

 private:
  /// m/s. A velocity change this far from gravity's is a contact's.
  static constexpr double kTolerance = 1e-6;
  struct Box {
    Vec2 lastVelocity = Vec2::Zero();
    bool landed = false;
    double landedAt = 0.0;
  };
  std::vector<Box> boxes_;
  double largest_ = 0.0;
};

/// The arch: a semicircle of this many voussoirs between these radii (m), standing on the ground.
constexpr int kVoussoirs = 9;
constexpr double kArchInner = 2.0;
constexpr double kArchOuter = 2.6;
/// Joints from the ground up either side to the crown: the ground's and four between voussoirs.
constexpr int kArchJoints = (kVoussoirs + 1) / 2;

Scene arch(double friction) {
  Scene scene = baseScene("arch", kHorizonMost);
  scene.bodies.push_back(ground(material(friction)));
  for (int k = 0; k < kVoussoirs; ++k) {
    const double from = kPi * k / kVoussoirs;
    const double to = kPi * (k + 1) / kVoussoirs;
    auto at = [](double radius, double angle) {
      return Vec2(radius * std::cos(angle), radius * std::sin(angle));
    };
    const CentredPolygon block = makePolygon(
        {at(kArchInner, from), at(kArchOuter, from), at(kArchOuter, to), at(kArchInner, to)});
    BodyDef voussoir = material(friction);
    voussoir.name = "voussoir" + std::to_string(k);
    voussoir.shape = block.shape;
    voussoir.position = block.centroid;
    scene.bodies.push_back(voussoir);
  }
  return scene;
}

/// The card house: cards this long and thick (m), each tent's two cards leaning this far from
/// the vertical (rad), two tents this far apart (m, apex to apex) under a roof card this long.
constexpr double kCardLength = 2.0;
constexpr double kCardThickness = 0.05;
constexpr double kCardLean = 20.0 * kPi / 180.0;
constexpr double kTentSpacing = 2.0;
constexpr double kRoofLength = 3.0;
/// Contacts under the roof: card on ground, roof on card.
constexpr int kCardLayers = 2;

/// A card leaning towards x = apexX from the side `side` (−1 left, +1 right), its lower outer
/// corner on the ground and its upper inner corner at x = apexX, height kCardLength·cos(lean).
BodyDef leaningCard(double apexX, int side, const BodyDef& surface) {
  const double c = std::cos(kCardLean), s = std::sin(kCardLean);
  BodyDef card = surface;
  card.name = "card";
  card.shape = makeBox(kCardThickness, kCardLength);
  card.angle = side < 0 ? -kCardLean : kCardLean;
  card.position = Vec2(apexX + side * (0.5 * kCardThickness * c + 0.5 * kCardLength * s),
                       0.5 * kCardThickness * s + 0.5 * kCardLength * c);
  return card;
}

Scene cardHouse(double friction) {
  Scene scene = baseScene("card_house", kHorizonMost);
  scene.bodies.push_back(ground(material(friction)));
  for (double apex : {-0.5 * kTentSpacing, 0.5 * kTentSpacing}) {
    for (int side : {-1, 1}) scene.bodies.push_back(leaningCard(apex, side, material(friction)));
  }
  BodyDef roof = material(friction);
  roof.name = "roof";
  roof.shape = makeBox(kRoofLength, kCardThickness);
  roof.position = Vec2(0.0, kCardLength * std::cos(kCardLean) + 0.5 * kCardThickness);
  scene.bodies.push_back(roof);
  return scene;
}

/// Warm-start energy: three balls of this radius (m) stacked on the ground; the top one is
/// removed (moved this far away, m, out of every contact) before this step; the run ends this
/// many steps later. The others fail if they pop up by more than the limit (m).
constexpr double kStackedBallRadius = 0.5;
constexpr double kRemovalDistance = 1000.0;
constexpr long kRemovalStep = 60;
constexpr int kAfterRemovalSteps = 60;
constexpr double kPopLimit = 0.01;

Scene warmStartPop(double ratio) {
  Scene scene = baseScene("warm_start_pop", int(kRemovalStep) + kAfterRemovalSteps);
  scene.bodies.push_back(ground(material(kFriction)));
  for (int k = 0; k < 3; ++k) {
    const Vec2 centre(0.0, (2 * k + 1) * kStackedBallRadius);
    scene.bodies.push_back(
        ball("ball" + std::to_string(k), kStackedBallRadius, centre, material(kFriction)));
  }
  makeTopHeavy(scene, ratio);
  return scene;
}

/// The World has no way to remove a body: the heavy ball is moved far away and stopped, which
/// takes it out of every contact just as a removal would.
void removeHeavyBall(std::vector<Body>& bodies) {
  Body& heavy = bodies.back();
  heavy.position = Vec2(kRemovalDistance, kRemovalDistance);
  heavy.velocity.setZero();
  heavy.angularVelocity = 0.0;
  heavy.updateCache();
}

/// m. far_from_origin fails when a body is this far from where the same run puts it at the origin.
constexpr double kTwinLimit = 0.01;

Scene farFromOrigin(double distance) {
  Scene scene = baseScene("far_from_origin", kRunSteps);
  const Vec2 origin(distance, distance);
  scene.bodies.push_back(ground(material(kFriction), origin));
  addStack(scene, kSmallStack, Vec2(kUnit, kUnit), origin, 0.0, material(kFriction));
  return scene;
}

/// The horizon of a structure whose top body stands on `contacts(knob)` contacts above the ground,
/// whose creep is judged against `creepLimit` (m) sideways.
Horizon structureHorizon(const std::function<int(double knob)>& contacts,
                         double creepLimit = kDisplacementLimit) {
  return {kHorizonLeast, kHorizonWindow, kHorizonMost,
          [contacts](double knob) { return kSinkPerContact * contacts(knob); }, creepLimit};
}

/// Contacts under the top of a stack or pyramid: one per box or row.
int perLayer(double layers) {
  return int(layers);
}

template <typename ProbeType, typename... Arguments>
std::function<std::unique_ptr<Probe>(const Scene&)> probeOf(Arguments... arguments) {
  return [=](const Scene&) { return std::make_unique<ProbeType>(arguments...); };
}

/// Stacks and pyramids: how tall, how heavy a load.
void stackScenes(std::vector<StressScene>& scenes) {
  const Criterion displacement{kDisplacementMeasure, kDisplacementLimit, kFallsByEye, true};
  const Knob boxes{"boxes", "", 2, 40, KnobScale::Integer};
  const Knob ratio{"mass ratio", "", 1, 1000, KnobScale::Logarithmic};
  scenes.push_back({"box_stack",
                    "Tall stack of boxes",
                    boxes,
                    displacement,
                    boxStack,
                    probeOf<DisplacementProbe>(kSkinStep),
                    {},
                    {},
                    {"soft step, 16 substeps at 240 Hz", "micro − pairs"},
                    structureHorizon(perLayer)});
  scenes.push_back({"circle_stack",
                    "Tall stack of circles",
                    {"balls", "", 2, 40, KnobScale::Integer},
                    displacement,
                    circleStack,
                    probeOf<DisplacementProbe>(kSkinStep),
                    {},
                    {},
                    {},
                    structureHorizon(perLayer)});
  scenes.push_back({"pyramid",
                    "Pyramid",
                    {"rows", "", 2, 20, KnobScale::Integer},
                    displacement,
                    pyramid,
                    probeOf<DisplacementProbe>(kSkinStep),
                    {},
                    {{"micro − acceleration removal", kColdMicroRows},
                     {"micro − low-speed restitution", kColdMicroRows}},
                    {"micro − pairs", "sequential − conjugate gradient"},
                    structureHorizon(perLayer)});
  scenes.push_back({"heavy_on_light",
                    "Heavy box on light ones",
                    ratio,
                    {"deepest contact penetration (m), or how far a box was squeezed out "
                     "sideways (over half a box)",
                     kPenetrationLimit,
                     "the heavy box visibly sinks into the box under it (2 cm), or the light boxes "
                     "are squeezed out",
                     true},
                    heavyOnLight,
                    probeOf<SinkProbe>(kSettledStep),
                    {},
                    {},
                    {"sequential + 4 substeps", "sequential − conjugate gradient",
                     "soft step, 16 substeps at 240 Hz", "micro − pairs"},
                    structureHorizon([](double) { return kLightBoxes + 1; }, kSqueezedOut)});
  scenes.push_back({"heavy_pyramid",
                    "Pyramid topped by a heavy box",
                    ratio,
                    displacement,
                    heavyPyramid,
                    probeOf<DisplacementProbe>(kSkinStep),
                    {},
                    {},
                    {"sequential + 4 substeps", "sequential − conjugate gradient"},
                    structureHorizon([](double) { return kHeavyPyramidRows; })});
}

/// Steps, speeds, overlaps and bounces.
void motionScenes(std::vector<StressScene>& scenes) {
  scenes.push_back(
      {"large_dt",
       "Large time step",
       {"dt", "s", 1.0 / 240, 1.0 / 15, KnobScale::Logarithmic},
       {"largest sideways distance of a box from its place in the stack at the end (m)",
        kDisplacementLimit, "the dropped stack ends leaning, toppled or scattered", true},
       largeTimeStep,
       probeOf<PlaceProbe>(stackPlaces(kSmallStack)),
       {},
       {},
       {"sequential − accumulation + 4 substeps"},
       {}});
  scenes.push_back(
      {"tunnelling",
       "Fast small ball against a thin wall",
       {"speed", "m/s", 1, 1000, KnobScale::Logarithmic},
       {"how far the ball's centre got past the wall's mid-plane (m, capped at 1)", 0.0,
        "the ball appears on the far side of the wall", false},
       tunnelling,
       probeOf<WallProbe>(1, 0.0, kThroughCap),
       {},
       {},
       {"sequential − continuous", "sequential − continuous + speculative contacts",
        "sequential − continuous + 4 substeps", "soft step − speculative contacts − continuous"},
       {}});
  scenes.push_back({"slope_landing",
                    "Landing on a slope that holds",
                    {"drop height", "m", 0.0, 1.0, KnobScale::Linear},
                    {"slide down the slope after the box first touches it (m)", kSlideLimit,
                     "the box lands, then slides down the slope before it sticks", true},
                    slopeLanding,
                    probeOf<LandingSlideProbe>(),
                    {},
                    {},
                    {"sequential + speculative contacts", "sequential − bias",
                     "soft step − speculative contacts"},
                    {}});
  scenes.push_back({"overlap_recovery",
                    "Overlap recovery",
                    {"overlap", "box sizes", 0.0, 0.5, KnobScale::Linear},
                    {"largest speed of a body (m/s)", kThrownSpeed,
                     "boxes fly apart instead of being pushed out of each other", true},
                    overlapRecovery,
                    probeOf<SpeedProbe>(),
                    {},
                    {},
                    {"sequential − bias"},
                    {}});
  scenes.push_back({"restitution_stack",
                    "High restitution on a stack",
                    {"restitution", "", 0.0, 1.0, KnobScale::Linear},
                    {"energy gained, as a lift of the whole stack (m)", kEnergyRiseLimit,
                     "boxes resting on each other start to hop", true},
                    restitutionStack,
                    probeOf<EnergyRiseProbe>(kSettledStep),
                    {},
                    {},
                    {"micro − both bounce fixes"},
                    {}});
  scenes.push_back(
      {"newtons_cradle",
       "Newton's cradle",
       {"balls", "", 1, 10, KnobScale::Integer},
       {"fraction of the striker's speed the far ball does not carry away", kCradleLoss,
        "the whole row moves off together instead of the far ball alone", false},
       newtonsCradle,
       [](const Scene& scene) -> std::unique_ptr<Probe> {
         return std::make_unique<CradleProbe>(int(scene.bodies.size()) - 1, kStrikeSpeed);
       },
       {},
       {},
       {},
       {}});
}

/// Friction, a removal and distance from the origin.
void holdingScenes(std::vector<StressScene>& scenes) {
  const Criterion displacement{kDisplacementMeasure, kDisplacementLimit, kFallsByEye, true};
  const Knob ratio{"mass ratio", "", 1, 1000, KnobScale::Logarithmic};
  const Knob friction{"friction coefficient", "", 1.0, 0.0, KnobScale::Linear};
  scenes.push_back({"arch",
                    "Arch held by friction",
                    friction,
                    displacement,
                    arch,
                    probeOf<DisplacementProbe>(kSkinStep),
                    {},
                    {},
                    {},
                    structureHorizon([](double) { return kArchJoints; })});
  scenes.push_back({"card_house",
                    "Card house held by friction",
                    friction,
                    displacement,
                    cardHouse,
                    probeOf<DisplacementProbe>(kSkinStep),
                    {},
                    {},
                    {},
                    structureHorizon([](double) { return kCardLayers; })});
  scenes.push_back({"warm_start_pop",
                    "Warm-start energy: the heavy top ball removed",
                    ratio,
                    {"largest rise of the remaining balls after the removal (m)", kPopLimit,
                     "the two remaining balls jump when the top one vanishes", true},
                    warmStartPop,
                    probeOf<RiseProbe>(std::vector<int>{1, 2}, kRemovalStep),
                    {{kRemovalStep, removeHeavyBall,
                      "the heavy ball is moved 1 km away and stopped (the World cannot remove a "
                      "body)"}},
                    {},
                    {},
                    {}});
  scenes.push_back(
      {"far_from_origin",
       "Far from the origin",
       {"distance", "m", 1, 1e6, KnobScale::Logarithmic},
       {"largest difference from the same run at the origin (m)", kTwinLimit,
        "the stack settles or jitters differently from the same stack at the origin", true},
       farFromOrigin,
       [](const Scene& scene) -> std::unique_ptr<Probe> {
         return std::make_unique<TwinProbe>(scene, groundTop(scene));
       },
       {},
       {},
       {},
       {}});
}

}  // namespace

std::vector<StressScene> catalogue() {
  std::vector<StressScene> scenes;
  stackScenes(scenes);
  motionScenes(scenes);
  holdingScenes(scenes);
  return scenes;
}

StressScene findStressScene(const std::string& name) {
  std::string known;
  for (StressScene& scene : catalogue()) {
    if (scene.name == name) return scene;
    known += (known.empty() ? "" : ", ") + scene.name;
  }
  throw std::invalid_argument("unknown stress scene '" + name + "' (known: " + known + ")");
}

}  // namespace impulse2d::stress
