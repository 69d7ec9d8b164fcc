// Frames of one step, one per solver event, each telling what the event did.
#include "impulse2d/render/trace.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace impulse2d::render {

namespace {

RenderSettings withVelocities(RenderSettings settings) {
  settings.overlays.velocities = true;
  settings.headsUpLines = settings.traceHeadsUpLines;
  return settings;
}

bool refersToPoint(const SolverEvent& event, const std::vector<Body>& bodies,
                   const std::vector<Manifold>& manifolds) {
  if (event.manifold < 0 || std::size_t(event.manifold) >= manifolds.size()) return false;
  const Manifold& manifold = manifolds[std::size_t(event.manifold)];
  return event.point >= 0 && event.point < manifold.pointCount && manifold.bodyA >= 0 &&
         manifold.bodyB >= 0 && std::size_t(manifold.bodyA) < bodies.size() &&
         std::size_t(manifold.bodyB) < bodies.size();
}

/// B's velocity relative to A's at the event's point.
Vec2 pointVelocity(const std::vector<Body>& bodies, const Manifold& manifold, const Vec2& point) {
  return bodies[std::size_t(manifold.bodyB)].velocityAt(point) -
         bodies[std::size_t(manifold.bodyA)].velocityAt(point);
}

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
  story.lines.push_back(story.label + whyThisPoint(event, before, manifolds, solver, partner));
  const Manifold& manifold = manifolds[std::size_t(event.manifold)];
  const ContactPoint& point = manifold.points[event.point];
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

TraceRecorder::TraceRecorder(const Simulation& simulation, const FrameRenderer& renderer,
                             FrameWriter& writer)
    : simulation_(simulation),
      renderer_(renderer.camera(), renderer.scene(), withVelocities(renderer.settings())),
      writer_(writer),
      before_(simulation.bodies()) {
  renderer_.setLog(renderer.log());
  renderer_.fitForces(simulation);
}

void TraceRecorder::onSolverEvent(const SolverEvent& event, const std::vector<Body>& bodies,
                                  const std::vector<Manifold>& manifolds) {
  FrameInfo info = describe(simulation_, renderer_.scene());
  info.step = simulation_.stepCount() + 1;  // the step being taken, not the steps done
  info.energy = totalEnergy(bodies, simulation_.settings().gravity);
  // The micro-collision resolver counts its impulses, so two events of one count are the two
  // corners of a pair impulse: both started from the bodies before it.
  const bool pairsSecond = simulation_.solverName() == "micro" && event.changesVelocity() &&
                           last_.phase == event.phase && last_.iteration == event.iteration &&
                           last_.manifold == event.manifold && last_.point != event.point;
  if (!pairsSecond) impulseBefore_ = before_;
  const int partner = pairsSecond ? last_.point : -1;
  const EventStory story = tellEvent(event, impulseBefore_, bodies, manifolds,
                                     simulation_.solverName(), simulation_.settings().dt, partner);
  std::vector<std::string> lines = headsUpLines(info);
  lines.insert(lines.end(), story.lines.begin(), story.lines.end());
  const SceneState state{info.time, simulation_.settings().gravity};
  const Frame frame = renderer_.draw(bodies, manifolds, state, lines, story.label,
                                     [&](Drawing& drawing, DrawnKinds& drawn) {
                                       drawHighlight(drawing, drawn, event, bodies, manifolds);
                                     });
  writer_.write(info.step, frame, event.changesVelocity());
  before_ = bodies;
  last_ = event;
}

void TraceRecorder::onVelocitiesChanged(const std::vector<Body>& bodies) {
  before_ = bodies;
}

void TraceRecorder::drawHighlight(Drawing& drawing, DrawnKinds& drawn, const SolverEvent& event,
                                  const std::vector<Body>& bodies,
                                  const std::vector<Manifold>& manifolds) const {
  if (!refersToPoint(event, bodies, manifolds)) return;
  const RenderSettings& settings = renderer_.settings();
  const Camera& camera = renderer_.camera();
  const Manifold& manifold = manifolds[std::size_t(event.manifold)];
  const Vec2& point = manifold.points[event.point].point;
  const Color highlight = settings.colours.highlight;
  drawing.setRole("highlight");
  drawing.ring(camera.toPixels(point), settings.highlightRadius, highlight,
               settings.highlightWidth);
  const Vec2 impulse =
      event.normalImpulse * manifold.normal + event.tangentImpulse * manifold.tangent();
  // At the run's force scale, as the force λ/Δt the event's impulse stands for over the step,
  // so it compares with the contact forces and the legend's scale bar.
  const ForceScale& forces = renderer_.forces();
  drawWorldArrow(drawing, camera, point, forces.metresPerNewton / forces.dt * impulse, highlight,
                 settings);
  drawn.highlight = true;
  if (!event.changesVelocity() || impulseBefore_.size() != bodies.size()) return;
  drawing.setRole("velocity before");
  const double beforeLength =
      drawWorldArrow(drawing, camera, point,
                     settings.velocityScale * pointVelocity(impulseBefore_, manifold, point),
                     withOpacity(highlight, 0.4), settings);
  drawing.setRole("velocity after");
  const double afterLength = drawWorldArrow(
      drawing, camera, point, settings.velocityScale * pointVelocity(bodies, manifold, point),
      highlight, settings);
  drawn.velocityChange = beforeLength > 0.0 || afterLength > 0.0;
}

FrameWriter traceStep(Simulation& simulation, long step, const FrameRenderer& renderer,
                      const std::filesystem::path& root, ImageFormat format) {
  if (step < 1 || simulation.stepCount() >= step) {
    throw std::invalid_argument("cannot trace step " + std::to_string(step) +
                                ": the simulation is at step " +
                                std::to_string(simulation.stepCount()));
  }
  FrameWriter writer(root, renderer.scene(), 1, tracePrefix(renderer.scene(), step),
                     renderer.settings(), format);
  while (simulation.stepCount() < step - 1) simulation.step();
  TraceRecorder recorder(simulation, renderer, writer);
  simulation.setObserver(&recorder);
  simulation.step();
  simulation.setObserver(nullptr);
  if (writer.frameCount() > 0) writer.writeContactSheet();
  return writer;
}

}  // namespace impulse2d::render
