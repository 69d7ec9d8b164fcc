// The lecture's method (lecture 3.6, after Millington ch. 14-15): resting contacts as a series of
// micro-collisions, one impulse per contact per update, resolved worst first.
#pragma once

#include <vector>

#include "impulse2d/solver.h"

namespace impulse2d {

/// The 2×2 contact matrix of one contact point: the velocity change (normal, tangent) at the
/// point that a unit impulse (normal, tangent) causes — the planar form of the lecture's
/// skew-symmetric construction, summed over both bodies.
Mat2 contactMatrix(const Body& a, const Body& b, const Vec2& point, const Vec2& normal);

class MicroCollisionSolver : public ContactSolver {
 public:
  explicit MicroCollisionSolver(const MicroCollisionSettings& settings) : settings_(settings) {}

  std::string name() const override { return "micro"; }
  void solveVelocities(const StepContext& context) override;
  void solvePositions(const StepContext& context) override;
  SolveReport lastReport() const override { return report_; }

  const MicroCollisionSettings& settings() const { return settings_; }

 private:
  /// Per contact point: what velocity resolution needs between impulses.
  struct PointState {
    int manifold = 0;
    int point = 0;
    Vec2 armA = Vec2::Zero();  ///< contact point − centre of mass of A
    Vec2 armB = Vec2::Zero();
    Mat2 contactMatrix = Mat2::Zero();
    Mat2 inverseContactMatrix = Mat2::Zero();
    Vec2 contactVelocity = Vec2::Zero();  ///< (normal, tangent) relative velocity now
    double targetNormalVelocity = 0.0;    ///< the bounce: −c·(vs − vacc), taken before the solve
    bool active = false;                  ///< touching, or closing a gap within this step
  };

  void prepare(const StepContext& context);
  double restitutionFor(const Manifold& manifold, const PointState& state) const;
  double desiredVelocityChange(const PointState& state) const;
  int worstVelocityPoint() const;
  Vec2 frictionImpulse(const PointState& state, const Manifold& manifold,
                       FrictionState& friction) const;
  void applyVelocityImpulse(const StepContext& context, int index, int iteration);
  void refreshContactVelocities(const StepContext& context, int bodyIndex);

  int worstPenetration(const StepContext& context) const;
  void resolvePenetration(const StepContext& context, int index, int iteration);
  void movePenetrations(const StepContext& context, int bodyIndex, const Vec2& linearMove,
                        double angularMove);

  MicroCollisionSettings settings_;
  std::vector<PointState> states_;
  SolveReport report_;
};

}  // namespace impulse2d
