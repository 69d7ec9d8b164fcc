// `i2d run SCENE --error-vs-reference FILE`: the scene's method watched by the global reference;
// per step the relative impulse error and the worst violation go to FILE, a summary to stdout.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "commands.h"
#include "failures.h"
#include "impulse2d/box2d/box2d_simulation.h"
#include "impulse2d/solvers/error_vs_reference.h"
#include "impulse2d/world.h"
#include "output_directories.h"
#include "output_file.h"
#include "scene_setup.h"

namespace i2d {
namespace {

using impulse2d::ReferenceError;

/// One row per velocity solve (substeps solve several times a step), at the solve's time;
/// exact_answer says whether the reference found one (without it the row has no errors). The
/// file appears only when complete (OutputFile).
void writeErrors(const std::string& path, const std::vector<ReferenceError>& errors,
                 double solveDt) {
  OutputFile file(path);
  std::ostream& out = file.stream();
  out << "solve,t,points,impulse_error,velocity_error,violation,exact_answer\n";
  for (const ReferenceError& error : errors) {
    out << error.step + 1 << ',' << double(error.step + 1) * solveDt << ',' << error.points << ','
        << error.impulseError << ',' << error.velocityError << ',' << error.violation << ','
        << (error.noExactAnswer.empty() ? "found" : "none") << '\n';
  }
  file.commit();
}

/// "median M, mean A, largest L" of the finite values (the steps with contact impulses).
std::string statistics(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(),
                              [](double value) { return !std::isfinite(value); }),
               values.end());
  if (values.empty()) return "no steps with contact impulses";
  std::sort(values.begin(), values.end());
  double sum = 0.0;
  for (double value : values) sum += value;
  std::ostringstream text;
  text << "median " << values[values.size() / 2] << ", mean " << sum / double(values.size())
       << ", largest " << values.back() << " over " << values.size() << " solves";
  return text.str();
}

/// The solves the reference found no exact answer for, if any: how many, and the first's reason.
void printUnanswered(const std::vector<ReferenceError>& errors) {
  const auto first = std::find_if(errors.begin(), errors.end(), [](const ReferenceError& error) {
    return !error.noExactAnswer.empty();
  });
  if (first == errors.end()) return;
  const auto count = std::count_if(first, errors.end(), [](const ReferenceError& error) {
    return !error.noExactAnswer.empty();
  });
  std::cout << "no answer    " << count << " of " << errors.size()
            << " solves have no exact answer, not measured (first: solve " << first->step + 1
            << ", " << first->noExactAnswer
            << "); biased targets on a pile can ask for an answer that does not exist "
               "(docs/global-reference.md)\n";
}

void printErrorSummary(const std::vector<ReferenceError>& errors) {
  std::vector<double> impulse, velocity, violation;
  for (const ReferenceError& error : errors) {
    impulse.push_back(error.impulseError);
    velocity.push_back(error.velocityError);
    violation.push_back(error.violation);
  }
  std::cout << "impulse err  " << statistics(impulse) << "  (|λ - λ*| / |λ*|)\n"
            << "velocity err " << statistics(velocity) << "  (the same in the energy norm)\n"
            << "violation    " << statistics(violation) << "  (relative to the impulse scale)\n";
  printUnanswered(errors);
}

/// The rows of the steps the world finished: a step that overflowed may have measured its
/// solves on overflowing velocities, so none of its rows is kept.
std::vector<ReferenceError> solvesBefore(const impulse2d::World& world,
                                         const std::vector<ReferenceError>& errors) {
  const long kept = world.stepCount() * world.settings().substeps;
  std::vector<ReferenceError> finished;
  for (const ReferenceError& error : errors) {
    if (error.step < kept) finished.push_back(error);
  }
  return finished;
}

}  // namespace

int errorVsReferenceRun(const RunOptions& options) {
  const impulse2d::SceneFile scene = loadScene(options.scene);
  if (scene.solver == impulse2d::kBox2dName) {
    throw RunFailure("--error-vs-reference measures micro, sequential or reference, not box2d");
  }
  auto solver = impulse2d::makeWatchedSolver(scene.solver, scene.solverSettings);
  const impulse2d::ErrorVsReference& watched = *solver;  // the world will own it
  impulse2d::World world(scene.world, std::move(solver));
  for (const impulse2d::Body& body : impulse2d::buildBodies(scene)) world.addBody(body);
  createOutputDirectory(directoryOf(options.errorVsReferencePath), "--error-vs-reference");
  const double solveDt = world.settings().dt / world.settings().substeps;
  for (int step = 0; step < scene.steps; ++step) {
    try {
      world.step();
    } catch (const impulse2d::NonFiniteState& failure) {
      writeErrors(*options.errorVsReferencePath, solvesBefore(world, watched.errors()), solveDt);
      throw RunFailure(failure.what());
    }
  }
  writeErrors(*options.errorVsReferencePath, watched.errors(), solveDt);
  std::cout << "scene        " << scene.name << " (solver " << scene.solver
            << ", watched by the reference)\nsteps        " << scene.steps << "\n";
  printErrorSummary(watched.errors());
  std::cout << "errors       " << *options.errorVsReferencePath << "\n";
  return kSuccess;
}

}  // namespace i2d
