// Lemke's method against small linear complementarity problems whose answers are known.
#include <random>

#include <catch2/catch.hpp>

#include "impulse2d/solvers/lcp.h"

using impulse2d::LemkePath;
using impulse2d::LemkeSettings;
using impulse2d::naturalResidual;
using impulse2d::RatioTest;
using impulse2d::solveLemke;

namespace {

/// Round-off of a few pivots on entries of order 1.
constexpr double kExact = 1e-12;

}  // namespace

TEST_CASE("a non-negative q needs no impulse: z = 0, w = q", "[lcp][lemke]") {
  Eigen::MatrixXd m(2, 2);
  m << 2.0, 1.0, 1.0, 2.0;
  const Eigen::VectorXd q = Eigen::Vector2d(1.0, 0.0);
  const auto solution = solveLemke(m, q, LemkeSettings{});
  REQUIRE(solution.solved);
  CHECK(solution.z.norm() == 0.0);
  CHECK(solution.pivots == 0);
}

TEST_CASE("one active row: z = (1, 0), w = (0, 2) for M = I, q = (-1, 2)", "[lcp][lemke]") {
  const Eigen::MatrixXd m = Eigen::MatrixXd::Identity(2, 2);
  const Eigen::VectorXd q = Eigen::Vector2d(-1.0, 2.0);
  const auto solution = solveLemke(m, q, LemkeSettings{});
  REQUIRE(solution.solved);
  CHECK(solution.z(0) == Approx(1.0).margin(kExact));
  CHECK(solution.z(1) == Approx(0.0).margin(kExact));
  CHECK(solution.w(1) == Approx(2.0).margin(kExact));
}

TEST_CASE("both rows active: the linear system 2a + b = 5, a + 2b = 6", "[lcp][lemke]") {
  Eigen::MatrixXd m(2, 2);
  m << 2.0, 1.0, 1.0, 2.0;
  const Eigen::VectorXd q = Eigen::Vector2d(-5.0, -6.0);
  const auto solution = solveLemke(m, q, LemkeSettings{});
  REQUIRE(solution.solved);
  CHECK(solution.z(0) == Approx(4.0 / 3.0).margin(kExact));
  CHECK(solution.z(1) == Approx(7.0 / 3.0).margin(kExact));
  CHECK(solution.w.cwiseAbs().maxCoeff() < kExact);
}

TEST_CASE("Murty's 4×4 example: z = (2, 1, 3, 1), w = 0", "[lcp][lemke]") {
  Eigen::MatrixXd m(4, 4);
  m << 1, -1, -1, -1, -1, 1, -1, -1, 1, 1, 2, 0, 1, 1, 0, 2;
  Eigen::VectorXd q(4);
  q << 3, 5, -9, -5;
  const auto solution = solveLemke(m, q, LemkeSettings{});
  REQUIRE(solution.solved);
  Eigen::VectorXd expected(4);
  expected << 2, 1, 3, 1;
  CHECK((solution.z - expected).cwiseAbs().maxCoeff() < kExact);
}

TEST_CASE("a singular, degenerate problem (two points of one contact) is solved",
          "[lcp][lemke][degenerate]") {
  // Two contact points that see the same unit response: only their sum z0 + z1 = 1 is fixed.
  Eigen::MatrixXd m(2, 2);
  m << 1.0, 1.0, 1.0, 1.0;
  const Eigen::VectorXd q = Eigen::Vector2d(-1.0, -1.0);
  const auto solution = solveLemke(m, q, LemkeSettings{});
  REQUIRE(solution.solved);
  CHECK(solution.z.sum() == Approx(1.0).margin(kExact));
  CHECK(naturalResidual(m, q, solution.z) < kExact);
}

TEST_CASE("random singular positive semi-definite problems with a solution are solved",
          "[lcp][lemke]") {
  // q is built from a known complementary pair (z*, w*), so a solution exists; for a positive
  // semi-definite M Lemke's method must then find one (not necessarily z*, M being singular).
  std::mt19937 random(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::bernoulli_distribution active(0.5);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 4 + trial;
    const Eigen::MatrixXd a =
        Eigen::MatrixXd::NullaryExpr(n, n / 2, [&] { return normal(random); });
    const Eigen::MatrixXd m = a * a.transpose();  // rank n/2: singular, like a contact system
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd w = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < n; ++i) (active(random) ? z(i) : w(i)) = std::abs(normal(random));
    const Eigen::VectorXd q = w - m * z;
    const auto solution = solveLemke(m, q, LemkeSettings{});
    INFO("trial " << trial << ": " << solution.failure);
    REQUIRE(solution.solved);
    CHECK(naturalResidual(m, q, solution.z) < 1e-10 * (1.0 + solution.z.cwiseAbs().maxCoeff()));
  }
}

TEST_CASE("every path — Harris's ratio test, other covering vectors — reaches a solution",
          "[lcp][lemke]") {
  // The same kind of problems as above: each path is another route to the solutions of a
  // positive semi-definite problem, so each must end at one.
  std::mt19937 random(11);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> cover(0.5, 2.0);
  std::bernoulli_distribution active(0.5);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 4 + trial;
    const Eigen::MatrixXd a =
        Eigen::MatrixXd::NullaryExpr(n, n / 2, [&] { return normal(random); });
    const Eigen::MatrixXd m = a * a.transpose();
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd w = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < n; ++i) (active(random) ? z(i) : w(i)) = std::abs(normal(random));
    const Eigen::VectorXd q = w - m * z;
    const Eigen::VectorXd covering = Eigen::VectorXd::NullaryExpr(n, [&] { return cover(random); });
    for (const LemkePath& path :
         {LemkePath{Eigen::VectorXd::Ones(n), RatioTest::Harris},
          LemkePath{covering, RatioTest::Lexicographic}, LemkePath{covering, RatioTest::Harris}}) {
      const auto solution = solveLemke(m, q, path, LemkeSettings{});
      INFO("trial " << trial << ": " << solution.failure);
      REQUIRE(solution.solved);
      CHECK(naturalResidual(m, q, solution.z) < 1e-10 * (1.0 + solution.z.cwiseAbs().maxCoeff()));
    }
  }
}

TEST_CASE("an infeasible problem ends on a ray and says so", "[lcp][lemke][failure]") {
  const Eigen::MatrixXd m = -Eigen::MatrixXd::Identity(1, 1);  // w = −z − 1 < 0 for all z ≥ 0
  const Eigen::VectorXd q = Eigen::VectorXd::Constant(1, -1.0);
  const auto solution = solveLemke(m, q, LemkeSettings{});
  CHECK_FALSE(solution.solved);
  CHECK_THAT(solution.failure, Catch::Contains("ray"));
}

TEST_CASE("the pivot limit is reported, not a half answer", "[lcp][lemke][failure]") {
  Eigen::MatrixXd m(4, 4);
  m << 1, -1, -1, -1, -1, 1, -1, -1, 1, 1, 2, 0, 1, 1, 0, 2;
  Eigen::VectorXd q(4);
  q << 3, 5, -9, -5;
  LemkeSettings options;
  options.maxPivots = 2;
  const auto solution = solveLemke(m, q, options);
  CHECK_FALSE(solution.solved);
  CHECK_THAT(solution.failure, Catch::Contains("pivot limit"));
}
