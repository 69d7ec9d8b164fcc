// Running a stress scene with one contact method: the methods compared (each a solver and the
// settings that turn its fixes on or off), and one deterministic run that reports its figure,
// whether it failed, and where and when it blew up if it did.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stress_scene.h"

namespace impulse2d::stress {

/// A contact method as the catalogue compares it: a solver plus scene-file overrides.
struct Method {
  std::string label;  ///< as tables and charts name it, e.g. "sequential − warm starting"
  std::string solver;
  std::vector<std::string> settings;  ///< "world.key=value" / "solver.key=value", as `i2d --set`
};

/// Every method searched on every scene: each solver with its defaults, then with each fix off.
std::vector<Method> baseMethods();
/// The fixes a scene may add (StressScene::fixes names them by label).
std::vector<Method> extraMethods();
/// The method of that label among both lists; throws std::invalid_argument if there is none.
Method findMethod(const std::string& label);
/// A file-name safe form of a label: "sequential − warm starting" -> "sequential-no-warm-starting".
std::string slug(const std::string& label);

/// Whether the method can run the scene: Box2D cannot take the scene's mid-run interventions.
bool canRun(const StressScene& stress, const Method& method);

/// What a run gave.
struct Outcome {
  double measure = 0.0;  ///< the criterion's figure; +inf when the run stopped early
  bool failed = false;   ///< measure above the criterion's limit, or stopped early
  /// Empty, or why the run stopped: "body NAME became non-finite at step N (solver S)", a
  /// solver's error.
  std::string stopped;
};

/// The scene at `knob`, set up for the method (solver, overrides, sleeping off).
Scene sceneFor(const StressScene& stress, const Method& method, double knob);

/// Called after the start and after every step, e.g. to write frames.
using StepWatcher = std::function<void(const Simulation&)>;

/// Runs the scene at `knob` with the method for its steps. Every step the bodies are checked: at
/// the first non-finite one the run stops and says so instead of carrying NaN on.
Outcome runStress(const StressScene& stress, const Method& method, double knob,
                  const StepWatcher& watch = {});

}  // namespace impulse2d::stress
