// The breaking point of a method on a stress scene: bisection over the knob between the value
// where the method holds and the value where it fails. The search is reproducible: a fixed
// bracket (the knob's easy and hard ends), a fixed number of halvings, deterministic runs, so
// the same build finds the same point on every machine and under any load.
#pragma once

#include <functional>
#include <vector>

#include "run.h"

namespace impulse2d::stress {

struct SearchSettings {
  /// Halvings of a continuous bracket: 6 narrow it to 1/64 of a linear range, or to a factor
  /// of range^(1/64) of a logarithmic one (11% of 1..1000). Counts are halved to the unit.
  int halvings = 6;
};

/// One run of the search.
struct Sample {
  double knob = 0.0;
  Outcome outcome;
};

enum class Verdict {
  Breaks,           ///< holds at lastHeld, fails at firstFailed, the two adjacent in the search
  HoldsThroughout,  ///< holds at the hardest value searched
  FailsAtEasiest,   ///< fails already at the easy end
};

struct BreakingPoint {
  Verdict verdict = Verdict::Breaks;
  double lastHeld = 0.0;        ///< knob; meaningless for FailsAtEasiest
  double firstFailed = 0.0;     ///< knob; meaningless for HoldsThroughout
  double hardest = 0.0;         ///< the hard end of this search
  std::vector<Sample> samples;  ///< every run, in the order it was made
};

/// The knob value halfway between a and b in the knob's own scale (whole numbers for counts).
double midpoint(const Knob& knob, double a, double b);

/// Bisects `run` over [knob.easy, hardest].
BreakingPoint findBreakingPoint(const Knob& knob, double hardest,
                                const std::function<Outcome(double)>& run,
                                const SearchSettings& settings = {});

/// The hardest knob value searched for the method: the knob's hard end, or the scene's limit for
/// the method (by label) or its solver where the full range costs too much.
double hardestFor(const StressScene& stress, const Method& method);

/// The method's breaking point on the scene. The run at the hardest value goes on past a failure
/// until the structure collapses (RunLength::UntilCollapsed), so its sway is seen whole.
BreakingPoint findBreakingPoint(const StressScene& stress, const Method& method,
                                const SearchSettings& settings = {});

}  // namespace impulse2d::stress
