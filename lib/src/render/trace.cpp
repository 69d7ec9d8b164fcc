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
                     const std::string& solver, double dt) {
  EventStory story;
  const bool velocity = event.changesVelocity();
  story.label = eventLabel(event, solver);
  const std::string why = event.phase == SolverEvent::Phase::Restitution
                              ? ", after the substeps: the bounce"
                          : solver == "micro" ? ", the worst closing speed"
                                              : ", in sweep order";
  story.lines.push_back(story.label + why);
  if (!velocity) {
    story.lines.push_back(format("moved the bodies apart: %.3f mm of penetration removed",
                                 1000.0 * event.desiredChange));
    return story;
  }
  if (!refersToPoint(event, after, manifolds) || before.size() != after.size()) return story;
  const Manifold& manifold = manifolds[std::size_t(event.manifold)];
  const ContactPoint& point = manifold.points[event.point];
  const double closingBefore = -pointVelocity(before, manifold, point.point).dot(manifold.normal);
  const double closingAfter = -pointVelocity(after, manifold, point.point).dot(manifold.normal);
  const Vec2 accelerations = after[std::size_t(manifold.bodyB)].lastAcceleration -
                             after[std::size_t(manifold.bodyA)].lastAcceleration;
  story.lines.push_back(format("closing speed %.3f → %.3f m/s; Δv wanted %.3f m/s", closingBefore,
                               closingAfter, event.desiredChange));
  story.lines.push_back(
      format("impulse λ_n = %.4f N s, λ_t = %.4f N s; accelerative velocity a·Δt = %.3f m/s",
             event.normalImpulse, event.tangentImpulse,
             std::abs(accelerations.dot(manifold.normal)) * dt));
  story.lines.push_back(frictionLine(manifold, point));
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
  const EventStory story = tellEvent(event, before_, bodies, manifolds, simulation_.solverName(),
                                     simulation_.settings().dt);
  std::vector<std::string> lines = headsUpLines(info);
  lines.insert(lines.end(), story.lines.begin(), story.lines.end());
  const SceneState state{info.time, simulation_.settings().gravity};
  const Frame frame = renderer_.draw(bodies, manifolds, state, lines, story.label,
                                     [&](Drawing& drawing, DrawnKinds& drawn) {
                                       drawHighlight(drawing, drawn, event, bodies, manifolds);
                                     });
  writer_.write(info.step, frame, event.changesVelocity());
  before_ = bodies;
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
  if (!event.changesVelocity() || before_.size() != bodies.size()) return;
  drawing.setRole("velocity before");
  const double beforeLength = drawWorldArrow(
      drawing, camera, point, settings.velocityScale * pointVelocity(before_, manifold, point),
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
