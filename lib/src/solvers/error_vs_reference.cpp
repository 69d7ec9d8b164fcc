// The reference watching a method: the exact answer of the method's own pre-solve state, then the
// method's answer, then the two compared.
#include "impulse2d/solvers/error_vs_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "impulse2d/simulation.h"

namespace impulse2d {

double relativeImpulseError(const Eigen::VectorXd& impulses, const Eigen::VectorXd& exact) {
  const double size = exact.norm();
  if (!(size > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return (impulses - exact).norm() / size;
}

double energyNormError(const Eigen::VectorXd& impulses, const Eigen::VectorXd& exact,
                       const Eigen::SparseMatrix<double>& delassus) {
  const double size = exact.dot(delassus * exact);
  if (!(size > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  const Eigen::VectorXd difference = impulses - exact;
  return std::sqrt(std::max(0.0, difference.dot(delassus * difference)) / size);
}

Eigen::VectorXd appliedImpulses(const std::vector<Manifold>& manifolds) {
  int count = 0;
  for (const Manifold& manifold : manifolds) count += manifold.pointCount;
  Eigen::VectorXd impulses(2 * count);
  int row = 0;
  for (const Manifold& manifold : manifolds) {
    for (int i = 0; i < manifold.pointCount; ++i, row += 2) {
      impulses(row) = manifold.points[i].normalImpulse;
      impulses(row + 1) = manifold.points[i].tangentImpulse;
    }
  }
  return impulses;
}

ReferenceSolverSettings referenceSettingsFor(const std::string& method,
                                             const SolverSettings& settings) {
  ReferenceSolverSettings reference = settings.reference;
  if (method == "sequential") reference.targets = settings.sequential.targets;
  if (method == "micro") {
    reference.targets.penetrationBias = false;
    reference.targets.restitutionThreshold = settings.micro.restitutionThreshold;
  }
  return reference;
}

std::unique_ptr<ErrorVsReference> makeWatchedSolver(const std::string& method,
                                                    const SolverSettings& settings) {
  return std::make_unique<ErrorVsReference>(makeSolver(method, settings),
                                            referenceSettingsFor(method, settings));
}

// The world's stages, passed through to the method; finding the contacts and storing the
// impulses are where the watcher looks.
class ErrorVsReference::WatchingStages : public StepStages {
 public:
  WatchingStages(StepStages& stages, ErrorVsReference& watcher)
      : stages_(stages), watcher_(watcher) {}
  StepContext findContacts(const ContactFinding& finding) override {
    context_.emplace(stages_.findContacts(finding));
    watcher_.solveExactly(*context_);
    return *context_;
  }
  void integrateVelocities() override { stages_.integrateVelocities(); }
  void integratePositions() override { stages_.integratePositions(); }
  void clearForces() override { stages_.clearForces(); }
  void refreshCaches() override { stages_.refreshCaches(); }
  void stopAtNonFiniteBody() override { stages_.stopAtNonFiniteBody(); }
  void storeImpulses() override {
    if (context_) watcher_.measure(*context_);
    stages_.storeImpulses();
  }

 private:
  StepStages& stages_;
  ErrorVsReference& watcher_;
  std::optional<StepContext> context_;
};

void ErrorVsReference::step(StepStages& stages) {
  WatchingStages watching(stages, *this);
  method_->step(watching);
}

// The copy gets the velocity update every method starts from (the world's, or soft step's spread
// over its substeps). A solve whose exact answer the reference cannot find is recorded as such,
// and the method's run goes on: the reference only watches it here.
void ErrorVsReference::solveExactly(const StepContext& context) {
  std::vector<Body> bodies = context.bodies;
  std::vector<Manifold> manifolds = context.manifolds;
  for (Body& body : bodies) {
    if (body.isAwake()) body.integrateVelocity(context.gravity, context.dt);
  }
  error_ = ReferenceError{};
  error_.step = static_cast<long>(errors_.size());
  exact_.resize(0);
  try {
    stopAtNonFiniteBody(bodies, context.gravity, error_.step, name());
    exact_ = reference_.exactImpulses({bodies, manifolds, context.dt});
  } catch (const std::runtime_error& failure) {  // ReferenceSolveFailure or NonFiniteState
    error_.noExactAnswer = failure.what();
  }
}

void ErrorVsReference::measure(const StepContext& context) {
  ReferenceError error = error_;
  const Eigen::VectorXd impulses = appliedImpulses(context.manifolds);
  error.points = static_cast<int>(impulses.size() / 2);
  if (exact_.size() == 0) {
    error.impulseError = std::numeric_limits<double>::quiet_NaN();
    error.velocityError = error.impulseError;
    if (!error.noExactAnswer.empty()) error.violation = error.impulseError;
  } else {
    error.impulseError = relativeImpulseError(impulses, exact_);
    error.velocityError = energyNormError(impulses, exact_, reference_.delassusMatrix());
    error.violation = reference_.residual(impulses);
  }
  errors_.push_back(error);
}

}  // namespace impulse2d
