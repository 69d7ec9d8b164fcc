// Sequential impulses ("Explaining the rigid body solver"; Box2D-Lite's Arbiter::PreStep and
// Arbiter::ApplyImpulse): every contact point is solved on its own, one after the other, and the
// sweep over all of them is repeated. Each point asks "how big an impulse stops the closing?",
// answered with the impulse per unit of velocity change; friction is the same question along the
// tangent, capped at μ times the normal impulse.
#pragma once

#include <array>
#include <vector>

#include "impulse2d/solver.h"

namespace impulse2d {

class SequentialImpulseSolver : public ContactSolver {
 public:
  explicit SequentialImpulseSolver(const SequentialImpulseSettings& settings)
      : settings_(settings) {}

  std::string name() const override { return "sequential"; }
  void solveVelocities(const StepContext& context) override;
  /// The shared position pass (position_correction.h): moves positions, never velocities.
  void solvePositions(const StepContext& context) override;
  /// iterations: sweeps made; residual: the largest normal impulse change in the last sweep (N s).
  SolveReport lastReport() const override { return report_; }

  const SequentialImpulseSettings& settings() const { return settings_; }

 private:
  /// Per contact point, computed once before the sweeps (Box2D-Lite's PreStep).
  struct PointState {
    int manifold = 0;
    int point = 0;
    double normalMass = 0.0;            ///< impulse per unit of normal velocity change
    double tangentMass = 0.0;           ///< impulse per unit of tangent velocity change
    double targetNormalVelocity = 0.0;  ///< bounce, bias or a gap's allowed approach
  };
  /// Per manifold: its points in states_, and whether its normals are solved as a block.
  struct ManifoldState {
    int manifold = 0;
    int firstPoint = 0;  ///< index of its first point in states_
    int pointCount = 0;
    bool block = false;
    Mat2 normalCoupling = Mat2::Zero();  ///< K, when block
  };
  /// What one point's solve did in a sweep, for the observer.
  struct PointImpulse {
    double desiredChange = 0.0;
    double normalImpulse = 0.0;
    double tangentImpulse = 0.0;
  };

  void prepare(const StepContext& context);
  void addManifoldState(const StepContext& context, int manifold, int firstPoint);
  void warmStart(const StepContext& context) const;
  double solveManifold(const StepContext& context, const ManifoldState& manifold, int sweep) const;
  PointImpulse solveNormal(const StepContext& context, const PointState& state) const;
  void solveNormalsTogether(const StepContext& context, const ManifoldState& manifold,
                            std::array<PointImpulse, 2>& impulses) const;
  double solveFriction(const StepContext& context, const PointState& state,
                       double normalImpulseThisSweep) const;
  double normalImpulseChange(ContactPoint& point, double impulse) const;
  double tangentImpulseChange(ContactPoint& point, double impulse, double friction,
                              double normalImpulseThisSweep) const;
  void updateFrictionStates(const StepContext& context) const;

  SequentialImpulseSettings settings_;
  std::vector<PointState> states_;
  std::vector<ManifoldState> manifoldStates_;
  SolveReport report_;
};

}  // namespace impulse2d
