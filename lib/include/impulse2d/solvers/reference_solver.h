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
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "impulse2d/solver.h"
#include "impulse2d/solvers/lcp.h"

namespace impulse2d {

class ReferenceSolver : public ContactSolver {
 public:
  explicit ReferenceSolver(const ReferenceSolverSettings& settings) : settings_(settings) {}

  std::string name() const override { return "reference"; }
  /// Builds and solves the step's LCP and applies its impulses. Throws std::runtime_error (after
  /// setting lastReport().converged = false) when Lemke fails or the residual exceeds the
  /// tolerance: never a silent half answer.
  void solveVelocities(const StepContext& context) override;
  /// The same position pass as sequential impulses (position_correction.h).
  void solvePositions(const StepContext& context) override;
  /// iterations: Lemke pivots; residual: the worst violated condition in N s, relative to the
  /// step's impulse scale (the largest of the impulses, each point's cancelling impulses and the
  /// momenta of the bodies in contact).
  SolveReport lastReport() const override { return report_; }

  /// The step's exact impulses (λn, λt) per point, interleaved in the order of the manifolds and
  /// their points, without applying them; throws like solveVelocities. Empty when nothing touches.
  Eigen::VectorXd exactImpulses(const StepContext& context);
  /// The worst violated physical condition of `impulses` (same layout) on the last solve's
  /// problem, relative to its impulse scale: what lastReport().residual is for the exact answer.
  double residual(const Eigen::VectorXd& impulses) const;

  /// The Delassus matrix of the last solve: rows/columns 2i (normal) and 2i+1 (tangent) of point
  /// i, in the order of the manifolds and their points; entry (r, c) is the relative velocity
  /// change along r from a unit impulse along c.
  const Eigen::MatrixXd& delassusMatrix() const { return delassus_; }

  const ReferenceSolverSettings& settings() const { return settings_; }

 private:
  /// One contact point as the global system sees it.
  struct PointRow {
    int manifold = 0;
    int point = 0;
    double friction = 0.0;
    double targetNormalVelocity = 0.0;
    double momentum = 0.0;  ///< N s, the larger of its two bodies' momenta seen from the point
  };

  void collectPoints(const StepContext& context);
  void buildDelassus(const StepContext& context);
  void buildFreeVelocity(const StepContext& context);
  void formulateLcp();
  void groupIslands(const StepContext& context);
  LcpSolution solveLcp() const;
  LcpSolution solveIsland(const Eigen::MatrixXd& matrix, const Eigen::VectorXd& vector) const;
  Eigen::VectorXd contactImpulses(const Eigen::VectorXd& lcpSolution) const;
  double impulseScale(const Eigen::VectorXd& impulses) const;
  void applyImpulses(const StepContext& context, const Eigen::VectorXd& impulses) const;
  void fail(const std::string& reason);

  ReferenceSolverSettings settings_;
  std::vector<PointRow> rows_;
  Eigen::MatrixXd delassus_;      ///< 2p × 2p
  Eigen::VectorXd freeVelocity_;  ///< 2p: (vn, vt) of each point before the solve
  Eigen::MatrixXd lcpMatrix_;     ///< 4p × 4p, variables (λn, λt⁺, λt⁻, β) per point
  Eigen::VectorXd lcpVector_;     ///< 4p
  /// The LCP variables of each island: points joined through dynamic bodies.
  std::vector<std::vector<int>> islands_;
  SolveReport report_;
};

}  // namespace impulse2d
