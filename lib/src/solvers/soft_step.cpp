// Soft step: per step, prepare the contact constraints; per substep, integrate velocities, warm
// start, solve with the soft bias, integrate positions, relax; then restitution and store.
#include "impulse2d/solvers/soft_step.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "impulse2d/collide.h"
#include "impulse2d/solvers/contact_math.h"
#include "impulse2d/solvers/two_point_block.h"

namespace impulse2d {
namespace {

/// How far along the normal a contact found `separation` apart moves from the middle of the gap
/// to where the surfaces will touch, when one or both are circles (roundSurfaces): a circle
/// touches a polygon at its own surface, and two circles where the line of centres divides as
/// their radii. Zero for two polygons, whose touching point the gap does not tell, and for an
/// overlap, whose middle is where the surfaces are pressed together.
Vec2 towardsTouchingPoint(const Shape& a, const Shape& b, double separation, const Vec2& normal) {
  const bool circleA = a.type == ShapeType::Circle;
  const bool circleB = b.type == ShapeType::Circle;
  if ((!circleA && !circleB) || separation <= 0.0) return Vec2::Zero();
  const double shareOfA =
      circleA && circleB ? a.radius / (a.radius + b.radius) : (circleB ? 1.0 : 0.0);
  return separation * (shareOfA - 0.5) * normal;
}

/// A round feature of a contact: a circle's centre and radius, or a polygon's vertex (radius 0),
/// and how fast it moves.
struct RoundFeature {
  Vec2 centre;
  Vec2 velocity;
  double radius;
};

RoundFeature roundFeature(const Body& body, const Vec2& anchor, const Vec2& velocity,
                          double angularVelocity) {
  if (body.shape.type == ShapeType::Circle) return {body.position, velocity, body.shape.radius};
  const Vec2 vertex = body.toWorld(anchor);
  return {vertex, velocity + cross(angularVelocity, Vec2(vertex - body.position)), 0.0};
}

/// The normal from A to B when two round features closing across a gap first touch within the
/// time `reach`, moving at constant velocity; if they do not, when they come closest within it (the
/// separation along it stays positive, and the contact asks nothing). Empty for features already
/// overlapping or moving apart.
std::optional<Vec2> touchingNormal(const RoundFeature& a, const RoundFeature& b, double reach) {
  const Vec2 between = b.centre - a.centre;
  const Vec2 closing = b.velocity - a.velocity;
  const double touching = a.radius + b.radius;
  const double c = between.squaredNorm() - touching * touching;
  const double half = between.dot(closing);
  const double speedSquared = closing.squaredNorm();
  if (c <= 0.0 || half >= 0.0) return std::nullopt;
  const double discriminant = half * half - speedSquared * c;
  double t = std::min(-half / speedSquared, reach);
  if (discriminant >= 0.0) t = std::min(c / (std::sqrt(discriminant) - half), t);
  const Vec2 atTouch = between + t * closing;
  const double distance = atTouch.norm();
  if (distance <= 0.0) return std::nullopt;
  return Vec2(atTouch / distance);
}

}  // namespace

Softness makeSoftness(double hertz, double dampingRatio, double h) {
  if (hertz == 0.0) return {};
  const double omega = 2.0 * kPi * hertz;
  const double a1 = 2.0 * dampingRatio + h * omega;
  const double a2 = h * omega * a1;
  const double a3 = 1.0 / (1.0 + a2);
  return {omega / a1, a2 * a3, a3};
}

Softness rigidSoftness(double h) {
  return {1.0 / h, 1.0, 0.0};
}

// Box2D v3's step: the bodies move within the substeps, so the shared stages only find the
// contacts, check the state, clear the forces the substeps used and store the impulses.
void SoftStepSolver::step(StepStages& stages) {
  const StepContext context = stages.findContacts(contactFinding());
  stages.stopAtNonFiniteBody();
  solveSubsteps(context);
  stages.clearForces();
  stages.storeImpulses();
}

void SoftStepSolver::solveSubsteps(const StepContext& context) {
  const double h = context.dt / settings_.substeps;
  inverseSubstep_ = 1.0 / h;
  pushVelocity_ = settings_.maxPushVelocity;
  prepareBodies(context, h);
  prepareConstraints(context, h);
  report_ = SolveReport{};
  for (int substep = 0; substep < settings_.substeps; ++substep) {
    integrateVelocities();
    if (context.observer) reportVelocitiesChanged(context);
    warmStart();
    report_.residual = solve(context, true, substep);
    integratePositions(h);
    if (settings_.relaxation != Relaxation::Off) report_.residual = solve(context, false, substep);
    report_.iterations = substep + 1;
  }
  if (settings_.restitution) applyRestitution(context);
  storeImpulses(context);
  finishBodies(context, h);
}

// Only awake dynamic bodies move: the others get zero inverse mass, so the contact pushes them
// not at all, and zero velocity.
void SoftStepSolver::prepareBodies(const StepContext& context, double h) {
  bodies_.assign(context.bodies.size(), SubstepBody{});
  for (int i = 0; i < static_cast<int>(context.bodies.size()); ++i) {
    const Body& body = context.bodies[i];
    if (!body.isAwake()) continue;
    SubstepBody& solverBody = bodies_[i];
    solverBody.velocity = body.velocity;
    solverBody.angularVelocity = body.angularVelocity;
    solverBody.inverseMass = body.inverseMass;
    solverBody.inverseInertia = body.inverseInertia;
    solverBody.velocityPerSubstep = h * (context.gravity + body.inverseMass * body.force);
    solverBody.angularVelocityPerSubstep = h * body.inverseInertia * body.torque;
  }
}

// Box2D v3's prepare: arms from each centre to the contact point as it was found (a recycled
// manifold's stay as they were, unturned: the Jacobians are fixed across steps as they are
// across substeps), the normal and tangent masses,
// the separation base, the closing velocity for restitution, and the impulses to warm start
// from (the last substep's of the last step, which the manifold keeps beside the step's totals).
void SoftStepSolver::prepareConstraints(const StepContext& context, double h) {
  const double hertz =
      std::min(settings_.contactHertz, settings_.maxHertzPerSubstepRate * inverseSubstep_);
  constraints_.resize(context.manifolds.size());
  lastSubstep_.recall(context.manifolds);
  std::size_t found = 0;
  for (int m = 0; m < static_cast<int>(context.manifolds.size()); ++m) {
    const Manifold& manifold = context.manifolds[m];
    Constraint& constraint = constraints_[m];
    constraint = Constraint{};
    constraint.load(manifold, m);
    const Body& bodyA = context.bodies[manifold.bodyA];
    const Body& bodyB = context.bodies[manifold.bodyB];
    constraint.turnArmA = !settings_.roundSurfaces || surfaceTurnsWithShape(bodyA.shape);
    constraint.turnArmB = !settings_.roundSurfaces || surfaceTurnsWithShape(bodyB.shape);
    const double pairHertz =
        bodyA.isAwake() && bodyB.isAwake() ? hertz : settings_.staticHertzFactor * hertz;
    constraint.softness = contactSoftness(pairHertz, h);
    const FoundManifold* foundManifold = recycling_.mayKeep(manifold, context.bodies)
                                             ? recycling_.foundManifold(manifold, found)
                                             : nullptr;
    for (int i = 0; i < manifold.pointCount; ++i) {
      ConstraintPoint& cp = constraint.points[i];
      const ContactPoint& point = manifold.points[i];
      const FoundPoint asFound = foundManifold
                                     ? foundManifold->points[i]
                                     : FoundPoint{point.point - bodyA.position,
                                                  point.point - bodyB.position, point.penetration};
      placePoint(manifold, point, asFound, bodyA, bodyB, lastSubstep_.recalled(m, i), cp);
    }
    if (settings_.speculativeAtTouch) placeAtTouch(context, constraint);
    prepareMasses(constraint);
  }
}

// A point's arms and separation base as found (with roundSurfaces, moved along the normal to
// where a circle will touch), and its impulses to warm start from.
void SoftStepSolver::placePoint(const Manifold& manifold, const ContactPoint& point,
                                const FoundPoint& found, const Body& bodyA, const Body& bodyB,
                                const LastSubstepImpulses& warmStart, ConstraintPoint& cp) const {
  const Vec2 shift =
      settings_.roundSurfaces
          ? towardsTouchingPoint(bodyA.shape, bodyB.shape, -found.penetration, manifold.normal)
          : Vec2::Zero();
  cp.armA = found.armA + shift;
  cp.armB = found.armB + shift;
  cp.baseSeparation = -point.penetration - (cp.armB - cp.armA).dot(manifold.normal);
  cp.normalImpulse = settings_.warmStarting ? warmStart.normal : 0.0;
  cp.tangentImpulse = settings_.warmStarting ? warmStart.tangent : 0.0;
}

// A speculative contact between round surfaces (speculativeAtTouch) is turned to where the two
// will touch within the step and one substep more (the last relax solve keeps a gap from closing
// within the next substep), each moving at its mean velocity over the step: the normal then runs
// between the two features, each arm reaches the touching point, and the separation base is the
// gap now along that normal, which the solver closes as the bodies reach it.
void SoftStepSolver::placeAtTouch(const StepContext& context, Constraint& constraint) const {
  const Manifold& manifold = context.manifolds[constraint.manifold];
  const Body& bodyA = context.bodies[manifold.bodyA];
  const Body& bodyB = context.bodies[manifold.bodyB];
  if (manifold.pointCount != 1 || !normalRunsToCentre(bodyA.shape, bodyB.shape, manifold)) return;
  const SubstepBody& a = bodies_[manifold.bodyA];
  const SubstepBody& b = bodies_[manifold.bodyB];
  const double halfSteps = 0.5 * settings_.substeps;
  const ContactPoint& point = manifold.points[0];
  const RoundFeature featureA = roundFeature(
      bodyA, point.anchorA, Vec2(a.velocity + halfSteps * a.velocityPerSubstep), a.angularVelocity);
  const RoundFeature featureB = roundFeature(
      bodyB, point.anchorB, Vec2(b.velocity + halfSteps * b.velocityPerSubstep), b.angularVelocity);
  const double reach = context.dt + 1.0 / inverseSubstep_;
  const std::optional<Vec2> normal = touchingNormal(featureA, featureB, reach);
  if (!normal) return;
  ConstraintPoint& cp = constraint.points[0];
  const Vec2 onA = featureA.centre + featureA.radius * *normal;
  const Vec2 onB = featureB.centre - featureB.radius * *normal;
  cp.armA = onA - bodyA.position;
  cp.armB = onB - bodyB.position;
  cp.baseSeparation = (onB - onA).dot(*normal) - (cp.armB - cp.armA).dot(*normal);
  constraint.normal = *normal;
  constraint.atTouch = true;
}

// Each point's normal and tangent masses and its closing velocity before the step.
void SoftStepSolver::prepareMasses(Constraint& constraint) const {
  const SubstepBody& a = bodies_[constraint.bodyA];
  const SubstepBody& b = bodies_[constraint.bodyB];
  const Vec2 normal = constraint.normal;
  const Vec2 tangent = leftPerpendicular(normal);
  for (int i = 0; i < constraint.pointCount; ++i) {
    ConstraintPoint& cp = constraint.points[i];
    const double kNormal = inverseEffectiveMass(a, b, cp.armA, cp.armB, normal);
    const double kTangent = inverseEffectiveMass(a, b, cp.armA, cp.armB, tangent);
    cp.normalMass = kNormal > 0.0 ? 1.0 / kNormal : 0.0;
    cp.tangentMass = kTangent > 0.0 ? 1.0 / kTangent : 0.0;
    cp.normalArmA = cross(cp.armA, normal);
    cp.normalArmB = cross(cp.armB, normal);
    cp.tangentArmA = cross(cp.armA, tangent);
    cp.tangentArmB = cross(cp.armB, tangent);
    cp.relativeVelocity = relativeVelocity(a, b, cp.armA, cp.armB).dot(normal);
  }
}

// The spring of a contact's points: its hertz and the damping, or the rigid limit without soft
// contacts.
Softness SoftStepSolver::contactSoftness(double hertz, double h) const {
  if (!settings_.softContacts) return rigidSoftness(h);
  return makeSoftness(hertz, settings_.dampingRatio, h);
}

void SoftStepSolver::integrateVelocities() {
  for (SubstepBody& body : bodies_) {
    body.velocity += body.velocityPerSubstep;
    body.angularVelocity += body.angularVelocityPerSubstep;
  }
}

// The last substep's impulses applied up front; off, each substep starts from zero.
void SoftStepSolver::warmStart() {
  if (!settings_.warmStarting) {
    for (Constraint& constraint : constraints_) {
      for (ConstraintPoint& cp : constraint.points) cp.normalImpulse = cp.tangentImpulse = 0.0;
    }
    return;
  }
  for (Constraint& constraint : constraints_) {
    SolverBody a = bodies_[constraint.bodyA];
    SolverBody b = bodies_[constraint.bodyB];
    const Vec2 tangent = leftPerpendicular(constraint.normal);
    for (int i = 0; i < constraint.pointCount; ++i) {
      ConstraintPoint& cp = constraint.points[i];
      cp.totalNormalImpulse += cp.normalImpulse;
      cp.totalTangentImpulse += cp.tangentImpulse;
      applyPairImpulse(a, b, cp.armA, cp.armB,
                       cp.normalImpulse * constraint.normal + cp.tangentImpulse * tangent);
    }
    storeVelocities(a, bodies_[constraint.bodyA]);
    storeVelocities(b, bodies_[constraint.bodyB]);
  }
}

// One Gauss-Seidel sweep: the normal impulses of each contact, then its friction (with
// Relaxation::FrictionInRelax, only in the relax sweep). With bias the overlap is pushed out
// softly; without (relax) only the velocities are made consistent. Each contact works on copies of
// its two bodies' velocities, written back once it is solved, as Box2D v3's b2SolveContact does.
// Returns the largest normal impulse change, the sweep's residual.
double SoftStepSolver::solve(const StepContext& context, bool useBias, int substep) {
  const bool friction = !useBias || settings_.relaxation != Relaxation::FrictionInRelax;
  double largestChange = 0.0;
  for (Constraint& constraint : constraints_) {
    SubstepBody& bodyA = bodies_[constraint.bodyA];
    SubstepBody& bodyB = bodies_[constraint.bodyB];
    std::array<PointImpulses, 2> before;
    if (context.observer) before = impulsesOf(constraint);
    SolverBody a = bodyA;
    SolverBody b = bodyB;
    const double change = solveNormals(constraint, bodyA, bodyB, a, b, useBias);
    largestChange = std::max(largestChange, change);
    if (friction) solveFriction(constraint, a, b);
    storeVelocities(a, bodyA);
    storeVelocities(b, bodyB);
    if (context.observer) reportPoints(context, constraint, before, substep, useBias);
  }
  return largestChange;
}

// Each point's impulses, before a traced sweep changes them.
std::array<SoftStepSolver::PointImpulses, 2> SoftStepSolver::impulsesOf(
    const Constraint& constraint) {
  return {PointImpulses{constraint.points[0].normalImpulse, constraint.points[0].tangentImpulse},
          PointImpulses{constraint.points[1].normalImpulse, constraint.points[1].tangentImpulse}};
}

// The velocities a contact's solve changed, back into its body.
void SoftStepSolver::storeVelocities(const SolverBody& solved, SubstepBody& body) {
  body.velocity = solved.velocity;
  body.angularVelocity = solved.angularVelocity;
}

// A traced sweep tells one event per point of the manifold just solved: the impulses it changed
// by, the velocity change its normal row wanted before clamping (λ/m), and the bodies after the
// manifold's solve as far as the substeps have moved them. The relax sweep's are its own phase.
void SoftStepSolver::reportPoints(const StepContext& context, const Constraint& constraint,
                                  const std::array<PointImpulses, 2>& before, int substep,
                                  bool useBias) {
  updateTracedState(context);
  for (int i = 0; i < constraint.pointCount; ++i) {
    const ConstraintPoint& cp = constraint.points[i];
    const SolverEvent event{useBias ? SolverEvent::Phase::Velocity : SolverEvent::Phase::Relax,
                            substep,
                            constraint.manifold,
                            i,
                            cp.wantedImpulse / cp.normalMass,
                            cp.normalImpulse - before[i].normal,
                            cp.tangentImpulse - before[i].tangent};
    context.observer->onSolverEvent(event, tracedBodies_, context.manifolds);
  }
}

// The velocities the next traced event starts from: a substep's after its gravity and loads, or
// the substeps' last before the restitution pass.
void SoftStepSolver::reportVelocitiesChanged(const StepContext& context) {
  updateTracedState(context);
  context.observer->onVelocitiesChanged(tracedBodies_);
}

// The world's bodies move when the step ends (finishBodies); a trace sees copies moved now, and
// the manifolds' impulses as they stand.
void SoftStepSolver::updateTracedState(const StepContext& context) {
  writeTotals(context);
  tracedBodies_ = context.bodies;
  for (int i = 0; i < static_cast<int>(tracedBodies_.size()); ++i) {
    if (tracedBodies_[i].isAwake()) moveBody(bodies_[i], tracedBodies_[i]);
  }
}

// The body moved by what the substeps so far did to it: position, angle and velocities.
void SoftStepSolver::moveBody(const SubstepBody& moved, Body& body) {
  body.position += moved.deltaPosition;
  body.angle += moved.deltaAngle;
  body.velocity = moved.velocity;
  body.angularVelocity = moved.angularVelocity;
  body.updateCache();
}

// The separation now is the base plus how far the anchors moved along the (fixed) normal, a
// circle's with its centre alone (roundSurfaces), every other turned with its body. A gap
// (s > 0) may close within the substep and no further; an overlap is pushed out at the soft bias
// rate, never faster than maxPushVelocity.
inline SoftStepSolver::NormalRow SoftStepSolver::normalRow(const Constraint& constraint,
                                                           const ConstraintPoint& cp,
                                                           const SubstepBody& a,
                                                           const SubstepBody& b,
                                                           bool useBias) const {
  const Vec2 armA = constraint.turnArmA ? rotate(a.deltaCos, a.deltaSin, cp.armA) : cp.armA;
  const Vec2 armB = constraint.turnArmB ? rotate(b.deltaCos, b.deltaSin, cp.armB) : cp.armB;
  const Vec2 anchorsMoved = b.deltaPosition - a.deltaPosition + armB - armA;
  const double separation = cp.baseSeparation + anchorsMoved.dot(constraint.normal);
  if (separation > 0.0) return {separation * inverseSubstep_, 1.0, 0.0};
  if (!useBias) return {};
  const Softness& soft = constraint.softness;
  return {std::max(soft.biasRate * separation, -pushVelocity_), soft.massScale, soft.impulseScale};
}

// The normal impulses of a contact, on the velocities `a` and `b` of its bodies, whose moves
// since the step began are `movedA` and `movedB`. Returns the largest change of an impulse.
inline double SoftStepSolver::solveNormals(Constraint& constraint, const SubstepBody& movedA,
                                           const SubstepBody& movedB, SolverBody& a, SolverBody& b,
                                           bool useBias) {
  const Vec2 normal = constraint.normal;
  double largestChange = 0.0;
  for (int i = 0; i < constraint.pointCount; ++i) {
    ConstraintPoint& cp = constraint.points[i];
    const NormalRow row = normalRow(constraint, cp, movedA, movedB, useBias);
    const double vn = velocityAlong(a, b, normal, cp.normalArmA, cp.normalArmB);
    const double impulse =
        -cp.normalMass * row.massScale * (vn + row.bias) - row.impulseScale * cp.normalImpulse;
    const double total = std::max(cp.normalImpulse + impulse, 0.0);
    const double change = total - cp.normalImpulse;
    cp.wantedImpulse = impulse;
    cp.normalImpulse = total;
    cp.totalNormalImpulse += change;
    applyAlong(a, b, normal, cp.normalArmA, cp.normalArmB, change);
    largestChange = std::max(largestChange, std::abs(change));
  }
  return largestChange;
}

// Coulomb friction on each point's running total, bounded by μ times its normal impulse.
inline void SoftStepSolver::solveFriction(Constraint& constraint, SolverBody& a,
                                          SolverBody& b) const {
  const Vec2 tangent = leftPerpendicular(constraint.normal);
  for (int i = 0; i < constraint.pointCount; ++i) {
    ConstraintPoint& cp = constraint.points[i];
    const double vt = velocityAlong(a, b, tangent, cp.tangentArmA, cp.tangentArmB);
    const double limit = constraint.friction * cp.normalImpulse;
    const double total = std::clamp(cp.tangentImpulse - cp.tangentMass * vt, -limit, limit);
    const double change = total - cp.tangentImpulse;
    cp.tangentImpulse = total;
    cp.totalTangentImpulse += change;
    applyAlong(a, b, tangent, cp.tangentArmA, cp.tangentArmB, change);
  }
}

// x += v·h; the rotation since the step began is kept as cosine and sine and turned by ω·h
// without trigonometry (then renormalised), as Box2D v3 does.
void SoftStepSolver::integratePositions(double h) {
  for (SubstepBody& body : bodies_) {
    if (body.inverseMass == 0.0 && body.inverseInertia == 0.0) continue;
    body.deltaPosition += h * body.velocity;
    const double turn = h * body.angularVelocity;
    body.deltaAngle += turn;
    const double c = body.deltaCos - turn * body.deltaSin;
    const double s = body.deltaSin + turn * body.deltaCos;
    const double length = std::sqrt(c * c + s * s);
    body.deltaCos = c / length;
    body.deltaSin = s / length;
  }
}

// Whether a point bounces: it was closing faster than the threshold before the step and was
// touched in it.
bool SoftStepSolver::bounces(const ConstraintPoint& cp) const {
  return cp.relativeVelocity <= -settings_.restitutionThreshold && cp.totalNormalImpulse != 0.0;
}

// A contact that bounces is made to separate at −e times its closing speed before the step: a
// two-point manifold whose points both bounce as one block (restitutionBlock), otherwise point by
// point as Box2D v3 does. With frictionInRestitution its friction is then solved once more, now
// bounded with the bounce's impulse in the normal one, and the bounce again, since at a corner,
// or at a face's two corners carrying unequal loads, friction also changes the normal velocities.
void SoftStepSolver::applyRestitution(const StepContext& context) {
  if (context.observer) reportVelocitiesChanged(context);
  for (Constraint& constraint : constraints_) {
    if (constraint.restitution == 0.0) continue;
    SubstepBody& a = bodies_[constraint.bodyA];
    SubstepBody& b = bodies_[constraint.bodyB];
    const BounceStart start = context.observer ? bounceStart(constraint, a, b) : BounceStart{};
    const bool bounced =
        applyPairRestitution(constraint, a, b) || applyPointRestitution(constraint, a, b);
    if (bounced && settings_.frictionInRestitution) {
      solveFriction(constraint, a, b);
      if (!applyPairRestitution(constraint, a, b)) applyPointRestitution(constraint, a, b);
    }
    if (bounced && context.observer) reportBounce(context, constraint, start);
  }
}

SoftStepSolver::BounceStart SoftStepSolver::bounceStart(const Constraint& constraint,
                                                        const SubstepBody& a,
                                                        const SubstepBody& b) const {
  BounceStart start;
  for (int i = 0; i < constraint.pointCount; ++i) {
    const ConstraintPoint& cp = constraint.points[i];
    start.totals[i] = {cp.totalNormalImpulse, cp.totalTangentImpulse};
    const double vn = relativeVelocity(a, b, cp.armA, cp.armB).dot(constraint.normal);
    start.wantedChange[i] = -constraint.restitution * cp.relativeVelocity - vn;
  }
  return start;
}

// A traced bounce tells one event per point that bounced: what the restitution pass (and the
// friction solved with it) added to the step's impulses, and the bodies after it.
void SoftStepSolver::reportBounce(const StepContext& context, const Constraint& constraint,
                                  const BounceStart& start) {
  updateTracedState(context);
  for (int i = 0; i < constraint.pointCount; ++i) {
    const ConstraintPoint& cp = constraint.points[i];
    if (!bounces(cp)) continue;
    const SolverEvent event{SolverEvent::Phase::Restitution,
                            settings_.substeps,
                            constraint.manifold,
                            i,
                            start.wantedChange[i],
                            cp.totalNormalImpulse - start.totals[i].normal,
                            cp.totalTangentImpulse - start.totals[i].tangent};
    context.observer->onSolverEvent(event, tracedBodies_, context.manifolds);
  }
}

// Each point that bounces, one after the other. Returns whether any did.
bool SoftStepSolver::applyPointRestitution(Constraint& constraint, SubstepBody& a,
                                           SubstepBody& b) const {
  bool bounced = false;
  for (int i = 0; i < constraint.pointCount; ++i) {
    ConstraintPoint& cp = constraint.points[i];
    if (!bounces(cp)) continue;
    bounced = true;
    const double vn = relativeVelocity(a, b, cp.armA, cp.armB).dot(constraint.normal);
    const double impulse = -cp.normalMass * (vn + constraint.restitution * cp.relativeVelocity);
    setBounceImpulse(constraint, cp, a, b, std::max(bounceBase(cp) + impulse, 0.0));
  }
  return bounced;
}

// The accumulated normal impulse a bounce is kept non-negative on: the impulse applied at the
// point over the whole step (restitutionOnStepTotals), or the last substep's, as in Box2D v3.
double SoftStepSolver::bounceBase(const ConstraintPoint& cp) const {
  return settings_.restitutionOnStepTotals ? cp.totalNormalImpulse : cp.normalImpulse;
}

// Sets the point's bounce base to `after` (≥ 0) and applies the change. The last substep's
// impulse, which the next step warm-starts from, takes the change too, never below 0.
void SoftStepSolver::setBounceImpulse(const Constraint& constraint, ConstraintPoint& cp,
                                      SubstepBody& a, SubstepBody& b, double after) const {
  const double change = after - bounceBase(cp);
  cp.normalImpulse = std::max(cp.normalImpulse + change, 0.0);
  cp.totalNormalImpulse += change;
  applyPairImpulse(a, b, cp.armA, cp.armB, change * constraint.normal);
}

// Both points of a two-point manifold that both bounce: the accumulated normal impulses x ≥ 0 that
// leave each point separating at −e times its closing speed before the step, or pushing nothing,
// found together (w = K (x − x₀) + vn − target ≥ 0, x·w = 0). False when the pair is not solved
// as one: the switch is off, a point does not bounce, or K is too ill-conditioned.
bool SoftStepSolver::applyPairRestitution(Constraint& constraint, SubstepBody& a,
                                          SubstepBody& b) const {
  if (!settings_.restitutionBlock.enabled || constraint.pointCount != 2) return false;
  ConstraintPoint& p0 = constraint.points[0];
  ConstraintPoint& p1 = constraint.points[1];
  if (!bounces(p0) || !bounces(p1)) return false;
  const Vec2& n = constraint.normal;
  const Mat2 k = normalCouplingMatrix(a, b, n, {p0.armA, p1.armA}, {p0.armB, p1.armB});
  if (!isWellConditioned(k, settings_.restitutionBlock.conditionLimit)) return false;
  const Vec2 before(bounceBase(p0), bounceBase(p1));
  Vec2 missing;  // vn − target at each point now
  for (int i = 0; i < 2; ++i) {
    const ConstraintPoint& cp = constraint.points[i];
    const double vn = relativeVelocity(a, b, cp.armA, cp.armB).dot(n);
    missing(i) = vn + constraint.restitution * cp.relativeVelocity;
  }
  const Vec2 after = solveTwoPointLcp(k, Vec2(missing - k * before));
  setBounceImpulse(constraint, p0, a, b, after(0));
  setBounceImpulse(constraint, p1, a, b, after(1));
  return true;
}

// The manifold keeps the impulses applied over the whole step (warm starts, solves and bounces
// summed), as every method reports them, the last substep's to warm start the next step from,
// and the friction state of each point.
void SoftStepSolver::storeImpulses(const StepContext& context) {
  writeTotals(context);
  for (const Constraint& constraint : constraints_) {
    if (constraint.atTouch) context.manifolds[constraint.manifold].normal = constraint.normal;
    for (int i = 0; i < constraint.pointCount; ++i) {
      const ConstraintPoint& cp = constraint.points[i];
      lastSubstep_.store(constraint.manifold, i, {cp.normalImpulse, cp.tangentImpulse});
    }
  }
  lastSubstep_.remember(context.manifolds, context.bodies);
}

// The step's impulses so far into the manifolds, and each point's friction state from its last
// substep: at the step's end, and for a traced event as it happens.
void SoftStepSolver::writeTotals(const StepContext& context) const {
  for (const Constraint& constraint : constraints_) {
    Manifold& manifold = context.manifolds[constraint.manifold];
    for (int i = 0; i < constraint.pointCount; ++i) {
      const ConstraintPoint& cp = constraint.points[i];
      ContactPoint& point = manifold.points[i];
      point.normalImpulse = cp.totalNormalImpulse;
      point.tangentImpulse = cp.totalTangentImpulse;
      point.friction = frictionStateOf(cp.normalImpulse, cp.tangentImpulse, manifold.friction, 0.0);
    }
  }
}

void SoftStepSolver::finishBodies(const StepContext& context, double h) const {
  for (int i = 0; i < static_cast<int>(context.bodies.size()); ++i) {
    Body& body = context.bodies[i];
    if (!body.isAwake()) continue;
    moveBody(bodies_[i], body);
    body.lastAcceleration = bodies_[i].velocityPerSubstep / h;
  }
}

}  // namespace impulse2d
