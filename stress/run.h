// Running a stress scene with one contact method: the methods compared (each a solver and the
// settings that turn its fixes on or off), and one deterministic run that reports its figure,
// whether it failed, and where and when it blew up if it did.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "probes.h"
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
  /// s. Simulated time the run lasted (a structure's run ends early once failed or bounded).
  double seconds = 0.0;
  /// s. When a structure's run first failed (its figure over the limit, or its sink); 0 if not.
  double failedAt = 0.0;
  /// Why a structure's run ended: "limit", "sink", "bounded"; at the horizon's end still growing,
  /// "creep" when its creep kept up as long again would carry it sideways past the scene's creep
  /// limit (a failure), else "unbounded"; empty for other scenes and for a run that stopped.
  std::string ended;
  /// A structure's slow figures; zero for other scenes.
  StructureFigures structure;
};

/// How far past its failure a structure's run goes.
enum class RunLength {
  UntilFailed,     ///< ends at the failure: all a search needs to know
  UntilCollapsed,  ///< runs on past its limit to kCollapseFactor times it, to see how far it sways
};

/// A structure whose figure exceeds its limit this many times has collapsed (half a box for the
/// 10 cm displacement limit): nothing more is learned by watching it.
constexpr double kCollapseFactor = 5.0;

/// The scene at `knob`, set up for the method (solver, overrides, sleeping off).
Scene sceneFor(const StressScene& stress, const Method& method, double knob);

/// Called after the start and after every step, e.g. to write frames.
using StepWatcher = std::function<void(const Simulation&)>;

/// Runs the scene at `knob` with the method for its steps, or a structure over its horizon.
/// Every step the bodies are checked: at the first non-finite one the run stops and says so
/// instead of carrying NaN on. A structure's figures (displacement, deepest contact) never fall,
/// so its run ends once the figure exceeds the limit (or kCollapseFactor times it) or its sink
/// exceeds the sink limit, or at a window's end from `least` on once its motion is bounded.
Outcome runStress(const StressScene& stress, const Method& method, double knob,
                  const StepWatcher& watch = {}, RunLength length = RunLength::UntilFailed);

}  // namespace impulse2d::stress
