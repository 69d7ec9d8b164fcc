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

/// The velocity change of `body` along `measureDirection` at `measurePoint` that a unit impulse
/// along `impulseDirection` at `impulsePoint` causes: d·d'/m + (r×d)(r'×d')/I. The building block
/// of the unit-impulse probe (one point) and of the reference's Delassus matrix (two points).
double velocityPerUnitImpulse(const Body& body, const Vec2& impulsePoint,
                              const Vec2& impulseDirection, const Vec2& measurePoint,
                              const Vec2& measureDirection);

/// The text's unit-impulse probe in closed form: how much the relative velocity along `direction`
/// at `point` changes when an impulse of 1 N s acts there (+direction on B, −direction on A):
/// 1/m_A + 1/m_B + (r_A×d)²/I_A + (r_B×d)²/I_B. Its inverse is the impulse per unit of velocity
/// change: the normal (or tangent) mass.
double unitImpulseResponse(const Body& a, const Body& b, const Vec2& point, const Vec2& direction);

/// The relative velocity (B's material minus A's) at `point`, along `direction`: vn on the
/// normal (< 0 closing), vt on the tangent.
double relativeVelocity(const Body& a, const Body& b, const Vec2& point, const Vec2& direction);

/// The rules that set the separating velocity a contact point should have after the solve.
struct TargetVelocityRules {
  bool penetrationBias = false;
  double biasFactor = 0.0;                    ///< fraction of (penetration − slop) per step
  double allowedPenetration = 0.0;            ///< m, the slop the bias leaves alone
  double maxBiasVelocity = 0.0;               ///< m/s
  double restitutionVelocityThreshold = 0.0;  ///< m/s, no bounce below this closing speed
};

/// The target separating velocity of one point, from its closing velocity before the solve:
/// - touching (penetration ≥ 0): the penetration bias min(β·(d − slop)/dt, cap), or 0;
/// - a gap (penetration < 0, speculative): −gap/dt, the approach that just closes it;
/// - a bounce −e·vn, when the closing speed exceeds the threshold and the gap closes within the
///   step, replaces either if larger. The bias never enters the bounce: a deep contact does not
///   bounce harder, and a bounce is not scaled by the penetration.
double targetSeparatingVelocity(double normalVelocityBefore, double penetration, double restitution,
                                double dt, const TargetVelocityRules& rules);

/// The normal coupling matrix K of two contact points on the same normal: entry (i, j) is the
/// change of point i's normal velocity per unit normal impulse at point j. Symmetric; its diagonal
/// is the unit-impulse response of each point.
Mat2 normalCouplingMatrix(const Body& a, const Body& b, const Vec2& normal, const Vec2& point0,
                          const Vec2& point1);

/// Whether K may be solved as a block: k₀₀² < conditionLimit · det K (Box2D's test). Two points
/// that act almost alike (a narrow contact) make K nearly singular; they are then solved apart.
bool isWellConditioned(const Mat2& k, double conditionLimit);

/// The 2×2 linear complementarity problem of a two-point manifold: x ≥ 0, w = K x + q ≥ 0 and
/// xᵢwᵢ = 0, solved exactly by trying its four cases in turn — both points push, only the first,
/// only the second, neither — as Box2D 2.4's block solver does. K must be well conditioned.
Vec2 solveTwoPointLcp(const Mat2& k, const Vec2& q);

/// Static inside Coulomb's limit |λt| < μλn, Dynamic on it (within `tolerance`, N s), None when
/// the point carries no normal impulse.
FrictionState frictionStateOf(double normalImpulse, double tangentImpulse, double friction,
                              double tolerance);

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

/// Applies the impulse (normal, tangent) of a manifold's point: +P to B, −P to A.
void applyContactImpulse(const StepContext& context, const Manifold& manifold, int point,
                         double normalImpulse, double tangentImpulse);

}  // namespace impulse2d
