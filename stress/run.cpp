// Deterministic stress runs of one method (run.h).
#include "run.h"

#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "impulse2d/box2d/box2d_simulation.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/world.h"

namespace impulse2d::stress {

std::vector<Method> baseMethods() {
  return {
      {"micro", "micro", {}},
      // The lecture's two bounce fixes, shown on the lecture's method: warm starting applies the
      // last step's resting impulse before a contact is looked at and changes which fix a bouncy
      // stack needs (docs/micro-collisions.md).
      {"micro − acceleration removal",
       "micro",
       {"solver.remove_acceleration_velocity=false", "solver.warm_starting=false"}},
      {"micro − low-speed restitution",
       "micro",
       {"solver.lower_restitution_at_low_speed=false", "solver.warm_starting=false"}},
      {"micro − friction", "micro", {"solver.friction=false"}},
      {"sequential", "sequential", {}},
      {"sequential − warm starting", "sequential", {"solver.impulses=accumulated"}},
      {"sequential − accumulation", "sequential", {"solver.impulses=clamped_each"}},
      {"reference", "reference", {}},
      {"soft step", "soft_step", {}},
      {"box2d", kBox2dName, {}},
  };
}

std::vector<Method> extraMethods() {
  return {
      {"sequential − accumulation + 4 substeps",
       "sequential",
       {"solver.impulses=clamped_each", "world.substeps=4"}},
      {"sequential + 4 substeps", "sequential", {"world.substeps=4"}},
      // The text's sweeps: without the conjugate gradient's push between them.
      {"sequential − conjugate gradient", "sequential", {"solver.conjugate_gradient=false"}},
      {"sequential + speculative contacts", "sequential", {"world.speculative_contacts=true"}},
      {"sequential − bias", "sequential", {"solver.penetration_bias=false"}},
      {"soft step − speculative contacts", "soft_step", {"solver.speculative_contacts=false"}},
      // Without continuous collision: the discrete methods' tunnelling and its two older cures.
      {"sequential − continuous", "sequential", {"world.continuous=false"}},
      {"sequential − continuous + speculative contacts",
       "sequential",
       {"world.continuous=false", "world.speculative_contacts=true"}},
      {"sequential − continuous + 4 substeps",
       "sequential",
       {"world.continuous=false", "world.substeps=4"}},
      {"soft step − speculative contacts − continuous",
       "soft_step",
       {"solver.speculative_contacts=false", "world.continuous=false"}},
      {"soft step, 16 substeps at 240 Hz",
       "soft_step",
       {"solver.substeps=16", "solver.contact_hertz=240"}},
      // The two points of a flat contact resolved together, impulses and moves; off, one point
      // at a time as the lecture does (docs/micro-collisions.md).
      {"micro − pairs", "micro", {"solver.impulses=point_totals", "solver.block_moves=false"}},
      {"micro − both bounce fixes",
       "micro",
       {"solver.remove_acceleration_velocity=false", "solver.lower_restitution_at_low_speed=false",
        "solver.warm_starting=false"}},
  };
}

Method findMethod(const std::string& label) {
  for (const std::vector<Method>& methods : {baseMethods(), extraMethods()}) {
    for (const Method& method : methods) {
      if (method.label == label) return method;
    }
  }
  throw std::invalid_argument("unknown stress method '" + label + "'");
}

std::string slug(const std::string& label) {
  std::string out;
  for (size_t i = 0; i < label.size(); ++i) {
    const unsigned char c = label[i];
    if (std::isalnum(c)) {
      out += char(c);
    } else if (label.compare(i, 3, "−") == 0) {
      out += "no";
      i += 2;
    } else if (c == '+') {
      out += "with";
    } else if (!out.empty() && out.back() != '-') {
      out += '-';
    }
  }
  return out;
}

bool canRun(const StressScene& stress, const Method& method) {
  return stress.interventions.empty() || method.solver != kBox2dName;
}

Scene sceneFor(const StressScene& stress, const Method& method, double knob) {
  Scene scene = stress.build(knob);
  scene.solver = method.solver;
  scene.world.sleep = Sleep::Off;
  for (const std::string& setting : method.settings) applySetting(scene, setting);
  return scene;
}

namespace {

void intervene(const StressScene& stress, Simulation& simulation) {
  for (const Intervention& intervention : stress.interventions) {
    if (intervention.step != simulation.stepCount()) continue;
    intervention.apply(dynamic_cast<World&>(simulation).bodies());
  }
}

Outcome stoppedAt(const std::string& reason) {
  Outcome outcome;
  outcome.measure = std::numeric_limits<double>::infinity();
  outcome.failed = true;
  outcome.stopped = reason;
  return outcome;
}

/// Whether a structure's run is over after this step: failed (or collapsed), or bounded from the
/// horizon's least steps on; sets the outcome's figures and why it ended.
bool structureEnded(const StressScene& stress, double knob, RunLength length, const Probe& probe,
                    const StructureWatch& watch, long step, Outcome& outcome) {
  const Horizon& horizon = stress.horizon;
  const double limit = stress.criterion.limit;
  const double endAt = length == RunLength::UntilCollapsed ? kCollapseFactor * limit : limit;
  outcome.structure = watch.figures();
  if (outcome.ended.empty() && probe.measure() > limit) outcome.ended = "limit";
  if (outcome.ended.empty() && outcome.structure.sink > horizon.sinkLimit(knob))
    outcome.ended = "sink";
  if (!outcome.ended.empty() && outcome.failedAt == 0.0) outcome.failedAt = outcome.seconds;
  if (probe.measure() > endAt || (outcome.ended == "sink" && length == RunLength::UntilFailed))
    return true;
  if (!watch.windowEnded() || step < horizon.least) return false;
  if (outcome.structure.bounded) {
    if (outcome.ended.empty()) outcome.ended = "bounded";
    return true;
  }
  if (step < horizon.most) return false;
  // Still moving at the end: it fails if its creep, kept up for as long again, would carry it
  // sideways past the scene's limit; a slower drift is reported, not failed.
  const double projected = outcome.structure.drift + outcome.structure.creep * outcome.seconds;
  if (outcome.ended.empty()) outcome.ended = projected > horizon.creepLimit ? "creep" : "unbounded";
  return true;
}

}  // namespace

Outcome runStress(const StressScene& stress, const Method& method, double knob,
                  const StepWatcher& watch, RunLength length) {
  const Scene scene = sceneFor(stress, method, knob);
  std::unique_ptr<Simulation> simulation = makeSimulation(scene);
  std::unique_ptr<Probe> probe = stress.probe(scene);
  const bool structure = stress.horizon.least > 0;
  StructureWatch structureWatch(structure ? stress.horizon.window : 1);
  const long steps = structure ? stress.horizon.most : scene.steps;
  probe->observe(*simulation);
  if (structure) structureWatch.observe(*simulation);
  if (watch) watch(*simulation);
  Outcome outcome;
  for (long step = 1; step <= steps; ++step) {
    intervene(stress, *simulation);
    try {
      simulation->step();
    } catch (const NonFiniteState& error) {
      return stoppedAt(error.what());  // names the body and the step
    } catch (const std::exception& error) {
      return stoppedAt(std::string(error.what()) + " at step " + std::to_string(step));
    }
    probe->observe(*simulation);
    if (watch) watch(*simulation);
    outcome.seconds = double(step) * scene.world.dt;
    if (!structure) continue;
    structureWatch.observe(*simulation);
    if (structureEnded(stress, knob, length, *probe, structureWatch, step, outcome)) break;
  }
  outcome.measure = probe->measure();
  outcome.failed = outcome.measure > stress.criterion.limit || outcome.ended == "sink" ||
                   outcome.ended == "creep";
  return outcome;
}

}  // namespace impulse2d::stress
