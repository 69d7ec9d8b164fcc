// The global reference: the Delassus matrix, exact reaction forces in a resting stack, Coulomb's
// limit on a slope, and failures that are reported rather than returned.
#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>

#include <Eigen/Eigenvalues>

#include "impulse2d/solvers/contact_math.h"
#include "impulse2d/solvers/reference_solver.h"
#include "impulse2d/world.h"
#include "solver_scenes.h"

using namespace impulse2d;
using namespace solvers;

namespace {

/// N. Sum over a manifold's points of normal (or tangent) impulse, over dt.
double manifoldForce(const World& world, int index, bool tangent) {
  const Manifold& manifold = world.manifolds()[static_cast<size_t>(index)];
  double impulse = 0.0;
  for (int i = 0; i < manifold.pointCount; ++i) {
    impulse += tangent ? manifold.points[i].tangentImpulse : manifold.points[i].normalImpulse;
  }
  return impulse / world.settings().dt;
}

std::unique_ptr<World> boxOnSlope(double angle, double friction) {
  Scene scene = lecture::sceneWith("reference", kDt);
  scene.bodies.push_back(lecture::ground(friction, angle));
  scene.bodies.push_back(lecture::boxOnSlope(Vec2(1.0, 1.0), angle, friction));
  return buildWorld(scene);
}

ReferenceSolver& referenceOf(World& world) {
  return dynamic_cast<ReferenceSolver&>(world.solver());
}

}  // namespace

TEST_CASE("10-box stack: the reference's contact forces are the weights above, to 1e-6",
          "[reference][stack][force]") {
  constexpr int kBoxes = 10;
  auto world = buildWorld(stackScene("reference", kBoxes, 0.6));
  for (int step = 0; step < stepsIn(2.0); ++step) {
    world->step();
    const SolveReport report = world->solver().lastReport();
    REQUIRE(report.converged);
    REQUIRE(report.residual <= ReferenceSolverSettings{}.residualTolerance);
    for (int level = 0; level < kBoxes; ++level) {
      const double weightAbove = (kBoxes - level) * kBoxMass * kGravity;
      INFO("level " << level << ", step " << step);
      CHECK(contactForce(*world, level, level + 1) == Approx(weightAbove).epsilon(1e-6));
    }
  }
}

TEST_CASE(
    "the Delassus matrix is symmetric, positive semi-definite, with the unit-impulse "
    "responses on its diagonal",
    "[reference][delassus]") {
  auto world = buildWorld(pyramidScene("reference", 3, 0.6));
  world->step();
  const Eigen::MatrixXd w(referenceOf(*world).delassusMatrix());
  REQUIRE(w.rows() == 2 * contactPointCount(*world));
  CHECK((w - w.transpose()).cwiseAbs().maxCoeff() < 1e-12);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(w);
  CHECK(eigen.eigenvalues().minCoeff() > -1e-12);
  int row = 0;
  for (const Manifold& manifold : world->manifolds()) {
    const Body& a = world->bodies()[static_cast<size_t>(manifold.bodyA)];
    const Body& b = world->bodies()[static_cast<size_t>(manifold.bodyB)];
    for (int i = 0; i < manifold.pointCount; ++i, row += 2) {
      const Vec2& point = manifold.points[i].point;
      CHECK(w(row, row) == Approx(unitImpulseResponse(a, b, point, manifold.normal)));
      CHECK(w(row + 1, row + 1) == Approx(unitImpulseResponse(a, b, point, manifold.tangent())));
    }
  }
}

TEST_CASE("each Delassus column is what a unit impulse at its point does to every point",
          "[reference][delassus][probe]") {
  auto world = buildWorld(pyramidScene("reference", 3, 0.6));
  world->step();
  const Eigen::MatrixXd w(referenceOf(*world).delassusMatrix());
  // Every point's (vn, vt), in the matrix's order.
  const auto velocities = [&](const std::vector<Body>& bodies) {
    std::vector<double> v;
    for (const Manifold& m : world->manifolds()) {
      const Body& a = bodies[static_cast<size_t>(m.bodyA)];
      const Body& b = bodies[static_cast<size_t>(m.bodyB)];
      for (int i = 0; i < m.pointCount; ++i) {
        v.push_back(relativeVelocity(a, b, m.points[i].point, m.normal));
        v.push_back(relativeVelocity(a, b, m.points[i].point, m.tangent()));
      }
    }
    return v;
  };
  const std::vector<double> before = velocities(world->bodies());
  int column = 0;
  for (const Manifold& manifold : world->manifolds()) {
    for (int i = 0; i < manifold.pointCount; ++i) {
      for (int axis = 0; axis < 2; ++axis, ++column) {
        std::vector<Body> probed = world->bodies();
        applyContactImpulse(probed, manifold, i, axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0);
        const std::vector<double> after = velocities(probed);
        for (int row = 0; row < w.rows(); ++row) {
          INFO("row " << row << ", column " << column);
          CHECK(after[static_cast<size_t>(row)] - before[static_cast<size_t>(row)] ==
                Approx(w(row, column)).margin(1e-12));
        }
      }
    }
  }
}

TEST_CASE("on a slope the reference gives N = m g cos θ, and friction m g sin θ or μN",
          "[reference][friction]") {
  constexpr double kFriction = 0.4;
  for (double angle : {0.2, 0.6}) {
    auto world = boxOnSlope(angle, kFriction);
    runSteps(*world, 10);
    const double mass = world->bodies()[1].mass;
    const double normal = manifoldForce(*world, 0, false);
    const double friction = std::abs(manifoldForce(*world, 0, true));
    INFO("slope " << angle);
    CHECK(normal == Approx(mass * lecture::kGravity * std::cos(angle)).epsilon(1e-9));
    if (std::tan(angle) < kFriction) {
      CHECK(friction == Approx(mass * lecture::kGravity * std::sin(angle)).epsilon(1e-9));
    } else {
      CHECK(friction == Approx(kFriction * normal).epsilon(1e-9));
      CHECK(world->manifolds()[0].points[0].friction == FrictionState::Dynamic);
    }
  }
}

TEST_CASE("a solve that cannot finish is reported and thrown, never returned half done",
          "[reference][failure]") {
  Scene scene = stackScene("reference", 5, 0.6);
  scene.solverSettings.reference.lemke.maxPivots = 2;
  scene.solverSettings.reference.activeSet.maxFactorizations = 0;  // Lemke's fallback
  auto world = buildWorld(scene);
  CHECK_THROWS_WITH(world->step(), Catch::Contains("pivot limit"));
  CHECK_FALSE(world->solver().lastReport().converged);
}

TEST_CASE("a tolerance the answer cannot meet is reported", "[reference][failure]") {
  Scene scene = stackScene("reference", 5, 0.6);
  scene.solverSettings.reference.residualTolerance = -1.0;
  auto world = buildWorld(scene);
  CHECK_THROWS_WITH(world->step(), Catch::Contains("exceeds the tolerance"));
  CHECK_FALSE(world->solver().lastReport().converged);
}

TEST_CASE(
    "a 1×1 box at 30° dropped from 2 m onto a μ 0.5 floor lands on its corner and settles under "
    "the "
    "reference",
    "[reference][residual]") {
  constexpr double kFriction = 0.5;
  Scene scene = lecture::sceneWith("reference", kDt);
  scene.bodies.push_back(lecture::ground(kFriction));
  BodyDef box = lecture::boxOnSlope(Vec2(1.0, 1.0), 0.0, kFriction);
  box.position = Vec2(0.0, 2.0);
  box.angle = std::acos(-1.0) / 6.0;  // 30°
  scene.bodies.push_back(box);
  auto world = buildWorld(scene);
  for (int step = 0; step < stepsIn(3.0); ++step) {
    INFO("step " << step);
    REQUIRE_NOTHROW(world->step());
    REQUIRE(world->solver().lastReport().residual <= ReferenceSolverSettings{}.residualTolerance);
  }
  // At rest on a face: the floor carries the weight.
  CHECK(manifoldForce(*world, 0, false) ==
        Approx(world->bodies()[1].mass * lecture::kGravity).epsilon(1e-6));
}

TEST_CASE(
    "a row of 5 touching elastic frictionless balls, the first struck to 2 m/s, keeps its "
    "momentum under the reference",
    "[reference][residual]") {
  constexpr int kBalls = 5;
  constexpr double kRadius = 0.5;
  constexpr double kSpeed = 2.0;
  Scene scene = lecture::sceneWith("reference", kDt);
  scene.world.gravity = Vec2::Zero();
  for (int i = 0; i < kBalls; ++i) {
    BodyDef ball;
    ball.shape = makeCircle(kRadius);
    ball.friction = 0.0;
    ball.restitution = 1.0;
    ball.position = Vec2(2.0 * kRadius * i, kRadius);  // touching; ball 0 is struck
    ball.velocity = Vec2(i == 0 ? kSpeed : 0.0, 0.0);
    scene.bodies.push_back(ball);
  }
  auto world = buildWorld(scene);
  for (int step = 0; step < 30; ++step) {
    INFO("step " << step);
    REQUIRE_NOTHROW(world->step());
    REQUIRE(world->solver().lastReport().residual <= ReferenceSolverSettings{}.residualTolerance);
  }
  // Momentum is conserved exactly by equal and opposite impulses.
  double momentum = 0.0;
  for (const Body& ball : world->bodies()) momentum += ball.mass * ball.velocity.x();
  CHECK(momentum == Approx(world->bodies()[0].mass * kSpeed).epsilon(1e-9));
}

TEST_CASE("two stacks apart on the ground are two islands, each solved as if alone",
          "[reference][islands]") {
  constexpr int kBoxes = 5;
  Scene one = stackScene("reference", kBoxes, 0.6);
  Scene two = one;
  addStack(two, kBoxes, Vec2(1.0, 1.0), Vec2(5.0, 0.0), 0.0, unitBoxMaterial(0.6));
  auto alone = buildWorld(one);
  auto both = buildWorld(two);
  for (int step = 0; step < 10; ++step) {
    alone->step();
    both->step();
    INFO("step " << step);
    // The ground joins nothing, so the second stack's problem is a copy of the first's.
    CHECK(both->solver().lastReport().iterations == 2 * alone->solver().lastReport().iterations);
    for (int level = 0; level < kBoxes; ++level) {
      const int below = level == 0 ? 0 : kBoxes + level;  // the ground, or the box below
      CHECK(contactForce(*both, below, kBoxes + level + 1) ==
            Approx(contactForce(*alone, level, level + 1)).epsilon(1e-12));
    }
  }
}

TEST_CASE(
    "pyramids landing from 0.2 and 0.5 m: every step solved, then the ground bears the weight",
    "[reference][landing]") {
  // A landing pile is statically indeterminate (a 2-row pyramid's Delassus matrix has rank 9
  // of 20) and its first steps are degenerate: the lexicographic path alone failed both of these.
  // Every step must pass the residual check, and once at rest the ground's reaction must be the
  // pyramid's weight.
  for (const auto& [rows, drop] : {std::pair{2, 0.2}, std::pair{4, 0.5}}) {
    Scene scene = pyramidScene("reference", rows, 0.6);
    for (BodyDef& body : scene.bodies) {
      if (body.type == BodyType::Dynamic) body.position.y() += drop;
    }
    auto world = buildWorld(scene);
    double worstResidual = 0.0;
    for (int step = 0; step < stepsIn(2.0); ++step) {
      REQUIRE_NOTHROW(world->step());
      worstResidual = std::max(worstResidual, world->solver().lastReport().residual);
    }
    double groundForce = 0.0;
    for (size_t m = 0; m < world->manifolds().size(); ++m) {
      const Manifold& manifold = world->manifolds()[m];
      if (manifold.bodyA == 0 || manifold.bodyB == 0) {
        groundForce += manifoldForce(*world, static_cast<int>(m), false);
      }
    }
    const double weight = kGravity * kBoxMass * rows * (rows + 1) / 2.0;
    INFO(rows << " rows from " << drop << " m");
    CHECK(worstResidual <= 1e-9);
    CHECK(groundForce == Approx(weight).epsilon(0.01));
  }
}

TEST_CASE(
    "a box thrown up along a wall stops at the top of its flight without failing the "
    "reference's check, and flies as if the wall were not there",
    "[reference][residual]") {
  // At the top the box's velocity is k·g·dt − k·g·dt: round-off of 1e-16 m/s, so the point on
  // the wall has nothing to cancel but rounding; the residual's scale must not vanish with it
  // (momentumAt: the step's m|a|dt). The wall never pushes: its contact is on a face parallel to
  // the flight, so the box rises and falls as a thrown body.
  constexpr double kDtWall = 0.03333333;  // as a scene file writes 1/30 s
  for (const int stepsToTop : {2, 3, 4}) {
    for (const double overlap : {0.0, 1e-3}) {
      for (const double sideways : {0.0, -1e-16}) {
        Scene scene = lecture::sceneWith("reference", kDtWall);
        BodyDef wall = lecture::ground(0.5);
        wall.shape = makeBox(1.0, 30.0);
        wall.position = Vec2(-6.0, 10.0);
        scene.bodies.push_back(wall);
        BodyDef box = lecture::boxOnSlope(Vec2(1.0, 1.0), 0.0, 0.46);
        box.position = Vec2(-5.0 - overlap, 3.0);
        double upward = 0.0;
        for (int k = 0; k < stepsToTop; ++k) upward += kDtWall * lecture::kGravity;
        box.velocity = Vec2(sideways, upward);
        scene.bodies.push_back(box);
        auto world = buildWorld(scene);
        INFO("steps to the top " << stepsToTop << ", overlap " << overlap << ", sideways "
                                 << sideways);
        for (int step = 0; step < 2 * stepsToTop + 2; ++step) {
          INFO("step " << step);
          REQUIRE_NOTHROW(world->step());
          REQUIRE(world->solver().lastReport().residual <=
                  ReferenceSolverSettings{}.residualTolerance);
        }
        const double flight = (2 * stepsToTop + 2) * kDtWall;
        CHECK(world->bodies()[1].velocity.y() ==
              Approx(upward - lecture::kGravity * flight).margin(1e-9));
      }
    }
  }
}

namespace {

/// A 1 × 0.5 box sliding at 6 m/s down a 30° slope (μ 0.9) into a vertical wall, restitution e.
Scene boxIntoWall(double restitution, bool inTwoSolves) {
  constexpr double kAngle = 30.0 * kPi / 180.0;
  constexpr double kFriction = 0.9;
  Scene scene = lecture::sceneWith("reference", 1.0 / 30.0);
  scene.solverSettings.reference.restitutionInTwoSolves = inTwoSolves;
  scene.bodies.push_back(lecture::ground(kFriction, kAngle));
  BodyDef wall = lecture::ground(kFriction);
  wall.shape = makeBox(1.0, 20.0);
  wall.position = Vec2(-4.0, 5.0);
  scene.bodies.push_back(wall);
  BodyDef box = lecture::boxOnSlope(Vec2(1.0, 0.5), kAngle, kFriction);
  box.position += Vec2(std::cos(kAngle), std::sin(kAngle));  // 1 m up the slope
  box.restitution = restitution;
  box.velocity = 6.0 * lecture::downSlope(kAngle);
  scene.bodies.push_back(box);
  return scene;
}

double mechanicalEnergy(const Body& body) {
  return 0.5 * body.mass * body.velocity.squaredNorm() +
         0.5 * body.inertia * body.angularVelocity * body.angularVelocity +
         body.mass * lecture::kGravity * body.position.y();
}

}  // namespace

TEST_CASE(
    "a box that slides into a wall and bounces while friction holds its face: Newton's bounce "
    "targets have no answer, and the island bounces by Poisson's law in two solves",
    "[reference][restitution]") {
  for (const double restitution : {0.3, 0.8}) {
    INFO("restitution " << restitution);
    // Newton's law alone: every Lemke path ends on a ray at the bounce.
    auto newton = buildWorld(boxIntoWall(restitution, false));
    CHECK_THROWS_AS(runSteps(*newton, 90), ReferenceSolveFailure);
    // In two solves: every step is answered and checked, and the bounce creates no energy.
    auto world = buildWorld(boxIntoWall(restitution, true));
    double largestGain = 0.0;  // relative to the energy before the step
    for (int step = 0; step < 90; ++step) {
      INFO("step " << step);
      const double before = mechanicalEnergy(world->bodies()[2]);
      REQUIRE_NOTHROW(world->step());
      REQUIRE(world->solver().lastReport().residual <= ReferenceSolverSettings{}.residualTolerance);
      const double gain = (mechanicalEnergy(world->bodies()[2]) - before) / std::abs(before);
      largestGain = std::max(largestGain, gain);
    }
    std::cout << "figure: box into a wall, e " << restitution
              << ": largest relative energy gain in a step " << largestGain << "\n";
    // Friction and a bounce with e < 1 only take energy away; 1e-12 is the round-off of a sum of
    // energies of order 10 J.
    CHECK(largestGain <= 1e-12);
  }
}

// Small islands go to Lemke, and Lemke's paths can all end a little short of the tolerance on a
// degenerate one: ten 0.1 m balls in a row on a frictionless floor, struck from touching at
// 0.5 m/s at 240 Hz, stopped the run in step 19 with every path at 1.2e-9 to 3.7e-9. Such an
// island now goes to the active set, as a large island goes to Lemke, and every step is answered
// within the tolerance.
TEST_CASE("a small island that Lemke cannot finish is answered within the tolerance every step",
          "[reference][failure]") {
  constexpr double kRadius = 0.1;
  Scene scene = lecture::sceneWith("reference", 1.0 / 240.0);
  BodyDef floor = lecture::ground(0.0);
  floor.shape = makeBox(100.0, 1.0);
  scene.bodies.push_back(floor);
  BodyDef ball;
  ball.shape = makeCircle(kRadius);
  ball.friction = 0.0;
  ball.restitution = 1.0;
  ball.position = Vec2(-2.0 * kRadius, kRadius);
  ball.velocity = Vec2(0.5, 0.0);
  scene.bodies.push_back(ball);
  ball.velocity = Vec2::Zero();
  for (int k = 0; k < 10; ++k) {
    ball.position = Vec2(2.0 * kRadius * k, kRadius);
    scene.bodies.push_back(ball);
  }
  auto world = buildWorld(scene);
  for (int step = 1; step <= 120; ++step) {
    INFO("step " << step);
    REQUIRE_NOTHROW(world->step());
    CHECK(world->solver().lastReport().residual <= ReferenceSolverSettings{}.residualTolerance);
  }
}
