// Tipping on a slope: a box held by friction (μ = 1, above every tan θ here) stands while the
// vertical through its centre of mass falls inside its base, i.e. while tan θ < w / h, and tips
// over once it falls outside. Not a friction fact but a torque one: gravity's moment about the
// downhill corner against the contact impulses', which every method must get from the contact
// points and arms. Each box is tried 2° either side of atan(w / h), placed on the slope and
// dropped onto it from 2 cm.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "exact_motion.h"
#include "impulse2d/scene/scene_file.h"
#include "lecture_scenes.h"

using namespace impulse2d;

namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kFriction = 1.0;

struct TippingRun {
  double largestTurn = 0.0;  ///< rad, the most the box turned from the slope at any step
  double finalTurn = 0.0;    ///< rad, after 4 s
  double slid = 0.0;         ///< m along the slope from t = 1 s (landed) to 4 s
};

TippingRun runTipping(const std::string& solver, const Vec2& size, double angle, double lift) {
  Scene scene = lecture::sceneWith(solver, kDt);
  scene.bodies.push_back(lecture::ground(kFriction, angle));
  scene.bodies.push_back(lecture::boxOnSlope(size, angle, kFriction, lift));
  auto world = buildWorld(scene);
  Vec2 landed = Vec2::Zero();
  TippingRun run;
  for (int step = 1; step <= 240; ++step) {
    world->step();
    if (step == 60) landed = world->bodies()[1].position;
    run.largestTurn = std::max(run.largestTurn, std::abs(world->bodies()[1].angle - angle));
  }
  run.finalTurn = world->bodies()[1].angle - angle;
  run.slid = (world->bodies()[1].position - landed).dot(lecture::downSlope(angle));
  return run;
}

}  // namespace

TEST_CASE("a tall box on a slope stands while tan θ < w / h and tips over beyond it",
          "[tipping][slope]") {
  for (const std::string solver : {"micro", "sequential", "soft_step", "reference"}) {
    for (const Vec2& size : {Vec2(0.5, 2.0), Vec2(0.6, 1.2)}) {
      const double tippingAngle = std::atan(size.x() / size.y());  // 14.0° and 26.6°
      for (const double lift : {0.0, 0.02}) {
        const double margin = 2.0 * kPi / 180.0;  // rad either side of the tipping angle
        const double below = tippingAngle - margin;
        const TippingRun stands = runTipping(solver, size, below, lift);
        INFO(solver << ", " << size.x() << " x " << size.y() << ", lift " << lift << ", "
                    << below * 180.0 / kPi << " deg: turned at most " << stands.largestTurn
                    << " rad, " << stands.finalTurn << " rad at the end, slid " << stands.slid
                    << " m after landing");
        // Turned by the margin about its downhill corner it would be past tipping: it must rock
        // less (soft step's compliant landing rocks it 0.012 rad), and end level on its face to
        // 1e-3 rad (half a millimetre across the narrower base), not sliding.
        CHECK(stands.largestTurn < margin);
        CHECK(std::abs(stands.finalTurn) < 1e-3);
        CHECK(std::abs(stands.slid) < 1e-3);
        const double beyond = tippingAngle + margin;
        const TippingRun tips = runTipping(solver, size, beyond, lift);
        INFO(beyond * 180.0 / kPi << " deg: turned " << tips.finalTurn << " rad");
        CHECK(std::abs(tips.finalTurn) == Approx(kPi / 2.0).margin(0.01));  // on its side
      }
    }
  }
}

namespace {

constexpr double kPlankLength = 2.0;
constexpr double kPlankThickness = 0.1;

/// A static ledge whose top is y = 0 and whose right edge is x = 0, and a plank lying on it at
/// rest with its centre `overhang` beyond the edge (negative: over the ledge), friction μ = 1.
Scene plankOverLedge(const std::string& solver, double dt, double overhang) {
  Scene scene = lecture::sceneWith(solver, dt);
  BodyDef ledge;
  ledge.name = "ledge";
  ledge.type = BodyType::Static;
  ledge.shape = makeBox(4.0, 1.0);
  ledge.position = Vec2(-2.0, -0.5);
  ledge.friction = kFriction;
  scene.bodies.push_back(ledge);
  BodyDef plank;
  plank.name = "plank";
  plank.shape = makeBox(kPlankLength, kPlankThickness);
  plank.position = Vec2(overhang, 0.5 * kPlankThickness);
  plank.friction = kFriction;
  scene.bodies.push_back(plank);
  return scene;
}

/// rad, clockwise, after `seconds` from rest: the plank turning about the ledge's edge, which
/// stays put under it: (I + m r²) θ'' = m g (d cos θ + (t / 2) sin θ), r the centre's distance
/// from the edge.
double tippedOverEdge(double overhang, double seconds) {
  const double mass = kPlankLength * kPlankThickness;
  const Vec2 centre(overhang, 0.5 * kPlankThickness);  // from the edge
  const double aboutEdge =
      mass * (kPlankLength * kPlankLength + kPlankThickness * kPlankThickness) / 12.0 +
      mass * centre.squaredNorm();
  const auto acceleration = [&](double angle, double) {
    return mass * lecture::kGravity *
           (centre.x() * std::cos(angle) + centre.y() * std::sin(angle)) / aboutEdge;
  };
  return exact::turnAfter({0.0, 0.0}, seconds, 1e-4, acceleration).angle;
}

}  // namespace

// A plank over the edge of a ledge: while the vertical through its centre falls on the ledge it
// lies still; once the centre is beyond the edge by d it turns about the edge, starting at
// θ'' = m g d / (I + m r²). Placed at rest with d from −0.5 to 0.6 m. Still: moved less than half
// of what creeping at micro's velocity epsilon (1e-4 m/s) would cover in 3 s. Tipping: the angle
// after 0.1 and 0.2 s equals the exact rigid turn within the integrator's lag, its spin times
// its step (at most 2 θ / t times dt, or soft step's substep). Measured: micro, sequential
// impulses and the reference lie exactly on semi-implicit Euler's answer ((n + 1) / n of the exact
// angle after n steps), soft step within its substeps' lag; still planks moved < 1e-13 m (soft
// step 8.4e-5 m).
TEST_CASE("a plank over a ledge lies still with its centre over it, and tips about the edge beyond",
          "[tipping]") {
  for (const std::string solver : {"micro", "sequential", "soft_step", "reference"}) {
    for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
      const int substeps = solver == "soft_step" ? SoftStepSettings{}.substeps : 1;
      for (const double overhang : {-0.5, -0.1, -0.02}) {
        auto world = buildWorld(plankOverLedge(solver, dt, overhang));
        const Vec2 start = world->bodies()[1].position;
        while (world->stepCount() * dt < 3.0) world->step();
        const double moved = (world->bodies()[1].position - start).norm();
        INFO(solver << ", dt " << dt << ", centre " << overhang << " m beyond the edge: moved "
                    << moved << " m");
        CHECK(moved < 0.5 * MicroCollisionSettings{}.velocityEpsilon * 3.0);
      }
      for (const double overhang : {0.1, 0.3, 0.6}) {
        auto world = buildWorld(plankOverLedge(solver, dt, overhang));
        for (const double seconds : {0.1, 0.2}) {
          while (world->stepCount() < std::lround(seconds / dt)) world->step();
          const double turned = -world->bodies()[1].angle;
          const double exact = tippedOverEdge(overhang, seconds);
          INFO(solver << ", dt " << dt << ", centre " << overhang << " m beyond the edge, after "
                      << seconds << " s: turned " << turned << " rad (exact " << exact << ")");
          CHECK(turned == Approx(exact).margin(2.0 * exact / seconds * dt / substeps));
        }
      }
    }
  }
}

// A disc sliding without friction off a table's edge: its centre goes round the edge like a
// particle on a circle of radius r (without friction nothing turns it), with
// v² = v₀² + 2 g r (1 − cos φ), and the edge lets go once gravity's part along the radius no
// longer covers the centripetal need, g cos φ = v² / r: at cos φ = (2/3)(1 + v₀² / (2 g r)). It
// then flies at the speed it left with, its horizontal speed v cos φ for good. Leaving a step
// early or late changes that by at most the speed gravity adds along the path in a step,
// g dt sin φ. A method whose contact normal is kept from a step before (Box2D v3's contact
// recycling of soft step with recycle_round_normals) pivots on a stale normal and is off by
// 0.8 % however short the step; held here down to 3,840 Hz (0.18 % there).
TEST_CASE("a disc sliding off a frictionless table's edge leaves it at cos φ = ⅔ (1 + v₀² / 2 g r)",
          "[tipping][contact]") {
  for (const std::string solver : {"micro", "sequential", "soft_step", "reference"}) {
    for (const double radius : {0.1, 0.3}) {
      for (const double speed : {0.05, 0.5}) {
        for (const double rate : {60.0, 240.0, 960.0, 3840.0}) {
          const double dt = 1.0 / rate;
          Scene scene = lecture::sceneWith(solver, dt);
          BodyDef table;
          table.type = BodyType::Static;
          table.shape = makeBox(10.0, 1.0);
          table.position = Vec2(-5.0, -0.5);  // its top right edge at the origin
          table.friction = 0.0;
          scene.bodies.push_back(table);
          BodyDef disc;
          disc.shape = makeCircle(radius);
          disc.position = Vec2(-0.02, radius);
          disc.velocity = Vec2(speed, 0.0);
          disc.friction = 0.0;
          scene.bodies.push_back(disc);
          auto world = buildWorld(scene);
          while (world->bodies()[1].position.y() > -radius) world->step();
          const double g = lecture::kGravity;
          const double leaving = 2.0 / 3.0 * (1.0 + speed * speed / (2.0 * g * radius));
          const double exact = std::sqrt(g * radius * leaving) * leaving;
          const double flying = world->bodies()[1].velocity.x();
          INFO(solver << ", r " << radius << " m, v0 " << speed << " m/s, " << rate
                      << " Hz: flies off at " << flying << " m/s (exact " << exact << ")");
          CHECK(flying == Approx(exact).margin(g * dt * std::sqrt(1.0 - leaving * leaving)));
        }
      }
    }
  }
}

namespace {

constexpr double kSeesawLength = 4.0;     // m
constexpr double kSeesawThickness = 0.1;  // m
constexpr double kSeatBox = 0.4;          // m, the boxes sitting on the plank
constexpr double kFulcrumTip = 1.0;       // m above the ground
constexpr int kPlank = 2;
constexpr int kLeftBox = 3;
constexpr int kRightBox = 4;

/// A seesaw: a plank balanced on the tip of a static triangle, a box of mass `left` a distance
/// `leftArm` to the left of the tip and one of mass `right` at `rightArm` to its right, all at
/// rest, exactly touching, friction 1 everywhere.
Scene seesawScene(const std::string& solver, double dt, double left, double leftArm, double right,
                  double rightArm) {
  Scene scene = lecture::sceneWith(solver, dt);
  scene.bodies.push_back(lecture::ground(kFriction));
  const CentredPolygon triangle =
      makePolygon({Vec2(-0.4, 0.0), Vec2(0.4, 0.0), Vec2(0.0, kFulcrumTip)});
  BodyDef fulcrum;
  fulcrum.type = BodyType::Static;
  fulcrum.shape = triangle.shape;
  fulcrum.position = triangle.centroid;
  fulcrum.friction = kFriction;
  scene.bodies.push_back(fulcrum);
  BodyDef plank;
  plank.shape = makeBox(kSeesawLength, kSeesawThickness);
  plank.position = Vec2(0.0, kFulcrumTip + 0.5 * kSeesawThickness);
  plank.friction = kFriction;
  scene.bodies.push_back(plank);
  const double seat = kFulcrumTip + kSeesawThickness + 0.5 * kSeatBox;
  for (const auto& [mass, at] : {std::pair{left, -leftArm}, std::pair{right, rightArm}}) {
    BodyDef box;
    box.shape = makeBox(kSeatBox, kSeatBox);
    box.density = mass / (kSeatBox * kSeatBox);
    box.position = Vec2(at, seat);
    box.friction = kFriction;
    scene.bodies.push_back(box);
  }
  return scene;
}

/// rad/s². The plank's angular acceleration from rest: the boxes' and the plank's weights'
/// moment about the fulcrum's tip over their moment of inertia about it.
double seesawAcceleration(const World& world) {
  const Vec2 tip(0.0, kFulcrumTip);
  double inertia = 0.0;
  double torque = 0.0;
  for (const int i : {kPlank, kLeftBox, kRightBox}) {
    const Body& body = world.bodies()[size_t(i)];
    inertia += body.inertia + body.mass * (body.position - tip).squaredNorm();
    torque -= (body.position.x() - tip.x()) * body.mass * lecture::kGravity;
  }
  return torque / inertia;
}

}  // namespace

// A plank on a fulcrum balances when the moments of its loads about the tip cancel,
// m₁ d₁ = m₂ d₂, and otherwise starts turning at α = Σ m g d / I about the tip, the boxes riding
// on it by friction. From rest semi-implicit Euler turns it α dt² n (n + 1) / 2 in n steps, which
// the rigid methods follow within 1 % over the first 0.1 s. Soft step's springs give at the tip
// (0.88–0.93 of that at 60 Hz), so for it the test holds the boxes to their places on the plank
// while it turns: with Box2D v3's recycling, measured in A's frame, a box and a plank turning
// together never count as moving, the box's unturned arm reads a slip that is not there, and
// friction holding it drags the box outward by about d θ² / 2 (docs/soft-step.md).
TEST_CASE("a seesaw balances when m₁ d₁ = m₂ d₂, and otherwise turns at Σ m g d / I about its tip",
          "[tipping][seesaw]") {
  for (const std::string solver : {"micro", "sequential", "reference", "soft_step"}) {
    for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
      for (const auto& [left, leftArm] : {std::pair{1.0, 1.5}, std::pair{2.0, 0.75}}) {
        auto world = buildWorld(seesawScene(solver, dt, left, leftArm, 1.0, 1.5));
        double farthest = 0.0;  // m, the plank's ends from where they started
        while (world->stepCount() * dt < 2.0) {
          world->step();
          farthest = std::max(
              farthest, 0.5 * kSeesawLength * std::abs(std::sin(world->bodies()[kPlank].angle)));
        }
        INFO(solver << ", dt " << dt << ", balanced " << left << " kg at " << leftArm
                    << " m: the plank's end moved " << farthest << " m in 2 s");
        CHECK(farthest < 1e-3);
      }
      if (solver == "soft_step") continue;
      for (const double left : {1.05, 2.1, 3.0}) {
        auto world = buildWorld(seesawScene(solver, dt, left, 1.5, 1.0, 1.5));
        const double acceleration = seesawAcceleration(*world);
        const long steps = std::lround(0.1 / dt);
        while (world->stepCount() < steps) world->step();
        const double discrete = acceleration * dt * dt * double(steps * (steps + 1)) / 2.0;
        INFO(solver << ", dt " << dt << ", " << left << " kg against 1 kg at 1.5 m: turned "
                    << world->bodies()[kPlank].angle << " rad in 0.1 s, semi-implicit Euler "
                    << discrete);
        CHECK(world->bodies()[kPlank].angle == Approx(discrete).epsilon(0.01));
      }
    }
  }
  const auto creep = [](const std::vector<std::string>& settings) {
    Scene scene = seesawScene("soft_step", 1.0 / 60.0, 1.05, 1.5, 1.0, 1.5);
    for (const std::string& setting : settings) applySetting(scene, setting);
    auto world = buildWorld(scene);
    const Body& plank = world->bodies()[kPlank];
    const Vec2 seated = plank.toLocal(world->bodies()[kRightBox].position);
    while (plank.angle < 0.18 && world->stepCount() < 600) world->step();
    return (plank.toLocal(world->bodies()[kRightBox].position) - seated).norm();
  };
  const double worldFrame = creep({});
  const double aFrame = creep({"solver.recycling=box2d_v3"});
  INFO("soft step: the right box moved " << worldFrame << " m along the plank by 0.18 rad ("
                                         << aFrame << " m with v3's measure)");
  CHECK(worldFrame < 0.01);
  CHECK(aFrame > 0.02);
}

namespace {

/// A convex polygon of 4 to 7 corners on an ellipse (half axes 0.2 to 0.8 m, turned at random),
/// the corners spread round it with jitter, so every corner turns by at least 20°.
Shape randomConvexPolygon(std::mt19937& random) {
  const auto uniform = [&random](double low, double high) {
    return low + (high - low) * double(random()) / double(std::mt19937::max());
  };
  const int corners = 4 + int(random() % 4);
  const double a = uniform(0.2, 0.8);
  const double b = uniform(0.2, 0.8);
  const double turn = uniform(0.0, 2.0 * kPi);
  std::vector<Vec2> vertices;
  for (int k = 0; k < corners; ++k) {
    const double at = 2.0 * kPi * (k + uniform(-0.25, 0.25)) / corners;
    const Vec2 onEllipse(a * std::cos(at), b * std::sin(at));
    vertices.push_back(rotation(turn) * onEllipse);
  }
  return makePolygon(vertices).shape;
}

struct FacePlacement {
  double angle = 0.0;   ///< rad, the body's angle that puts the face down
  double height = 0.0;  ///< m, the centroid above the ground with the face on it
  double left = 0.0;    ///< m, the face's ends relative to the centroid's x
  double right = 0.0;
};

/// The pose that lays `shape` on its face `face` on flat ground.
FacePlacement onFace(const Shape& shape, int face) {
  const Vec2 normal = shape.normals[size_t(face)];
  FacePlacement placement;
  placement.angle = -0.5 * kPi - std::atan2(normal.y(), normal.x());
  const Mat2 turn = rotation(placement.angle);
  const Vec2 a = turn * shape.vertices[size_t(face)];
  const Vec2 b = turn * shape.vertices[(size_t(face) + 1) % shape.vertices.size()];
  placement.height = -a.y();
  placement.left = std::min(a.x(), b.x());
  placement.right = std::max(a.x(), b.x());
  return placement;
}

}  // namespace

// A body lying on a face stands while the vertical through its centroid falls inside that face,
// and tips about the nearer end once it falls outside: the ground's push can only act within the
// face, so only there can it balance the weight's moment. Random convex polygons on every face
// (placements within 5 % of the face's width of the balance are left out), placed at rest,
// friction 1 (the pivot then holds: μ above e h / (k² + h²) for all of these).
TEST_CASE("a convex polygon lying on a face stands iff its centroid is above that face",
          "[tipping][polygon]") {
  std::mt19937 random(42);
  for (int polygon = 0; polygon < 24; ++polygon) {
    const Shape shape = randomConvexPolygon(random);
    for (int face = 0; face < int(shape.vertices.size()); ++face) {
      const FacePlacement placement = onFace(shape, face);
      const double width = placement.right - placement.left;
      const double inside = std::min(-placement.left, placement.right);  // < 0: outside
      if (std::abs(inside) < 0.05 * width) continue;
      for (const std::string solver : {"micro", "sequential", "reference", "soft_step"}) {
        Scene scene = lecture::sceneWith(solver, kDt);
        scene.bodies.push_back(lecture::ground(kFriction));
        BodyDef body;
        body.shape = shape;
        body.angle = placement.angle;
        body.position = Vec2(0.0, placement.height);
        body.friction = kFriction;
        scene.bodies.push_back(body);
        auto world = buildWorld(scene);
        while (world->stepCount() * kDt < 2.0) world->step();
        const double turned = std::abs(world->bodies()[1].angle - placement.angle);
        INFO(solver << ", polygon " << polygon << ", face " << face << ": centroid "
                    << inside / width << " of the face's width inside it; turned " << turned
                    << " rad in 2 s");
        if (inside > 0.0) {
          CHECK(turned < 1e-3);
        } else {
          CHECK(turned > 0.1);
        }
      }
    }
  }
}
