// Frames of one step, one per solver event.
#include "impulse2d/render/trace.h"

#include <cstdio>
#include <stdexcept>

namespace impulse2d::render {

namespace {

RenderSettings withVelocities(RenderSettings settings) {
  settings.overlays.velocities = true;
  return settings;
}

bool refersToPoint(const SolverEvent& event, const std::vector<Manifold>& manifolds) {
  return event.manifold >= 0 && std::size_t(event.manifold) < manifolds.size() &&
         event.point >= 0 && event.point < manifolds[event.manifold].pointCount;
}

}  // namespace

std::string describe(const SolverEvent& event) {
  char text[160];
  if (event.phase == SolverEvent::Phase::Velocity) {
    std::snprintf(text, sizeof text,
                  "velocity %d: contact %d.%d  dv = %.3f m/s  J = (%.3f, %.3f) N s",
                  event.iteration, event.manifold, event.point, event.desiredChange,
                  event.normalImpulse, event.tangentImpulse);
  } else {
    std::snprintf(text, sizeof text, "position %d: contact %d.%d  removed %.5f m of penetration",
                  event.iteration, event.manifold, event.point, event.desiredChange);
  }
  return text;
}

TraceRecorder::TraceRecorder(const Simulation& simulation, const FrameRenderer& renderer,
                             FrameWriter& writer)
    : simulation_(simulation),
      renderer_(renderer.camera(), renderer.scene(), withVelocities(renderer.settings())),
      writer_(writer) {
  renderer_.fitForces(simulation);
}

void TraceRecorder::onSolverEvent(const SolverEvent& event, const std::vector<Body>& bodies,
                                  const std::vector<Manifold>& manifolds) {
  FrameInfo info = render::describe(simulation_, renderer_.scene());
  info.step = simulation_.stepCount() + 1;  // the step being taken, not the steps done
  info.energy = totalEnergy(bodies, simulation_.settings().gravity);
  std::vector<std::string> lines = headsUpLines(info);
  lines.push_back(describe(event));
  renderer_.draw(bodies, manifolds, lines);
  drawHighlight(event, manifolds);
  writer_.write(info.step, renderer_.canvas());
}

void TraceRecorder::drawHighlight(const SolverEvent& event,
                                  const std::vector<Manifold>& manifolds) {
  if (!refersToPoint(event, manifolds)) return;
  const RenderSettings& settings = renderer_.settings();
  const Manifold& manifold = manifolds[event.manifold];
  const Vec2& point = manifold.points[event.point].point;
  const Color highlight = settings.colours.highlight;
  fillCircle(renderer_.canvas(), renderer_.camera().toPixels(point), settings.highlightRadius,
             withOpacity(highlight, 0.0), highlight, settings.highlightWidth);
  const Vec2 impulse =
      event.normalImpulse * manifold.normal + event.tangentImpulse * manifold.tangent();
  drawWorldArrow(renderer_.canvas(), renderer_.camera(), point,
                 settings.traceImpulseScale * impulse, highlight, settings);
}

FrameWriter traceStep(Simulation& simulation, long step, const FrameRenderer& renderer,
                      const std::filesystem::path& root) {
  if (step < 1 || simulation.stepCount() >= step) {
    throw std::invalid_argument("cannot trace step " + std::to_string(step) +
                                ": the simulation is at step " +
                                std::to_string(simulation.stepCount()));
  }
  FrameWriter writer(root, renderer.scene(), 1, tracePrefix(renderer.scene(), step),
                     renderer.settings());
  while (simulation.stepCount() < step - 1) simulation.step();
  TraceRecorder recorder(simulation, renderer, writer);
  simulation.setObserver(&recorder);
  simulation.step();
  simulation.setObserver(nullptr);
  if (writer.frameCount() > 0) writer.writeContactSheet();
  return writer;
}

}  // namespace impulse2d::render
