// The lecture's method (lecture 3.6, after Millington ch. 14-15): resting contacts as a series of
// micro-collisions, one impulse per contact per update, resolved worst first; then penetration
// resolved worst first by moving the bodies apart. Beyond the lecture, each a switch of
// MicroCollisionSettings: per-update impulse totals, warm starting, and a flat contact's two
// points resolved together (pair impulses, pair moves).
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include <Eigen/LU>

#include "impulse2d/solver.h"
#include "impulse2d/solvers/contact_math.h"
#include "impulse2d/solvers/micro_collision_settings.h"
#include "impulse2d/solvers/point_memory.h"
#include "impulse2d/solvers/worst_first_queue.h"

namespace impulse2d {

/// The lecture's micro-collision resolver, worst contact first (docs/micro-collisions.md).
class MicroCollisionSolver : public ContactSolver {
 public:
  /// A resolver with these settings.
  explicit MicroCollisionSolver(const MicroCollisionSettings& settings) : settings_(settings) {}

  std::string name() const override { return "micro"; }
  /// Finds the contacts, integrates the velocities, resolves them, moves the bodies, resolves the
  /// penetration that remains.
  void step(StepStages& stages) override;
  /// The velocity phase: impulses worst first.
  void solveVelocities(const StepContext& context);
  /// The penetration phase: moves worst first.
  void solvePositions(const StepContext& context);
  SolveReport lastReport() const override { return report_; }

  /// its settings
  const MicroCollisionSettings& settings() const { return settings_; }

 private:
  /// The parts of a (normal, tangent) pair: velocities, velocity changes and impulses at a contact.
  static double normalPart(const Vec2& pair) { return pair.x(); }
  static double tangentPart(const Vec2& pair) { return pair.y(); }
  /// Whether an update's impulses at a point add up to one micro-collision (impulse totals).
  bool pointTotals() const { return settings_.impulses >= MicroCollisionImpulses::PointTotals; }

  /// What a penetration move changes of one body: its pose, the rotation as cosine and sine.
  struct Pose {
    Vec2 position = Vec2::Zero();
    double angle = 0.0;
    double cosine = 1.0;
    double sine = 0.0;
    double inverseMass = 0.0;
    double inverseInertia = 0.0;
    bool movable = false;  ///< not static
    bool moved = false;    ///< since the body last got its pose
    /// A circle (its surface does not turn with it, surfaceTurnsWithShape). One line of cache
    /// holds a pose: a circle's radius is the length of its contact anchors, not stored.
    bool round = false;
    Vec2 toWorld(const Vec2& local) const { return position + rotate(cosine, sine, local); }
    /// A contact's anchor on this body now. A polygon's turns with it. A circle's surface under
    /// the contact is the same however the circle turns, so its anchor is its centre plus its
    /// radius (the anchor's length) along `outward` (the normal now on A, its reverse on B), as
    /// Box2D 2.4's position solver keeps a circle's centre. Turned with the circle, the anchor of
    /// a disc rolling at ω rises r(1 − cos ω dt) off the contact within the step (9 mm for
    /// r = 0.25 m at 16 rad/s and 60 Hz), and the overlap of a landing reads as a gap.
    Vec2 anchorNow(const Vec2& anchor, const Vec2& outward) const {
      return round ? Vec2(position + anchor.norm() * outward) : toWorld(anchor);
    }
    void turnBy(double turn) {
      angle += turn;
      cosine = std::cos(angle);
      sine = std::sin(angle);
    }
  };
  /// A contact point in the velocity phase, laid out by use in two cache lines: the first holds
  /// what refreshing its contact velocity reads, the second what its severity and an impulse
  /// read and write; what only an impulse or the penetration phase needs comes after.
  struct alignas(64) PointState {
    int bodyA = 0;
    int bodyB = 0;
    double penetration = 0.0;    ///< m, at the step's start (the penetration phase: MovePoint)
    Vec2 normal = Vec2::Zero();  ///< from A to B
    Vec2 armA = Vec2::Zero();    ///< contact point minus A's centre (fixed while solving)
    Vec2 armB = Vec2::Zero();    ///< contact point minus B's centre
    Vec2 contactVelocity = Vec2::Zero();  ///< (normal, tangent) relative velocity now
    Vec2 totalImpulse = Vec2::Zero();     ///< (normal, tangent) applied here in this update
    double accelerationVelocity = 0.0;    ///< vacc: the last update's acceleration along n, m/s
    double restitution = 0.0;             ///< the manifold's mixed coefficient
    /// Set by each impulse; at the step's start, the state the carried totals give (prepare).
    FrictionState friction = FrictionState::None;
    bool bounced = false;  ///< had its bounce this step (targetNormalVelocity)
    int pair = -1;  ///< index into pairs_ when pair impulses may resolve it with its other point
    int manifold = 0;
    int point = 0;
    Vec2 anchorA = Vec2::Zero();               ///< the point on A's surface, in A's frame
    Vec2 anchorB = Vec2::Zero();               ///< the point on B's surface, in B's frame
    Mat2 contactMatrix = Mat2::Zero();         ///< unit impulse -> velocity change
    Mat2 inverseContactMatrix = Mat2::Zero();  ///< velocity change -> impulse
  };
  /// A contact point in the penetration phase: what a move reads and refreshes, one cache line.
  struct alignas(64) MovePoint {
    int bodyA = 0;
    int bodyB = 0;
    double penetration = 0.0;     ///< m, kept current while bodies move
    Vec2 normal = Vec2::Zero();   ///< from A to B
    Vec2 anchorA = Vec2::Zero();  ///< the point on A's surface, in A's frame
    Vec2 anchorB = Vec2::Zero();  ///< the point on B's surface, in B's frame
  };
  /// The two points of a manifold as one micro-collision: states_[first] and states_[first + 1].
  struct PointPair {
    enum class Status { NotInverted, Inverted, Singular };
    int first = 0;
    Status status = Status::NotInverted;
    /// (normal at the first, normal at the second, tangent) impulses -> velocity changes
    Eigen::Matrix3d contactMatrix;
    /// (normal at the first, normal at the second, tangent) velocity changes -> impulses
    Eigen::Matrix3d inverseContactMatrix;
    /// the same for the two normals alone, for a frictionless pair
    Eigen::Matrix2d inverseNormalMatrix;
  };
  /// The two states of a pair, in manifold order.
  using PointsOfPair = std::array<PointState*, 2>;

  void prepare(const StepContext& context);
  void loadSolverBodies(const StepContext& context);
  void storeVelocities(const StepContext& context) const;
  void storeVelocity(const StepContext& context, int body) const;
  Vec2 contactVelocityNow(const PointState& state) const;
  void applyImpulse(const PointState& state, const Vec2& impulse);
  PointState preparePoint(const StepContext& context, int manifoldIndex, int pointIndex);
  Vec2 warmStartTotals(const Manifold& manifold, const ContactPoint& point,
                       bool bouncedLastStep) const;
  FrictionState carriedFriction(const PointState& state, double friction) const;
  void indexContactsByBody(const StepContext& context);
  double appliedRestitution(const PointState& state, double closingSpeed) const;
  double accelerationVelocity(const StepContext& context, const Manifold& manifold) const;
  double targetNormalVelocity(const PointState& state) const;
  Vec2 desiredVelocityChange(const PointState& state) const;
  bool engaged(const PointState& state) const;
  void preparePairs();
  void invertPairContactMatrix(PointPair& pair) const;
  bool applyPairChange(const StepContext& context, const PointState& worst, int iteration);
  bool pairNeedsChange(const PointsOfPair& points, bool bounce, std::array<Vec2, 2>& desired) const;
  bool newPairTotals(const PointPair& pair, const PointsOfPair& points,
                     const std::array<Vec2, 2>& desired, double friction, Eigen::Vector3d& after,
                     bool& sliding) const;
  std::array<Vec2, 2> applyPairTotals(Manifold& manifold, const PointsOfPair& points,
                                      const Eigen::Vector3d& after, FrictionState friction,
                                      bool bounce);
  bool slidingPairTotals(const PointPair& pair, const Eigen::Vector3d& before,
                         const Eigen::Vector3d& change, double slide, Eigen::Vector3d& after) const;
  void afterImpulse(const StepContext& context, const PointState& state);
  double severity(const PointState& state) const;
  bool toBounce(const PointState& state) const;
  int worstVelocityPoint();
  void recordRound();
  bool stillProgressing() const;
  Vec2 newTotalImpulse(const PointState& state, const Vec2& before, double friction,
                       const Vec2& desiredChange, FrictionState& frictionState) const;
  bool separatesPastItsBounce(const PointState& state) const;
  Vec2 frictionAlone(const PointState& state, const Vec2& before, double friction,
                     const Vec2& desiredChange, FrictionState& frictionState) const;
  void applyVelocityChange(const StepContext& context, int index, int iteration);
  void refreshContactVelocities(const StepContext& context, int bodyIndex, int refreshedBody);

  int worstPenetration();
  void resolvePenetration(const StepContext& context, int index, int iteration);
  void resolvePoint(const StepContext& context, int index, int iteration);
  int otherPoint(int index) const;
  void afterMove(const StepContext& context, const MovePoint& point);
  bool resolvePair(const StepContext& context, int index, int partner, int iteration);
  Vec2 contactPointNow(const MovePoint& point, const Vec2& normal) const;
  void loadPoses(const StepContext& context);
  void storePoses(const StepContext& context);
  void storePose(const StepContext& context, int body);
  Vec2 normalNow(const MovePoint& point) const;
  std::array<Vec2, 2> anchorsNow(const MovePoint& point, const Vec2& normal) const;
  double penetrationNow(const MovePoint& point) const;
  void moveBody(Pose& body, const Vec2& arm, const Vec2& direction, double penetration,
                double totalInertia) const;
  void refreshPenetrations(int bodyIndex, int refreshedBody);

  MicroCollisionSettings settings_;
  std::vector<SolverBody> solverBodies_;  ///< by body, during the velocity phase
  std::vector<Pose> poses_;               ///< by body, during the penetration phase
  std::vector<PointState> states_;
  /// Whether each point had its bounce last step: a bounce is not resting weight, so it is not
  /// warm-started.
  PointMemory<bool> bounced_;
  std::vector<MovePoint> movePoints_;  ///< by point, as states_, during the penetration phase
  std::vector<PointPair> pairs_;
  std::vector<int>
      contactsOfBodyStart_;  ///< states_ of body i: contactsOfBody_[start[i], start[i+1])
  std::vector<int> contactsOfBody_;
  std::vector<double> queueKeys_;
  WorstFirstQueue queue_;              ///< contact points by how badly they need resolving
  std::vector<double> waitingTotals_;  ///< the queue's waiting total after each round (recordRound)
  double dt_ = 0.0;                    ///< the step being resolved
  SolveReport report_;
};

}  // namespace impulse2d
