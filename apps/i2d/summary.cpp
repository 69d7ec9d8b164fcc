// Printing the run summary.
#include "summary.h"

#include <ostream>

namespace i2d {

Energy measureEnergy(const impulse2d::Simulation& simulation) {
  return {impulse2d::kineticEnergy(simulation), impulse2d::potentialEnergy(simulation)};
}

void printSummary(std::ostream& out, const RunSummary& summary) {
  const double microsecondsPerStep =
      summary.steps > 0 ? 1e6 * summary.wallSeconds / double(summary.steps) : 0.0;
  out << "scene        " << summary.scene << " (solver " << summary.solver << ")\n"
      << "steps        " << summary.steps << " of " << summary.dt
      << " s = " << double(summary.steps) * summary.dt << " s simulated\n"
      << "wall time    " << summary.wallSeconds << " s, " << microsecondsPerStep << " µs per step\n"
      << "contacts     " << summary.contactPoints << " points at the end, penetration "
      << summary.penetrationAtEnd << " m in the last state\n"
      << "kinetic      " << summary.start.kinetic << " J at start, " << summary.end.kinetic
      << " J at end\n"
      << "potential    " << summary.start.potential << " J at start, " << summary.end.potential
      << " J at end\n";
  if (summary.csvPath) {
    out << "csv          " << *summary.csvPath << " (" << summary.csvRows << " rows)\n";
  }
  for (const std::string& line : summary.outputs) out << line << "\n";
}

}  // namespace i2d
