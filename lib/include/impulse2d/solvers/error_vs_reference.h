// Each method's error against the exact answer of the same step. A method's solver is wrapped:
// at every step the global reference (reference_solver.h) solves a copy of the state the method
// starts from, given the step's velocity update, exactly; the method runs its own step, and the
// two answers are compared point by point. The method's run is unchanged: the reference only
// ever solves copies.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "impulse2d/solver.h"
#include "impulse2d/solvers/reference_solver.h"

namespace impulse2d {

/// One step's figures. Both are 0 for the exact answer.
struct ReferenceError {
  long step = 0;   ///< 0-based solve count (one per substep)
  int points = 0;  ///< contact points solved
  /// ‖λ − λ*‖ / ‖λ*‖ over every point's (λn, λt); NaN when nothing touches or λ* = 0.
  double impulseError = 0.0;
  /// The same in the energy norm, sqrt(dᵀW d / λ*ᵀW λ*) with d = λ − λ* and W the Delassus
  /// matrix: the error of the velocity changes the impulses cause. A flat contact's two corners
  /// can share a load in many ways that all cause the same velocities (a stack is statically
  /// indeterminate); this measure does not see those differences, the impulse error does.
  double velocityError = 0.0;
  /// The worst violated condition of the method's impulses on the same problem (penetrating
  /// velocity, friction outside the cone, friction short of the limit or pushing along while
  /// sliding), in N s relative to the step's impulse scale: the reference's own residual measure.
  double violation = 0.0;
  /// Why the reference found no exact answer of this solve's problem (empty when it did); the
  /// errors above are then NaN. A method's biased targets on a statically indeterminate pile can
  /// ask for an answer that does not exist (docs/global-reference.md).
  std::string noExactAnswer;
};

/// ‖λ − λ*‖ / ‖λ*‖; NaN when ‖λ*‖ = 0 (no exact impulse to be relative to).
double relativeImpulseError(const Eigen::VectorXd& impulses, const Eigen::VectorXd& exact);

/// sqrt(dᵀW d / λ*ᵀW λ*), d = λ − λ*; NaN when λ*ᵀW λ* = 0.
double energyNormError(const Eigen::VectorXd& impulses, const Eigen::VectorXd& exact,
                       const Eigen::SparseMatrix<double>& delassus);

/// The impulses (λn, λt) the solver left on the points, in the reference's order.
Eigen::VectorXd appliedImpulses(const std::vector<Manifold>& manifolds);

/// The reference settings that pose the method's own problem: the method's bias and bounce
/// targets (sequential: its ContactTargetSettings; micro: no bias, its bounce limit), the rest
/// from settings.reference.
ReferenceSolverSettings referenceSettingsFor(const std::string& method,
                                             const SolverSettings& settings);

/// `method` (a solver name) wrapped so the reference watches it.
class ErrorVsReference;
std::unique_ptr<ErrorVsReference> makeWatchedSolver(const std::string& method,
                                                    const SolverSettings& settings);

/// A method watched by the reference: each step's impulses are compared with the exact ones.
class ErrorVsReference : public ContactSolver {
 public:
  /// `method` watched by a reference solver with `reference` settings.
  ErrorVsReference(std::unique_ptr<ContactSolver> method, const ReferenceSolverSettings& reference)
      : method_(std::move(method)), reference_(reference) {}

  std::string name() const override { return method_->name(); }
  /// The method's own step, watched through its stages: once the contacts are found, a copy of
  /// the bodies is given this substep's velocity update and solved exactly; once the method
  /// stores its impulses, they are compared with the exact ones. Only copies are solved.
  void step(StepStages& stages) override;
  SolveReport lastReport() const override { return method_->lastReport(); }

  /// One entry per step (or substep) so far.
  const std::vector<ReferenceError>& errors() const { return errors_; }
  /// the watched method
  ContactSolver& method() { return *method_; }

 private:
  class WatchingStages;
  /// The exact impulses of the state the method starts from, after the velocity update.
  void solveExactly(const StepContext& context);
  /// The method's impulses against the exact ones.
  void measure(const StepContext& context);

  std::unique_ptr<ContactSolver> method_;
  ReferenceSolver reference_;
  ReferenceError error_;   ///< this step's, filled as the step goes
  Eigen::VectorXd exact_;  ///< this step's exact impulses, empty when there are none
  std::vector<ReferenceError> errors_;
};

}  // namespace impulse2d
