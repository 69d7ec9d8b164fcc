// The global reference: every contact point of the step in one linear complementarity problem,
// normal and friction impulses together, solved exactly by Lemke's method (lcp.h). This is the
// "global approach" lecture 3.6 names and does not build: its impulses are the reaction forces
// (× dt) of a resting scene, the accuracy reference for the cheaper methods.
//
// THE PROBLEM, per contact point i (v = velocities after the impulses, W the Delassus matrix):
//   λn ≥ 0,  vn − target ≥ 0,  λn·(vn − target) = 0     no pull, no overlap velocity
//   |λt| ≤ μλn, and if the point slides, λt = −μλn·sign(vt)  Coulomb (in 2D the cone is exact)
// With λt = λt⁺ − λt⁻ and β (the sliding speed) the Coulomb conditions become complementarity
// rows too (Stewart–Trinkle): vt + β ⟂ λt⁺, −vt + β ⟂ λt⁻, μλn − λt⁺ − λt⁻ ⟂ β.
//
// HOW IT SCALES: points couple only through the dynamic bodies they share, so W = J M⁻¹ Jᵀ is
// sparse and the problem splits into islands (static bodies join nothing). An island of up to
// lemkeIslandPoints points is solved by Lemke on its dense LCP (points³, exact, cheap when
// small); a larger one by the active set (active_set.h: sparse factorizations of W on the touching
// rows, started from last step's states), with Lemke as the fallback while the island is not too
// big; a small island that Lemke cannot finish goes to the active set in turn. Lemke is tried
// along several paths (a perturbed q, Harris's ratio test, other covering vectors) until one
// passes. Every answer is checked against the physical conditions before it is used. The targets
// carry no penetration bias (the position pass removes overlap): a biased pile can pose a problem
// with no exact answer (docs/global-reference.md).
#pragma once

#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "impulse2d/solver.h"
#include "impulse2d/solvers/active_set.h"
#include "impulse2d/solvers/lcp.h"
#include "impulse2d/solvers/point_memory.h"
#include "impulse2d/solvers/reference_solver_settings.h"

namespace impulse2d {

/// The reference found no exact answer for a step (every path failed, or the answer's residual
/// exceeds the tolerance). Its message starts "reference solver: " and says why.
class ReferenceSolveFailure : public std::runtime_error {
 public:
  /// A failure for `reason`.
  explicit ReferenceSolveFailure(const std::string& reason)
      : std::runtime_error("reference solver: " + reason) {}
};

/// All contact impulses solved together as one LCP: the accuracy reference.
class ReferenceSolver : public ContactSolver {
 public:
  /// A reference with these settings.
  explicit ReferenceSolver(const ReferenceSolverSettings& settings) : settings_(settings) {}

  std::string name() const override { return "reference"; }
  /// Builds and solves the step's LCP and applies its impulses. Throws ReferenceSolveFailure (after
  /// setting lastReport().converged = false) when Lemke fails or the residual exceeds the
  /// tolerance: never a silent half answer.
  void solveVelocities(const StepContext& context);
  /// The same position pass as sequential impulses (position_correction.h).
  void solvePositions(const StepContext& context);
  /// Finds the contacts, integrates the velocities, solves them exactly, moves the bodies, runs
  /// the position pass.
  void step(StepStages& stages) override;
  /// iterations: Lemke pivots plus active-set factorizations; residual: the worst violated
  /// condition in N s, relative to the step's impulse scale (the largest of the impulses, each
  /// point's cancelling impulses and the momenta of the bodies in contact).
  SolveReport lastReport() const override { return report_; }

  /// The step's exact impulses (λn, λt) per point, interleaved in the order of the manifolds and
  /// their points, without applying them; throws like solveVelocities. Empty when nothing touches.
  Eigen::VectorXd exactImpulses(const StepContext& context);
  /// The worst violated physical condition of `impulses` (same layout) on the last solve's
  /// problem, relative to its impulse scale: what lastReport().residual is for the exact answer.
  double residual(const Eigen::VectorXd& impulses) const;

  /// The Delassus matrix of the last solve: rows/columns 2i (normal) and 2i+1 (tangent) of point
  /// i, in the order of the manifolds and their points; entry (r, c) is the relative velocity
  /// change along r from a unit impulse along c. Sparse: zero between points that share no
  /// dynamic body. Formed on request: the solve itself forms only small islands' blocks.
  Eigen::SparseMatrix<double> delassusMatrix() const;

  /// its settings
  const ReferenceSolverSettings& settings() const { return settings_; }

 private:
  /// One contact point as the global system sees it.
  struct PointRow {
    int manifold = 0;
    int point = 0;
    double friction = 0.0;
    double targetNormalVelocity = 0.0;
    double inelasticTarget = 0.0;  ///< the target without a bounce (restitutionInTwoSolves)
    double restitution = 0.0;      ///< the manifold's
    double momentum = 0.0;  ///< N s, the larger of its two bodies' momenta seen from the point
                            ///< (momentumAt)
    std::array<int, 2> body{{-1, -1}};  ///< A and B, −1 for a static body
    /// The Jacobian rows (normal, tangent) on A and B: −(d, r×d) and +(d, r×d).
    std::array<std::array<Eigen::Vector3d, 2>, 2> jacobian{};
    Eigen::Vector2d lastImpulse = Eigen::Vector2d::Zero();  ///< kept by feature id
    bool carried = false;  ///< lastImpulse is last step's answer at this point (ContactPoint)
    ContactState lastState = ContactState::Unknown;  ///< kept by feature id
    ContactState state = ContactState::Unknown;      ///< this step's answer's
    /// Its target asks for a bounce (restitution raised it above the inelastic one).
    bool bounces() const { return targetNormalVelocity > inelasticTarget; }
  };

  void collectPoints(const StepContext& context);
  void buildEffectiveMasses(const StepContext& context);
  void buildFreeVelocity(const StepContext& context);
  void groupIslands(const StepContext& context);
  /// largeIslands counts the islands given to the active set so far this step.
  void solveIsland(const StepContext& context, const std::vector<int>& island, int& largeIslands,
                   Eigen::VectorXd& impulses);
  /// One solve of the island's problem as posed; false with the reason if none of the methods
  /// answers it.
  bool solveIslandOnce(const StepContext& context, const std::vector<int>& island,
                       int& largeIslands, Eigen::VectorXd& impulses, std::string& failure);
  void bounceInTwoSolves(const StepContext& context, const std::vector<int>& island,
                         int& largeIslands, Eigen::VectorXd& impulses,
                         const std::string& newtonFailure);
  std::vector<int> inFeatureIdOrder(const StepContext& context,
                                    const std::vector<int>& island) const;
  void islandLcp(const std::vector<int>& island, Eigen::MatrixXd& matrix,
                 Eigen::VectorXd& vector) const;
  LcpSolution solveByLemke(const std::vector<int>& island) const;
  /// The island by the active set; false, with its reason added to `failure`, if it fails.
  bool solveIslandByActiveSet(const StepContext& context, const std::vector<int>& island,
                              KeptFactorization& kept, Eigen::VectorXd& impulses,
                              std::string& failure);
  ActiveSetAnswer solveByActiveSet(const StepContext& context, const std::vector<int>& island,
                                   KeptFactorization& kept);
  static IslandPoint islandPoint(const StepContext& context, const PointRow& row,
                                 std::vector<int>& localBody, std::vector<int>& bodies);
  /// The factorization kept from step to step for the island given to the active set as the
  /// `ordinal`-th large one of the step.
  KeptFactorization& keptFactorization(int ordinal);
  Eigen::SparseMatrix<double> islandDelassus(const std::vector<int>& points) const;
  std::vector<std::vector<std::pair<int, int>>> pointsOfBodies(
      const std::vector<int>& points) const;
  Eigen::VectorXd velocityChange(const std::vector<int>& points,
                                 const Eigen::VectorXd& impulses) const;
  Eigen::VectorXd islandImpulses(const std::vector<int>& island, const Eigen::VectorXd& z) const;
  double residualOver(const std::vector<int>& points, const Eigen::VectorXd& impulses) const;
  double impulseScale(const std::vector<int>& points, const Eigen::VectorXd& impulses) const;
  void applyImpulses(const StepContext& context, const Eigen::VectorXd& impulses);
  void fail(const std::string& reason);

  ReferenceSolverSettings settings_;
  std::vector<PointRow> rows_;
  Eigen::VectorXd inverseMass_;   ///< 3 per body of the step: 1/m, 1/m, 1/I (0 if static)
  Eigen::VectorXd diagonal_;      ///< 2p: the Delassus matrix's diagonal
  Eigen::VectorXd freeVelocity_;  ///< 2p: (vn, vt) of each point before the solve
  /// 2p: impulses applied before the checked solve, the compression and restitution impulses of
  /// an island that bounced in two solves (freeVelocity_ includes what they do); 0 elsewhere.
  Eigen::VectorXd pushed_;
  /// The points of each island: points joined through dynamic bodies.
  std::vector<std::vector<int>> islands_;
  /// The active set's factors of each large island's last system, by the island's ordinal
  /// among the large islands of the step (a changed island is found out by its size or by
  /// refinement failing, and factorized anew).
  std::vector<std::unique_ptr<KeptFactorization>> keptFactors_;
  /// Each point's state in the last answer, which the next step's active set starts from: a
  /// resting pile poses the system it solved last step.
  PointMemory<ContactState> lastStates_;
  SolveReport report_;
};

}  // namespace impulse2d
