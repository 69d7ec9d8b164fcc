// Per-step figures of a run and the events of a traced step.
#include "run_figures.h"

#include <algorithm>
#include <cmath>

namespace i2d {

StepFigures measureStep(const impulse2d::Simulation& simulation) {
  StepFigures figures;
  figures.step = simulation.stepCount();
  figures.time = double(figures.step) * simulation.settings().dt;
  figures.kinetic = impulse2d::kineticEnergy(simulation);
  figures.potential = impulse2d::potentialEnergy(simulation);
  figures.contacts = impulse2d::contactPointCount(simulation);
  figures.penetration = impulse2d::largestPenetration(simulation);
  const impulse2d::WorldSettings& world = simulation.settings();
  const double impulseTime = world.dt / std::max(1, world.substeps);
  const double loadTime = std::max(0.0, figures.time - impulseTime);
  const std::vector<impulse2d::Body>& bodies = simulation.bodies();
  const auto loaded = [&](int index) {
    const impulse2d::Body& body = bodies[std::size_t(index)];
    return !body.isStatic() && !body.load.isZero();
  };
  for (const impulse2d::Body& body : bodies) {
    if (!body.isStatic()) figures.appliedForce += body.load.forceAt(loadTime).norm();
  }
  for (const impulse2d::Manifold& manifold : simulation.manifolds()) {
    if (!loaded(manifold.bodyA) && !loaded(manifold.bodyB)) continue;
    double tangent = 0.0;
    for (int i = 0; i < manifold.pointCount; ++i) tangent += manifold.points[i].tangentImpulse;
    figures.frictionForce += std::abs(tangent) / impulseTime;
  }
  return figures;
}

bool hasLoads(const impulse2d::Simulation& simulation) {
  for (const impulse2d::Body& body : simulation.bodies()) {
    if (!body.isStatic() && !body.load.isZero()) return true;
  }
  return false;
}

impulse2d::render::FigureTable figureTable(const std::vector<StepFigures>& figures,
                                           const std::vector<long>& frameSteps) {
  impulse2d::render::FigureTable table;
  table.columns = {"time (s)",         "kinetic energy (J)", "potential energy (J)",
                   "total energy (J)", "contact points",     "largest penetration (m)"};
  for (const long step : frameSteps) {
    if (step < 0 || std::size_t(step) >= figures.size()) break;
    const StepFigures& f = figures[std::size_t(step)];
    table.rows.push_back({f.time, f.kinetic, f.potential, f.kinetic + f.potential,
                          double(f.contacts), f.penetration});
  }
  return table;
}

void EventLog::onSolverEvent(const impulse2d::SolverEvent& event,
                             const std::vector<impulse2d::Body>&,
                             const std::vector<impulse2d::Manifold>&) {
  // A push between sweeps wants no velocity change of its own.
  if (!event.changesVelocity() || event.phase == impulse2d::SolverEvent::Phase::Push) return;
  errors_.push_back(std::abs(event.desiredChange));
  iterations_.push_back(event.iteration);
}

}  // namespace i2d
