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
      {"sequential − warm starting", "sequential", {"solver.warm_starting=false"}},
      {"sequential − accumulation",
       "sequential",
       {"solver.accumulate_impulses=false", "solver.warm_starting=false"}},
      {"reference", "reference", {}},
      {"soft step", "soft_step", {}},
      {"box2d", kBox2dName, {}},
  };
}

std::vector<Method> extraMethods() {
  return {
      {"sequential − accumulation + 4 substeps",
       "sequential",
       {"solver.accumulate_impulses=false", "solver.warm_starting=false", "world.substeps=4"}},
      {"sequential + 4 substeps", "sequential", {"world.substeps=4"}},
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
      {"micro − pairs", "micro", {"solver.pair_impulses=false", "solver.pair_moves=false"}},
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
  scene.world.sleeping = false;
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
  return {std::numeric_limits<double>::infinity(), true, reason};
}

}  // namespace

Outcome runStress(const StressScene& stress, const Method& method, double knob,
                  const StepWatcher& watch) {
  const Scene scene = sceneFor(stress, method, knob);
  std::unique_ptr<Simulation> simulation = makeSimulation(scene);
  std::unique_ptr<Probe> probe = stress.probe(scene);
  probe->observe(*simulation);
  if (watch) watch(*simulation);
  for (long step = 0; step < scene.steps; ++step) {
    intervene(stress, *simulation);
    try {
      simulation->step();
    } catch (const NonFiniteState& error) {
      return stoppedAt(error.what());  // names the body and the step
    } catch (const std::exception& error) {
      return stoppedAt(std::string(error.what()) + " at step " + std::to_string(step + 1));
    }
    probe->observe(*simulation);
    if (watch) watch(*simulation);
  }
  const double measure = probe->measure();
  return {measure, measure > stress.criterion.limit, ""};
}

}  // namespace impulse2d::stress
