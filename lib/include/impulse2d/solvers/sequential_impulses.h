// Sequential impulses ("Explaining the rigid body solver"; Box2D-Lite's Arbiter::PreStep and
// Arbiter::ApplyImpulse): every contact point is solved on its own, one after the other, and the
// sweep over all of them is repeated. Each point asks "how big an impulse stops the closing?",
// answered with the impulse per unit of velocity change; friction is the same question along the
// tangent, capped at μ times the normal impulse. Between sweeps the totals are pushed on along
// the direction the sweeps keep moving them (the conjugate gradient, pushOn), unless the settings
// turn it off.
//
// For speed the sweeps touch only what they need, laid out contiguously: a solver body
// per body (velocity, angular velocity, inverse mass and inertia) and a constraint per contact
// point (arms, masses, target, running totals), all computed once per step before the sweeps and
// written back to the bodies and manifolds after them. The buffers are reused, so a step
// allocates nothing once they have grown.
#pragma once

#include <array>
#include <vector>

#include "impulse2d/solver.h"
#include "impulse2d/solvers/contact_math.h"
#include "impulse2d/solvers/contact_recycling.h"
#include "impulse2d/solvers/sequential_impulse_settings.h"

namespace impulse2d {

/// Sequential impulses with accumulated impulses and warm starting (docs/sequential-impulses.md).
class SequentialImpulseSolver : public ContactSolver {
 public:
  /// A solver with these settings.
  explicit SequentialImpulseSolver(const SequentialImpulseSettings& settings)
      : settings_(settings), recycling_(settings.recycling, kDiscArmsStayAsFound) {}

  std::string name() const override { return "sequential"; }
  /// Finds the contacts, integrates the velocities, sweeps them, moves the bodies, runs the
  /// position pass.
  void step(StepStages& stages) override;
  /// The velocity sweeps.
  void solveVelocities(const StepContext& context);
  /// The shared position pass (position_correction.h): moves positions, never velocities.
  void solvePositions(const StepContext& context);
  /// iterations: sweeps made; residual: the largest impulse change (normal or friction) in the last
  /// sweep (N s).
  SolveReport lastReport() const override { return report_; }

  /// its settings
  const SequentialImpulseSettings& settings() const { return settings_; }

 private:
  /// Whether each contact's running total is clamped (accumulated impulses), not each impulse.
  bool accumulated() const { return settings_.impulses != ImpulseAccumulation::ClampedEach; }
  /// Whether the conjugate gradient pushes between sweeps: it needs totals to clamp.
  bool pushes() const { return settings_.conjugateGradient && accumulated(); }

  /// Per contact point, computed once before the sweeps (Box2D-Lite's PreStep).
  struct PointState {
    /// The arms' torque per unit impulse along the normal and the tangent, r × n and r × t for
    /// A's arm and B's (the arm: the contact point minus the centre of mass). With them the
    /// relative velocity is n·(vB − vA) + ωB (rB × n) − ωA (rA × n), and an impulse λ turns a body
    /// by λ (r × n)/I.
    double normalTorqueArmA = 0.0;
    double normalTorqueArmB = 0.0;
    double tangentTorqueArmA = 0.0;
    double tangentTorqueArmB = 0.0;
    double normalMass = 0.0;            ///< impulse per unit of normal velocity change
    double tangentMass = 0.0;           ///< impulse per unit of tangent velocity change
    double targetNormalVelocity = 0.0;  ///< bounce, bias or a gap's allowed approach
    double normalImpulse = 0.0;         ///< N s, running total (the manifold's, during the solve)
    double tangentImpulse = 0.0;        ///< N s, running total
  };
  /// Per manifold: its bodies and normal, its points in states_, and whether its normals are
  /// solved as a block.
  struct ManifoldState : SolverManifold {
    int firstPoint = 0;  ///< index of its first point in states_
    bool block = false;
    Mat2 normalCoupling = Mat2::Zero();   ///< K, when block
    Mat2 inverseCoupling = Mat2::Zero();  ///< K⁻¹, when block
  };
  /// The two bodies of the contact being solved, copied into locals for its solves and written
  /// back after them: each solve reads the velocities the one before it changed, without a round
  /// trip through memory (Box2D's vA, wA, vB, wB).
  struct BodyPair {
    SolverBody a;
    SolverBody b;
    /// The relative velocity (B's material minus A's) at a point, along `direction`, from the
    /// arms' torques along it (PointState).
    double relativeVelocity(const Vec2& direction, double torqueArmA, double torqueArmB) const {
      return velocityAlong(a, b, direction, torqueArmA, torqueArmB);
    }
    /// +λ·direction to B, −λ·direction to A at a point: Δv = λ·direction/m, Δω = λ (r × d)/I.
    void applyImpulse(const Vec2& direction, double torqueArmA, double torqueArmB, double impulse) {
      applyAlong(a, b, direction, torqueArmA, torqueArmB, impulse);
    }
    double relativeNormalVelocity(const PointState& point, const Vec2& normal) const {
      return relativeVelocity(normal, point.normalTorqueArmA, point.normalTorqueArmB);
    }
    double relativeTangentVelocity(const PointState& point, const Vec2& tangent) const {
      return relativeVelocity(tangent, point.tangentTorqueArmA, point.tangentTorqueArmB);
    }
    void applyNormalImpulse(const PointState& point, const Vec2& normal, double impulse) {
      applyImpulse(normal, point.normalTorqueArmA, point.normalTorqueArmB, impulse);
    }
    void applyTangentImpulse(const PointState& point, const Vec2& tangent, double impulse) {
      applyImpulse(tangent, point.tangentTorqueArmA, point.tangentTorqueArmB, impulse);
    }
  };
  /// What one point's solve did in a sweep, for the observer.
  struct PointImpulse {
    double desiredChange = 0.0;
    double normalImpulse = 0.0;
    double tangentImpulse = 0.0;
  };
  /// Per contact point, the conjugate gradient's record (settings' conjugateGradient): what the
  /// last sweep changed, and the direction the push follows (N s).
  struct PointDirection {
    PointImpulse change;
    double normal = 0.0;
    double tangent = 0.0;
    /// The direction starts again as the last sweep's changes.
    void restartFromChange() {
      normal = change.normalImpulse;
      tangent = change.tangentImpulse;
    }
    /// After a push: the direction is the push plus the last sweep's changes.
    void continueWith(const PointImpulse& pushed) {
      normal = pushed.normalImpulse + change.normalImpulse;
      tangent = pushed.tangentImpulse + change.tangentImpulse;
    }
  };

  void prepare(const StepContext& context);
  void prepareBodies(const StepContext& context);
  void addManifoldState(const StepContext& context, int manifold);
  void warmStart();
  void pushOn(const StepContext& context, int sweep);
  bool converged() const;
  double solveManifold(const StepContext& context, const ManifoldState& manifold, int sweep);
  void solveNormal(const ManifoldState& manifold, PointState& point, BodyPair& bodies,
                   PointImpulse& impulse);
  void solveFrictions(const ManifoldState& manifold, BodyPair& bodies,
                      std::array<PointImpulse, 2>& impulses);
  void solveNormalsTogether(const ManifoldState& manifold, BodyPair& bodies,
                            std::array<PointImpulse, 2>& impulses);
  double solveFriction(const ManifoldState& manifold, PointState& point, BodyPair& bodies,
                       double normalImpulseThisSweep);
  BodyPair loadBodies(const ManifoldState& manifold) const {
    return {solverBodies_[manifold.bodyA], solverBodies_[manifold.bodyB]};
  }
  /// Only the velocities go back: the masses never change within a step.
  void storeBodies(const ManifoldState& manifold, const BodyPair& bodies) {
    storeVelocities(bodies.a, solverBodies_[manifold.bodyA]);
    storeVelocities(bodies.b, solverBodies_[manifold.bodyB]);
  }
  static void storeVelocities(const SolverBody& from, SolverBody& to) {
    to.velocity = from.velocity;
    to.angularVelocity = from.angularVelocity;
  }
  double normalImpulseChange(PointState& point, double impulse) const;
  double tangentImpulseChange(PointState& point, double impulse, double friction,
                              double normalImpulseThisSweep) const;
  void storeResults(const StepContext& context) const;
  void reportPoints(const StepContext& context, const ManifoldState& manifold, int sweep,
                    const std::array<PointImpulse, 2>& impulses, SolverEvent::Phase phase) const;

  /// A kept manifold's arm on a disc stays where it was found while the disc rolls (the
  /// recycling's roundSurfaces): turned with the disc, three piled discs crept 2.2 mm in 2.5 s.
  static constexpr bool kDiscArmsStayAsFound = true;

  SequentialImpulseSettings settings_;
  ContactRecycling recycling_;  ///< which manifolds are kept across steps (settings' recycling)
  std::vector<SolverBody> solverBodies_;
  std::vector<PointState> states_;
  std::vector<ManifoldState> manifoldStates_;
  std::vector<PointDirection> directions_;  ///< one per point of states_, when pushes()
  double sweepChangeSquared_ = 0.0;         ///< (N s)², the sum over this sweep's changes
  double lastChangeSquared_ = 0.0;          ///< (N s)², the same for the sweep before
  SolveReport report_;
};

}  // namespace impulse2d
