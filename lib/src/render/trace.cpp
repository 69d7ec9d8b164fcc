// Frames of one step, one per solver event, each telling what the event did.
#include "impulse2d/render/trace.h"

#include <stdexcept>

namespace impulse2d::render {

namespace {

RenderSettings withVelocities(RenderSettings settings) {
  settings.overlays.velocities = true;
  settings.headsUpLines = settings.traceHeadsUpLines;
  return settings;
}

}  // namespace

TraceRecorder::TraceRecorder(const Simulation& simulation, const FrameRenderer& renderer,
                             FrameWriter& writer)
    : simulation_(simulation),
      renderer_(renderer.camera(), renderer.scene(), withVelocities(renderer.settings())),
      writer_(writer),
      teller_(simulation.bodies()) {
  renderer_.setLog(renderer.log());
  renderer_.fitForces(simulation);
}

void TraceRecorder::onSolverEvent(const SolverEvent& event, const std::vector<Body>& bodies,
                                  const std::vector<Manifold>& manifolds) {
  FrameInfo info = describe(simulation_, renderer_.scene());
  info.step = simulation_.stepCount() + 1;  // the step being taken, not the steps done
  info.energy = totalEnergy(bodies, simulation_.settings().gravity);
  const EventStory story =
      teller_.tell(event, bodies, manifolds, simulation_.solverName(), simulation_.settings().dt);
  std::vector<std::string> lines = headsUpLines(info);
  lines.insert(lines.end(), story.lines.begin(), story.lines.end());
  const SceneState state{info.time, simulation_.settings().gravity};
  const Frame frame = renderer_.draw(bodies, manifolds, state, lines, story.label,
                                     [&](Drawing& drawing, DrawnKinds& drawn) {
                                       drawHighlight(drawing, drawn, event, bodies, manifolds);
                                     });
  writer_.write(info.step, frame, event.changesVelocity());
}

void TraceRecorder::onVelocitiesChanged(const std::vector<Body>& bodies) {
  teller_.restart(bodies);
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
  if (!event.changesVelocity() || teller_.impulseBefore().size() != bodies.size()) return;
  drawing.setRole("velocity before");
  const double beforeLength = drawWorldArrow(
      drawing, camera, point,
      settings.velocityScale * pointVelocity(teller_.impulseBefore(), manifold, point),
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
