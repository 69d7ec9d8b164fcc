// Accuracy against answers a student can derive by hand, on the shipped lecture scenes: the slide
// of a box down an incline, the apex of a bouncing ball, the acceleration of a rolling disk and
// the drift of a box that static friction should hold.
#pragma once

#include <string>
#include <vector>

namespace benchmarks {

struct AnalyticCheck {
  std::string scene;     ///< the shipped scene it runs
  std::string quantity;  ///< what is compared, with its unit
  double expected = 0.0;
  double measured = 0.0;
};

/// Every analytic check run with `solver` at its default settings.
std::vector<AnalyticCheck> analyticChecks(const std::string& solver);

}  // namespace benchmarks
