// The solver factory: solver names -> solvers.
#include "impulse2d/solver.h"

#include <stdexcept>

#include "impulse2d/solvers/micro_collision.h"
#include "impulse2d/solvers/reference_solver.h"
#include "impulse2d/solvers/sequential_impulses.h"
#include "impulse2d/solvers/soft_step.h"

namespace impulse2d {

std::vector<std::string> solverNames() {
  return {"micro", "sequential", "reference", "soft_step"};
}

std::unique_ptr<ContactSolver> makeSolver(const std::string& name, const SolverSettings& settings) {
  if (name == "micro") return std::make_unique<MicroCollisionSolver>(settings.micro);
  if (name == "sequential") return std::make_unique<SequentialImpulseSolver>(settings.sequential);
  if (name == "reference") return std::make_unique<ReferenceSolver>(settings.reference);
  if (name == "soft_step") return std::make_unique<SoftStepSolver>(settings.softStep);
  std::string known;
  for (const std::string& candidate : solverNames()) {
    known += (known.empty() ? "" : ", ") + candidate;
  }
  throw std::invalid_argument("unknown solver '" + name + "' (known: " + known + ")");
}

}  // namespace impulse2d
