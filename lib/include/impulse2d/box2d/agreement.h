// How closely our contact methods agree with Box2D on one scene: every method runs the scene in
// lockstep with Box2D, and per body we measure how far its position and angle stray from Box2D's
// at the same step, beside figures a student can check by eye or by hand (resting height, slide
// distance, bounce apex, time to come to rest, drift of a stack). `i2d agree` and the reports
// print agreementTable(measureAgreement(scene, solvers)).
#pragma once

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "impulse2d/scene/scene.h"
#include "impulse2d/simulation.h"

namespace impulse2d {

/// The thresholds behind the scene-level figures.
struct AgreementSettings {
  /// m/s. A body moving slower than this is at rest: Box2D's linear sleep tolerance.
  double restLinearSpeed = 0.01;
  /// rad/s. A body turning slower than this is at rest: Box2D's angular sleep tolerance (2°/s).
  double restAngularSpeed = 2.0 * kPi / 180.0;
  /// m/s. A body that fell faster than this and then rises faster than this has bounced; slower
  /// motion is the jitter of a resting contact, not a bounce.
  double bounceSpeed = 0.1;
  /// s. Drift is measured from the positions at this time, once a stack has settled.
  double driftStart = 1.0;
};

/// Not measured (no bounce, never at rest, run too short): shown as "—".
inline constexpr double kNotMeasured = std::numeric_limits<double>::quiet_NaN();

/// One dynamic body in one method.
struct BodyFigures {
  int body = -1;  ///< index into the scene's bodies
  /// the body's name in the scene
  std::string name;
  double finalHeight = 0.0;    ///< m, height of the centre of mass after the last step
  double slideDistance = 0.0;  ///< m, path of the centre of mass over the steps it was touching
  /// m, the highest the centre of mass rose after its first bounce; kNotMeasured without one.
  double bounceApex = kNotMeasured;
  double finalPositionDifference = 0.0;    ///< m, |x − x_Box2D| after the last step
  double largestPositionDifference = 0.0;  ///< m, its largest value over the run
  double finalAngleDifference = 0.0;       ///< rad, |θ − θ_Box2D| after the last step
  double largestAngleDifference = 0.0;     ///< rad, its largest value over the run
};

/// One method over the whole run.
struct MethodFigures {
  /// the solver name, or "box2d"
  std::string method;
  std::vector<BodyFigures> bodies;  ///< the dynamic bodies, in scene order
  /// s. The first time after which every dynamic body stays at rest; kNotMeasured if one still
  /// moves at the end.
  double timeToRest = kNotMeasured;
  /// m. Largest displacement of any dynamic body since driftStart; kNotMeasured if the run ends
  /// before it.
  double drift = kNotMeasured;
  /// Empty, or why the method stopped (the reference solver missing its tolerance, say): its
  /// figures then cover the stepsRun steps before.
  std::string failure;
  /// steps the method ran (all of them unless it failed)
  long stepsRun = 0;
};

/// How far each method strays from Box2D over one scene's run (`i2d agree`).
struct Agreement {
  /// the scene's name
  std::string scene;
  /// steps each method ran
  long steps = 0;
  /// s, the time step
  double dt = 0.0;
  /// the thresholds the figures were measured with
  AgreementSettings settings;
  /// methods[0] is the reference, Box2D; its differences are zero.
  std::vector<MethodFigures> methods;

  /// The figures of the method of that name; throws std::out_of_range if it did not run.
  const MethodFigures& method(const std::string& name) const;
};

/// Runs the scene for scene.steps in Box2D and in each of our solvers, side by side.
Agreement measureAgreement(const Scene& scene, const std::vector<std::string>& solvers,
                           const AgreementSettings& settings = {});

/// Runs the given simulations of the scene side by side; simulations[0] is the reference the
/// others are measured against.
Agreement measureAgreement(const Scene& scene, std::vector<std::unique_ptr<Simulation>> simulations,
                           const AgreementSettings& settings = {});

/// The figures as Markdown: the summary table, then one table per dynamic body.
std::string agreementTable(const Agreement& agreement);

/// The summary table alone (time to rest, drift, largest differences), for scenes of many bodies.
std::string agreementSummary(const Agreement& agreement);

}  // namespace impulse2d
