// What each solver event of a step did, in the lecture's words: the text of a traced step's
// frames (trace.h), and of the browser's trace, which draws no frames.
#include "impulse2d/render/event_story.h"

#include <cctype>
#include <cmath>
#include <cstdio>

namespace impulse2d::render {

bool refersToPoint(const SolverEvent& event, const std::vector<Body>& bodies,
                   const std::vector<Manifold>& manifolds) {
  if (event.manifold < 0 || std::size_t(event.manifold) >= manifolds.size()) return false;
  const Manifold& manifold = manifolds[std::size_t(event.manifold)];
  return event.point >= 0 && event.point < manifold.pointCount && manifold.bodyA >= 0 &&
         manifold.bodyB >= 0 && std::size_t(manifold.bodyA) < bodies.size() &&
         std::size_t(manifold.bodyB) < bodies.size();
}

Vec2 pointVelocity(const std::vector<Body>& bodies, const Manifold& manifold, const Vec2& point) {
  return bodies[std::size_t(manifold.bodyB)].velocityAt(point) -
         bodies[std::size_t(manifold.bodyA)].velocityAt(point);
}

namespace {

/// Drops the sign of a number printed as zero ("-0.000"), which only says round-off was
/// negative.
std::string withoutNegativeZeros(std::string text) {
  for (std::size_t at = text.find("-0"); at != std::string::npos; at = text.find("-0", at + 1)) {
    std::size_t end = at + 2;
    while (end < text.size() && (text[end] == '0' || text[end] == '.')) ++end;
    const bool allZero = end == text.size() || !std::isdigit(static_cast<unsigned char>(text[end]));
    if (allZero) text.erase(at, 1);
  }
  return text;
}

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char text[200];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return withoutNegativeZeros(text);
}

/// B's speed towards A along the normal at the point: positive when closing.
double closingSpeed(const std::vector<Body>& bodies, const Manifold& manifold, const Vec2& point) {
  return -pointVelocity(bodies, manifold, point).dot(manifold.normal);
}

/// m/s: closing speeds that print alike (to the 3 decimals of the closing speed line) are equal.
constexpr double kPrintedSpeed = 0.5e-3;

/// Whether the point closes at least as fast as every contact point of the step.
bool closesFastest(const std::vector<Body>& bodies, const std::vector<Manifold>& manifolds,
                   const Manifold& manifold, const ContactPoint& point) {
  const double speed = closingSpeed(bodies, manifold, point.point);
  for (const Manifold& other : manifolds) {
    if (other.bodyA < 0 || other.bodyB < 0 || std::size_t(other.bodyA) >= bodies.size() ||
        std::size_t(other.bodyB) >= bodies.size()) {
      continue;
    }
    for (int i = 0; i < other.pointCount; ++i) {
      if (closingSpeed(bodies, other, other.points[i].point) > speed + kPrintedSpeed) return false;
    }
  }
  return true;
}

/// Why the solver took this point: ", the worst closing speed" only for the point closing
/// fastest (the resolver's queue weighs slip too); a pair's second corner names the first.
std::string whyThisPoint(const SolverEvent& event, const std::vector<Body>& before,
                         const std::vector<Manifold>& manifolds, const std::string& solver,
                         int partner) {
  if (event.phase == SolverEvent::Phase::Restitution) return ", after the substeps: the bounce";
  if (solver != "micro") return ", in sweep order";
  if (partner >= 0) {
    char text[96];
    std::snprintf(text, sizeof text, ", in one impulse with contact %d.%d (a pair of corners)",
                  event.manifold, partner);
    return text;
  }
  const Manifold& manifold = manifolds[std::size_t(event.manifold)];
  return closesFastest(before, manifolds, manifold, manifold.points[event.point])
             ? ", the worst closing speed"
             : ", the largest velocity change wanted";
}

/// Friction at the point after the event: static when |λt| stays inside μλn, dynamic on it.
std::string frictionLine(const Manifold& manifold, const ContactPoint& point) {
  const double limit = manifold.friction * point.normalImpulse;
  const double used = std::abs(point.tangentImpulse);
  if (point.friction == FrictionState::Dynamic) {
    return format("dynamic friction: |λ_t| = %.4f N s = μλ_n (μ = %.2f): on the cone, sliding",
                  used, manifold.friction);
  }
  return format("static friction: |λ_t| = %.4f N s < μλ_n = %.4f N s (μ = %.2f): it holds", used,
                limit, manifold.friction);
}

/// "velocity 3: contact 5.0": the pass, its count (sweep, impulse, move, or soft step's substep,
/// whose relax sweep is "relax 3") and the point. Soft step bounces after its substeps:
/// "restitution: contact 5.0".
std::string eventLabel(const SolverEvent& event, const std::string& solver) {
  char label[96];
  if (event.phase == SolverEvent::Phase::Restitution) {
    std::snprintf(label, sizeof label, "restitution: contact %d.%d", event.manifold, event.point);
    return label;
  }
  const char* pass = !event.changesVelocity()                   ? "position"
                     : event.phase == SolverEvent::Phase::Relax ? "relax"
                     : event.phase == SolverEvent::Phase::Push  ? "push"
                     : solver == "soft_step"                    ? "substep"
                                                                : "velocity";
  std::snprintf(label, sizeof label, "%s %d: contact %d.%d", pass, event.iteration, event.manifold,
                event.point);
  return label;
}

}  // namespace

EventStory tellEvent(const SolverEvent& event, const std::vector<Body>& before,
                     const std::vector<Body>& after, const std::vector<Manifold>& manifolds,
                     const std::string& solver, double dt, int partner) {
  EventStory story;
  story.label = eventLabel(event, solver);
  if (!event.changesVelocity()) {
    story.lines.push_back(story.label +
                          (solver == "micro" ? ", the deepest penetration" : ", in sweep order"));
    story.lines.push_back(format("moved the bodies apart: %.3f mm of penetration removed",
                                 1000.0 * event.desiredChange));
    return story;
  }
  if (!refersToPoint(event, after, manifolds) || before.size() != after.size()) {
    story.lines.push_back(story.label);
    return story;
  }
  const Manifold& manifold = manifolds[std::size_t(event.manifold)];
  const ContactPoint& point = manifold.points[event.point];
  if (event.phase == SolverEvent::Phase::Push) {
    // Short lines: a tall scene's frame is narrow.
    story.lines.push_back(story.label + ", conjugate gradient");
    story.lines.push_back(format("closing speed %.3f → %.3f m/s",
                                 closingSpeed(before, manifold, point.point),
                                 closingSpeed(after, manifold, point.point)));
    story.lines.push_back(format("pushed on: λ_n %+.4f N s, λ_t %+.4f N s", event.normalImpulse,
                                 event.tangentImpulse));
    return story;
  }
  story.lines.push_back(story.label + whyThisPoint(event, before, manifolds, solver, partner));
  const Vec2 accelerations = after[std::size_t(manifold.bodyB)].lastAcceleration -
                             after[std::size_t(manifold.bodyA)].lastAcceleration;
  story.lines.push_back(format("closing speed %.3f → %.3f m/s; Δv wanted %.3f m/s",
                               closingSpeed(before, manifold, point.point),
                               closingSpeed(after, manifold, point.point), event.desiredChange));
  story.lines.push_back(
      format("impulse λ_n = %.4f N s, λ_t = %.4f N s; accelerative velocity a·Δt = %.3f m/s",
             event.normalImpulse, event.tangentImpulse,
             std::abs(accelerations.dot(manifold.normal)) * dt));
  if (manifold.friction > 0.0) story.lines.push_back(frictionLine(manifold, point));
  return story;
}

EventStory EventTeller::tell(const SolverEvent& event, const std::vector<Body>& bodies,
                             const std::vector<Manifold>& manifolds, const std::string& solver,
                             double dt) {
  // The micro-collision resolver counts its impulses, so two events of one count are the two
  // corners of a pair impulse: both started from the bodies before it.
  const bool pairsSecond = solver == "micro" && event.changesVelocity() &&
                           last_.phase == event.phase && last_.iteration == event.iteration &&
                           last_.manifold == event.manifold && last_.point != event.point;
  if (!pairsSecond) impulseBefore_ = before_;
  const int partner = pairsSecond ? last_.point : -1;
  EventStory story = tellEvent(event, impulseBefore_, bodies, manifolds, solver, dt, partner);
  before_ = bodies;
  last_ = event;
  return story;
}

}  // namespace impulse2d::render
