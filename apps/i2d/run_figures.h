// The figures of a run, every step: energies, contacts and penetration, for the plots
// (--plots) and the viewer page's table. And the events of one traced step, for its plot.
#pragma once

#include <string>
#include <vector>

#include "impulse2d/render/viewer.h"
#include "impulse2d/simulation.h"
#include "impulse2d/solver.h"

namespace i2d {

struct StepFigures {
  long step = 0;
  double time = 0.0;         ///< s
  double kinetic = 0.0;      ///< J
  double potential = 0.0;    ///< J
  int contacts = 0;          ///< contact points
  double penetration = 0.0;  ///< m, the largest
  /// N: the applied loads on the dynamic bodies (the sum of their magnitudes) in the last step,
  /// and the friction force their contacts answered with (the sum over those contacts of
  /// |Σ λt| / dt): the textbook picture of static friction giving way.
  double appliedForce = 0.0;
  double frictionForce = 0.0;
};

/// The figures of the simulation as it stands.
StepFigures measureStep(const impulse2d::Simulation& simulation);

/// Whether any body of the simulation carries an applied load.
bool hasLoads(const impulse2d::Simulation& simulation);

/// The rows of the viewer's table for the steps of the frames written (figures by step).
impulse2d::render::FigureTable figureTable(const std::vector<StepFigures>& figures,
                                           const std::vector<long>& frameSteps);

/// The velocity events of one step, as a traced step's solver reports them.
class EventLog : public impulse2d::SolverObserver {
 public:
  void onSolverEvent(const impulse2d::SolverEvent& event, const std::vector<impulse2d::Body>&,
                     const std::vector<impulse2d::Manifold>&) override;
  /// |the velocity change wanted| (m/s) at each velocity event, in order: the error the event
  /// removes.
  const std::vector<double>& velocityErrors() const { return errors_; }
  /// The iteration (sweep, or impulse count for micro) of each of those events.
  const std::vector<int>& iterations() const { return iterations_; }

 private:
  std::vector<double> errors_;
  std::vector<int> iterations_;
};

}  // namespace i2d
