// Shapes: valid convex polygons only, and mass and inertia from shape and density.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "impulse2d/shape.h"

using namespace impulse2d;

TEST_CASE("a box has mass ρwh and moment of inertia m(w²+h²)/12", "[shape][mass]") {
  const MassProperties box = computeMass(makeBox(2.0, 0.5), 3.0);
  CHECK(box.mass == Approx(3.0 * 2.0 * 0.5).epsilon(1e-14));
  CHECK(box.inertia == Approx(box.mass * (4.0 + 0.25) / 12.0).epsilon(1e-14));
}

TEST_CASE("a circle has mass ρπr² and moment of inertia mr²/2", "[shape][mass]") {
  const MassProperties disk = computeMass(makeCircle(0.5), 2.0);
  CHECK(disk.mass == Approx(2.0 * kPi * 0.25).epsilon(1e-14));
  CHECK(disk.inertia == Approx(0.5 * disk.mass * 0.25).epsilon(1e-14));
}

TEST_CASE("a polygon is moved so its centroid is the origin", "[shape][polygon]") {
  const CentredPolygon triangle = makePolygon({Vec2(0, 0), Vec2(1, 0), Vec2(0.5, 1)});
  CHECK((triangle.centroid - Vec2(0.5, 1.0 / 3.0)).norm() < 1e-14);
  // An isosceles triangle of base b and height h about its centroid: I = m(b²/24 + h²/18).
  const MassProperties mass = computeMass(triangle.shape, 1.0);
  CHECK(mass.mass == Approx(0.5).epsilon(1e-14));
  CHECK(mass.inertia == Approx(0.5 * (1.0 / 24.0 + 1.0 / 18.0)).epsilon(1e-12));
}

TEST_CASE("clockwise vertices are accepted and turned counter-clockwise", "[shape][polygon]") {
  const CentredPolygon square = makePolygon({Vec2(0, 0), Vec2(0, 1), Vec2(1, 1), Vec2(1, 0)});
  const auto& v = square.shape.vertices;
  for (size_t i = 0; i < v.size(); ++i) CHECK(cross(v[i], v[(i + 1) % v.size()]) > 0.0);
  for (size_t i = 0; i < v.size(); ++i) {
    CHECK(square.shape.normals[i].dot(v[i]) > 0.0);  // outward
    CHECK(square.shape.normals[i].norm() == Approx(1.0).epsilon(1e-15));
  }
}

TEST_CASE("polygons that cannot be simulated are rejected with the reason", "[shape][invalid]") {
  using Catch::Matchers::Contains;
  CHECK_THROWS_WITH(makePolygon({Vec2(0, 0), Vec2(1, 0)}), Contains("at least 3"));
  CHECK_THROWS_WITH(makePolygon({Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(0, 1)}),
                    Contains("repeats"));
  CHECK_THROWS_WITH(makePolygon({Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), Vec2(1, 1)}),
                    Contains("collinear"));
  CHECK_THROWS_WITH(makePolygon({Vec2(0, 0), Vec2(1, 0), Vec2(2, 0)}), Contains("zero area"));
  CHECK_THROWS_WITH(makePolygon({Vec2(0, 0), Vec2(2, 0), Vec2(2, 2), Vec2(1, 0.5), Vec2(0, 2)}),
                    Contains("not convex at vertex 3"));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(makePolygon({Vec2(0, 0), Vec2(1, 0), Vec2(nan, 1)}), Contains("not finite"));
  CHECK_THROWS_AS(makeCircle(0.0), ShapeError);
  CHECK_THROWS_AS(makeCircle(std::numeric_limits<double>::infinity()), ShapeError);
  CHECK_THROWS_AS(makeBox(1.0, -1.0), ShapeError);
}
