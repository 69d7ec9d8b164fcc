// Bisection over a stress scene's knob (breaking_points.h).
#include "breaking_points.h"

#include <cmath>

namespace impulse2d::stress {

double midpoint(const Knob& knob, double a, double b) {
  switch (knob.scale) {
    case KnobScale::Integer:
      return a + std::trunc(0.5 * (b - a));
    case KnobScale::Logarithmic:
      return std::sqrt(a * b);
    case KnobScale::Linear:
      break;
  }
  return 0.5 * (a + b);
}

namespace {

/// Whether the bracket is as narrow as the search goes.
bool narrowEnough(const Knob& knob, double held, double failed, int halvings,
                  const SearchSettings& settings) {
  if (knob.scale == KnobScale::Integer) return std::abs(failed - held) <= 1.0;
  return halvings >= settings.halvings;
}

}  // namespace

BreakingPoint findBreakingPoint(const Knob& knob, double hardest,
                                const std::function<Outcome(double)>& run,
                                const SearchSettings& settings) {
  BreakingPoint point;
  point.hardest = hardest;
  auto fails = [&](double value) {
    point.samples.push_back({value, run(value)});
    return point.samples.back().outcome.failed;
  };
  if (fails(knob.easy)) {
    point.verdict = Verdict::FailsAtEasiest;
    point.firstFailed = knob.easy;
    return point;
  }
  point.lastHeld = knob.easy;
  if (!fails(hardest)) {
    point.verdict = Verdict::HoldsThroughout;
    point.lastHeld = hardest;
    return point;
  }
  point.firstFailed = hardest;
  for (int halvings = 0; !narrowEnough(knob, point.lastHeld, point.firstFailed, halvings, settings);
       ++halvings) {
    const double middle = midpoint(knob, point.lastHeld, point.firstFailed);
    (fails(middle) ? point.firstFailed : point.lastHeld) = middle;
  }
  return point;
}

double hardestFor(const StressScene& stress, const Method& method) {
  for (const std::string& name : {method.label, method.solver}) {
    const auto limit = stress.hardestFor.find(name);
    if (limit != stress.hardestFor.end()) return limit->second;
  }
  return stress.knob.hard;
}

BreakingPoint findBreakingPoint(const StressScene& stress, const Method& method,
                                const SearchSettings& settings) {
  const double hardest = hardestFor(stress, method);
  return findBreakingPoint(
      stress.knob, hardest,
      [&](double knob) {
        const RunLength length =
            knob == hardest ? RunLength::UntilCollapsed : RunLength::UntilFailed;
        return runStress(stress, method, knob, {}, length);
      },
      settings);
}

}  // namespace impulse2d::stress
