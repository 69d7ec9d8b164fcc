// Soft step (Box2D v3's solver; Catto's Solver2D "solve_soft_step", docs/soft-step.md): the step
// is cut into substeps, and in each the contacts are soft constraints — a spring and damper of a
// set stiffness (hertz) and damping ratio pushing the overlap out — solved once with that bias
// after the velocities are integrated, then once more without it ("relax") after the positions
// moved. The bodies are integrated here, substep by substep; the overlap in a substep comes from
// how far the bodies moved since the step began, not from a new collision test. A restitution
// pass after the substeps gives the bounce.
#pragma once

#include <array>
#include <vector>

#include "impulse2d/solver.h"
#include "impulse2d/solvers/contact_math.h"
#include "impulse2d/solvers/contact_recycling.h"
#include "impulse2d/solvers/point_memory.h"
#include "impulse2d/solvers/soft_step_settings.h"

namespace impulse2d {

/// The three numbers a soft constraint is solved with in a substep of length h, from its
/// stiffness ω = 2πf and damping ratio ζ (Box2D v3's b2MakeSoft): a1 = 2ζ + hω, a2 = hω·a1,
/// a3 = 1/(1 + a2); biasRate = ω/a1, massScale = a2·a3, impulseScale = a3. The impulse is then
/// −massScale·m·(vn + biasRate·s) − impulseScale·λ: an implicit spring-damper step.
struct Softness {
  double biasRate = 0.0;      ///< 1/s: the velocity asked per metre of overlap
  double massScale = 1.0;     ///< fraction of the rigid impulse applied
  double impulseScale = 0.0;  ///< fraction of the accumulated impulse given back
};

/// The softness of a spring of `hertz` and `dampingRatio` in a substep h; hertz 0 is no spring
/// (no bias, rigid mass); the rigid limit (hertz → ∞) is rigidSoftness(h).
Softness makeSoftness(double hertz, double dampingRatio, double h);
/// The limit of infinite stiffness: the whole overlap is asked back in one substep.
Softness rigidSoftness(double h);

/// Box2D v3's soft step: substeps of soft contacts, relax, restitution (docs/soft-step.md).
class SoftStepSolver : public ContactSolver {
 public:
  /// A solver with these settings.
  explicit SoftStepSolver(const SoftStepSettings& settings)
      : settings_(settings), recycling_(settings.recycling, settings.roundSurfaces) {}

  std::string name() const override { return "soft_step"; }
  /// Finds the contacts (ahead, recycling what moved little), then the substeps move the bodies:
  /// velocity, warm start, biased solve, positions and relax, then restitution.
  void step(StepStages& stages) override;
  /// iterations: substeps made; residual: the largest normal impulse change in the last relax.
  SolveReport lastReport() const override { return report_; }
  /// How soft step finds its contacts: every contact speculative (settings speculativeContacts,
  /// as Box2D v3), and its contact recycling.
  ContactFinding contactFinding() { return {settings_.speculativeContacts, &recycling_}; }
  /// which manifolds are kept across steps, and how each was found
  const ContactRecycling& recycling() const { return recycling_; }

  /// its settings
  const SoftStepSettings& settings() const { return settings_; }

 private:
  /// What the iterations touch of a body: velocities, inverse masses, and how far it moved since
  /// the step began (deltaAngle's cosine and sine rotate the contact arms).
  struct SubstepBody : SolverBody {
    Vec2 velocityPerSubstep = Vec2::Zero();  ///< (g + F/m)·h
    double angularVelocityPerSubstep = 0.0;  ///< (τ/I)·h
    Vec2 deltaPosition = Vec2::Zero();
    double deltaAngle = 0.0;
    double deltaCos = 1.0;
    double deltaSin = 0.0;
  };
  /// One contact point, prepared once per step (Box2D v3's b2PrepareContactsTask).
  struct ConstraintPoint {
    Vec2 armA = Vec2::Zero();  ///< from A's centre to the contact point, as the point was found
    Vec2 armB = Vec2::Zero();
    /// Separation minus (armB − armA)·n: adding (cB + rB − cA − rA)·n now gives the separation.
    double baseSeparation = 0.0;
    /// The torque arms rA × n, rB × n, rA × t, rB × t, for the solves (fixed, as the arms are).
    double normalArmA = 0.0;
    double normalArmB = 0.0;
    double tangentArmA = 0.0;
    double tangentArmB = 0.0;
    double normalMass = 0.0;
    double tangentMass = 0.0;
    double normalImpulse = 0.0;
    double tangentImpulse = 0.0;
    double totalNormalImpulse = 0.0;   ///< all normal impulse applied this step: did it touch?
    double totalTangentImpulse = 0.0;  ///< all friction impulse applied this step
    double relativeVelocity = 0.0;     ///< vn before the step, for restitution
    double wantedImpulse = 0.0;        ///< the last normal solve's impulse before clamping
  };
  struct Constraint : SolverManifold {
    /// The arms that turn with their bodies within the step: not a circle's (roundSurfaces).
    bool turnArmA = true;
    bool turnArmB = true;
    /// Normal and arms taken from where round surfaces will touch (speculativeAtTouch).
    bool atTouch = false;
    Softness softness;  ///< the spring of its points
    std::array<ConstraintPoint, 2> points;
  };
  /// A point's normal and friction impulses.
  struct PointImpulses {
    double normal = 0.0;   ///< N s
    double tangent = 0.0;  ///< N s
  };
  /// What a point keeps from one step to the next: the impulses its last substep held, which warm
  /// start every substep of the next step (v3's `normalImpulse`; the step's totals, which every
  /// method reports in ContactPoint, are v3's `totalNormalImpulse`). They differ in a step with an
  /// impact, whose impulse the first substep spends.
  using LastSubstepImpulses = PointImpulses;
  /// A traced bounce's start, per point: the step's impulses so far, and the velocity change
  /// along the normal that leaves it separating at −e times its closing speed before the step.
  struct BounceStart {
    std::array<PointImpulses, 2> totals;
    std::array<double, 2> wantedChange{};
  };
  /// What a point's normal row asks in this sweep: its bias velocity and its softness.
  struct NormalRow {
    double bias = 0.0;
    double massScale = 1.0;
    double impulseScale = 0.0;
  };

  /// The substeps, restitution and the impulses stored; moves the bodies.
  void solveSubsteps(const StepContext& context);
  void prepareBodies(const StepContext& context, double h);
  void prepareConstraints(const StepContext& context, double h);
  void placePoint(const Manifold& manifold, const ContactPoint& point, const FoundPoint& found,
                  const Body& bodyA, const Body& bodyB, const LastSubstepImpulses& warmStart,
                  ConstraintPoint& cp) const;
  void placeAtTouch(const StepContext& context, Constraint& constraint) const;
  void prepareMasses(Constraint& constraint) const;
  Softness contactSoftness(double hertz, double h) const;
  void integrateVelocities();
  void warmStart();
  double solve(const StepContext& context, bool useBias, int substep);
  void reportPoints(const StepContext& context, const Constraint& constraint,
                    const std::array<PointImpulses, 2>& before, int substep, bool useBias);
  void reportVelocitiesChanged(const StepContext& context);
  void updateTracedState(const StepContext& context);
  static void moveBody(const SubstepBody& moved, Body& body);
  static std::array<PointImpulses, 2> impulsesOf(const Constraint& constraint);
  static void storeVelocities(const SolverBody& solved, SubstepBody& body);
  double solveNormals(Constraint& constraint, const SubstepBody& movedA, const SubstepBody& movedB,
                      SolverBody& a, SolverBody& b, bool useBias);
  NormalRow normalRow(const Constraint& constraint, const ConstraintPoint& cp, const SubstepBody& a,
                      const SubstepBody& b, bool useBias) const;
  void solveFriction(Constraint& constraint, SolverBody& a, SolverBody& b) const;
  void integratePositions(double h);
  void applyRestitution(const StepContext& context);
  BounceStart bounceStart(const Constraint& constraint, const SubstepBody& a,
                          const SubstepBody& b) const;
  void reportBounce(const StepContext& context, const Constraint& constraint,
                    const BounceStart& start);
  bool bounces(const ConstraintPoint& cp) const;
  double bounceBase(const ConstraintPoint& cp) const;
  void setBounceImpulse(const Constraint& constraint, ConstraintPoint& cp, SubstepBody& a,
                        SubstepBody& b, double after) const;
  bool applyPairRestitution(Constraint& constraint, SubstepBody& a, SubstepBody& b) const;
  bool applyPointRestitution(Constraint& constraint, SubstepBody& a, SubstepBody& b) const;
  void storeImpulses(const StepContext& context);
  void writeTotals(const StepContext& context) const;
  void finishBodies(const StepContext& context, double h) const;

  SoftStepSettings settings_;
  ContactRecycling recycling_;
  std::vector<SubstepBody> bodies_;
  std::vector<Constraint> constraints_;
  PointMemory<LastSubstepImpulses> lastSubstep_;
  /// A traced step's copies of the world's bodies, moved as far as the substeps have moved them.
  std::vector<Body> tracedBodies_;
  double inverseSubstep_ = 0.0;
  double pushVelocity_ = 0.0;
  SolveReport report_;
};

}  // namespace impulse2d
