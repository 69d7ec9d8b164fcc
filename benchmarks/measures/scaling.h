// The cost per step of each method, at its default settings, on pyramids of 10 to about 5000
// boxes (sleeping off), and the exponent of a power law fitted to it: cost ∝ bodies^exponent.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "progress_bar.h"

namespace benchmarks {

struct ScalingPoint {
  std::string solver;
  int rows = 0;
  int boxes = 0;
  bool measured = false;             ///< false: not run, its cost would not fit the budget
  double microsecondsPerStep = 0.0;  ///< median after warm-up
  long stepsMeasured = 0;
  int contactPoints = 0;  ///< in the last step
  std::string failure;    ///< why the method stopped the run, if it did (then not measured)
};

/// Every method on every pyramid of the family, in increasing size per method.
std::vector<ScalingPoint> scalingPoints(const std::vector<int>& rows);

/// Measures the points in order. A size is run only if the size before it, scaled by the cube of
/// the ratio of box counts (the dense solve's growth, the steepest of the methods), fits the
/// budget of one point; the sizes after one that does not are not run either.
void measureScaling(std::vector<ScalingPoint>& points, ProgressBar& progress);

/// Below this many boxes the fixed cost of a step hides how a method scales.
inline constexpr int kFitMinimumBoxes = 45;
/// The largest pyramid of the range the exponent target is set over (10 to 40 rows): 40
/// rows. Above it micro's first steps from rest, which a size's warm-up does not get past, pass
/// the cap of 200 impulses per point, and the few steps that fit the budget are those.
inline constexpr int kRangeMaximumBoxes = 820;

/// Least-squares slope of log(cost) against log(boxes) over the method's measured points with
/// kFitMinimumBoxes to maximumBoxes boxes; NaN with fewer than two.
double fittedExponent(const std::vector<ScalingPoint>& points, const std::string& solver,
                      int maximumBoxes = std::numeric_limits<int>::max());

/// One row per measured point, with its method's fitted exponent.
void writeScalingCsv(const std::string& path, const std::vector<ScalingPoint>& points);

/// µs per step by boxes (rows) and method (columns), and each method's fitted exponent.
void printScalingTable(const std::vector<ScalingPoint>& points);

}  // namespace benchmarks
