// Lockstep runs of several simulations of one scene, and the figures of agreement with Box2D.
#include "impulse2d/box2d/agreement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "impulse2d/box2d/box2d_simulation.h"

namespace impulse2d {
namespace {

/// What one body's figures are measured from while it runs.
struct BodyTrack {
  Vec2 previousPosition = Vec2::Zero();
  Vec2 driftOrigin = Vec2::Zero();
  bool hasFallen = false;  ///< moved down faster than bounceSpeed
};

/// One simulation while it runs: its figures so far and what they are measured from.
struct Run {
  std::unique_ptr<Simulation> simulation;
  MethodFigures figures;
  std::vector<BodyTrack> tracks;  ///< parallel to figures.bodies
  bool driftStarted = false;
  long lastMovingStep = -1;
};

Run startRun(std::unique_ptr<Simulation> simulation) {
  Run run;
  run.figures.method = simulation->solverName();
  const std::vector<Body>& bodies = simulation->bodies();
  for (size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].isStatic()) continue;
    BodyFigures figures;
    figures.body = int(i);
    figures.name = bodies[i].name;
    run.figures.bodies.push_back(figures);
    run.tracks.push_back({bodies[i].position, bodies[i].position, false});
  }
  run.simulation = std::move(simulation);
  return run;
}

/// Which bodies have a contact point after the last step.
std::vector<bool> touchingBodies(const Simulation& simulation) {
  std::vector<bool> touching(simulation.bodies().size(), false);
  for (const Manifold& manifold : simulation.manifolds()) {
    if (manifold.pointCount == 0) continue;
    touching[manifold.bodyA] = true;
    touching[manifold.bodyB] = true;
  }
  return touching;
}

void trackBounce(const Body& body, double bounceSpeed, bool& hasFallen, BodyFigures& figures) {
  if (body.velocity.y() < -bounceSpeed) hasFallen = true;
  const bool bounced = !std::isnan(figures.bounceApex);
  if (!bounced && hasFallen && body.velocity.y() > bounceSpeed) {
    figures.bounceApex = body.position.y();
  }
  if (bounced) figures.bounceApex = std::max(figures.bounceApex, body.position.y());
}

bool isMoving(const Body& body, const AgreementSettings& settings) {
  return body.velocity.norm() > settings.restLinearSpeed ||
         std::abs(body.angularVelocity) > settings.restAngularSpeed;
}

void trackDrift(const Body& body, bool driftStarts, BodyTrack& track, double& drift) {
  if (driftStarts) track.driftOrigin = body.position;
  const double displacement = (body.position - track.driftOrigin).norm();
  drift = std::isnan(drift) ? displacement : std::max(drift, displacement);
}

/// Slide, bounce, rest and drift after one step.
void observe(Run& run, long step, const Agreement& agreement) {
  const std::vector<Body>& bodies = run.simulation->bodies();
  const std::vector<bool> touching = touchingBodies(*run.simulation);
  const bool driftStarts =
      !run.driftStarted && (step + 1) * agreement.dt >= agreement.settings.driftStart;
  run.driftStarted = run.driftStarted || driftStarts;
  bool moving = false;
  for (size_t k = 0; k < run.figures.bodies.size(); ++k) {
    BodyFigures& figures = run.figures.bodies[k];
    BodyTrack& track = run.tracks[k];
    const Body& body = bodies[figures.body];
    if (touching[figures.body]) {
      figures.slideDistance += (body.position - track.previousPosition).norm();
    }
    track.previousPosition = body.position;
    trackBounce(body, agreement.settings.bounceSpeed, track.hasFallen, figures);
    if (run.driftStarted) trackDrift(body, driftStarts, track, run.figures.drift);
    moving = moving || isMoving(body, agreement.settings);
  }
  if (moving) run.lastMovingStep = step;
}

/// Position and angle differences against the reference after one step.
void compare(Run& run, const Simulation& reference) {
  for (BodyFigures& figures : run.figures.bodies) {
    const Body& body = run.simulation->bodies()[figures.body];
    const Body& other = reference.bodies()[figures.body];
    figures.finalPositionDifference = (body.position - other.position).norm();
    figures.finalAngleDifference = std::abs(body.angle - other.angle);
    figures.largestPositionDifference =
        std::max(figures.largestPositionDifference, figures.finalPositionDifference);
    figures.largestAngleDifference =
        std::max(figures.largestAngleDifference, figures.finalAngleDifference);
  }
}

/// One step of the run; a method whose solve fails stops, and the failure is kept in its
/// figures. A body that overflows (NonFiniteState) ends the whole measure: no figure of it would
/// be finite.
bool advance(Run& run) {
  if (!run.figures.failure.empty()) return false;
  try {
    run.simulation->step();
  } catch (const NonFiniteState&) {
    throw;
  } catch (const std::exception& error) {
    run.figures.failure = error.what();
    return false;
  }
  ++run.figures.stepsRun;
  return true;
}

MethodFigures finishRun(Run& run, double dt) {
  for (BodyFigures& figures : run.figures.bodies) {
    figures.finalHeight = run.simulation->bodies()[figures.body].position.y();
  }
  if (run.figures.failure.empty() && run.lastMovingStep < run.figures.stepsRun - 1) {
    run.figures.timeToRest = (run.lastMovingStep + 1) * dt;
  }
  return std::move(run.figures);
}

}  // namespace

const MethodFigures& Agreement::method(const std::string& name) const {
  for (const MethodFigures& figures : methods) {
    if (figures.method == name) return figures;
  }
  throw std::out_of_range("no method '" + name + "' in the agreement of " + scene);
}

Agreement measureAgreement(const Scene& scene, std::vector<std::unique_ptr<Simulation>> simulations,
                           const AgreementSettings& settings) {
  Agreement agreement{scene.name, scene.steps, scene.world.dt, settings, {}};
  std::vector<Run> runs;
  for (auto& simulation : simulations) runs.push_back(startRun(std::move(simulation)));
  for (long step = 0; step < scene.steps; ++step) {
    for (Run& run : runs) {
      if (advance(run)) observe(run, step, agreement);
    }
    for (size_t i = 1; i < runs.size(); ++i) {
      if (runs[i].figures.stepsRun == step + 1 && runs[0].figures.stepsRun == step + 1) {
        compare(runs[i], *runs[0].simulation);
      }
    }
  }
  for (Run& run : runs) agreement.methods.push_back(finishRun(run, scene.world.dt));
  return agreement;
}

Agreement measureAgreement(const Scene& scene, const std::vector<std::string>& solvers,
                           const AgreementSettings& settings) {
  std::vector<std::unique_ptr<Simulation>> simulations;
  simulations.push_back(std::make_unique<Box2dSimulation>(scene));
  for (const std::string& solver : solvers) {
    if (solver == kBox2dName) continue;
    Scene variant = scene;
    variant.solver = solver;
    simulations.push_back(makeSimulation(variant));
  }
  return measureAgreement(scene, std::move(simulations), settings);
}

namespace {

constexpr const char* kDash = "—";

/// Lengths and times to a tenth of a millimetre (or millisecond).
std::string fixed(double value) {
  if (std::isnan(value)) return kDash;
  char text[32];
  std::snprintf(text, sizeof text, "%.4f", value);
  return text;
}

/// Differences span many decades (1e-7 in free fall, 1e-1 in a collapse): three figures.
std::string scientific(double value) {
  if (std::isnan(value)) return kDash;
  char text[32];
  std::snprintf(text, sizeof text, "%.2e", value);
  return text;
}

std::string row(const std::vector<std::string>& cells) {
  std::string line = "|";
  for (const std::string& cell : cells) line += " " + cell + " |";
  return line + "\n";
}

std::string header(const std::vector<std::string>& titles) {
  return row(titles) + row(std::vector<std::string>(titles.size(), "---"));
}

/// A reference row shows no differences: it is what the others are measured against.
std::string differenceCell(double value, bool isReference) {
  return isReference ? kDash : scientific(value);
}

std::string summaryRow(const MethodFigures& figures, bool isReference) {
  double position = 0.0;
  double angle = 0.0;
  for (const BodyFigures& body : figures.bodies) {
    position = std::max(position, body.largestPositionDifference);
    angle = std::max(angle, body.largestAngleDifference);
  }
  return row({figures.method, fixed(figures.timeToRest), scientific(figures.drift),
              differenceCell(position, isReference), differenceCell(angle, isReference)});
}

std::string bodyRow(const std::string& method, const BodyFigures& body, bool isReference) {
  return row({method, fixed(body.finalHeight), fixed(body.slideDistance), fixed(body.bounceApex),
              differenceCell(body.finalPositionDifference, isReference),
              differenceCell(body.largestPositionDifference, isReference),
              differenceCell(body.finalAngleDifference, isReference),
              differenceCell(body.largestAngleDifference, isReference)});
}

std::string bodyTable(const Agreement& agreement, size_t k) {
  std::string text = "\n## " + agreement.methods[0].bodies[k].name + "\n\n";
  text +=
      header({"method", "final height (m)", "slide (m)", "apex after first bounce (m)",
              "Δposition end (m)", "Δposition max (m)", "Δangle end (rad)", "Δangle max (rad)"});
  for (size_t i = 0; i < agreement.methods.size(); ++i) {
    text += bodyRow(agreement.methods[i].method, agreement.methods[i].bodies[k], i == 0);
  }
  return text;
}

}  // namespace

std::string agreementSummary(const Agreement& agreement) {
  std::ostringstream intro;
  intro << "# Agreement with Box2D: " << agreement.scene << "\n\n"
        << agreement.steps << " steps of " << agreement.dt << " s. Differences are |ours − Box2D| "
        << "at the same step. At rest: every speed under " << agreement.settings.restLinearSpeed
        << " m/s and " << agreement.settings.restAngularSpeed << " rad/s. Drift: largest "
        << "displacement since t = " << agreement.settings.driftStart << " s.\n\n";
  std::string text = intro.str();
  text += header(
      {"method", "time to rest (s)", "drift (m)", "largest Δposition (m)", "largest Δangle (rad)"});
  for (size_t i = 0; i < agreement.methods.size(); ++i) {
    text += summaryRow(agreement.methods[i], i == 0);
  }
  for (const MethodFigures& figures : agreement.methods) {
    if (figures.failure.empty()) continue;
    text += "\n**" + figures.method + "** stopped after " + std::to_string(figures.stepsRun) +
            " steps: " + figures.failure + "\n";
  }
  return text;
}

std::string agreementTable(const Agreement& agreement) {
  std::string text = agreementSummary(agreement);
  if (agreement.methods.empty()) return text;
  for (size_t k = 0; k < agreement.methods[0].bodies.size(); ++k) {
    text += bodyTable(agreement, k);
  }
  return text;
}

}  // namespace impulse2d
