// The exact answers some tests hold a method to when no closed form is at hand: a body turning
// with one degree of freedom, θ'' = f(θ, θ'), integrated by classic Runge–Kutta in steps far
// finer than any time step under test (its error, about the fourth power of the step, is far
// below the integrators' lag the tests allow).
#pragma once

#include <cmath>

namespace exact {

struct Turn {
  double angle = 0.0;  ///< rad
  double spin = 0.0;   ///< rad/s
};

/// The angle and spin after `seconds` from `start`, with angular acceleration
/// `acceleration(angle, spin)` (rad/s²), in RK4 steps of `step` (s).
template <class Acceleration>
Turn turnAfter(Turn start, double seconds, double step, const Acceleration& acceleration) {
  const auto rate = [&](const Turn& at) { return Turn{at.spin, acceleration(at.angle, at.spin)}; };
  const auto ahead = [](const Turn& at, const Turn& by, double h) {
    return Turn{at.angle + h * by.angle, at.spin + h * by.spin};
  };
  Turn now = start;
  for (long i = 0; i < std::lround(seconds / step); ++i) {
    const Turn k1 = rate(now);
    const Turn k2 = rate(ahead(now, k1, 0.5 * step));
    const Turn k3 = rate(ahead(now, k2, 0.5 * step));
    const Turn k4 = rate(ahead(now, k3, step));
    now.angle += step / 6.0 * (k1.angle + 2.0 * k2.angle + 2.0 * k3.angle + k4.angle);
    now.spin += step / 6.0 * (k1.spin + 2.0 * k2.spin + 2.0 * k3.spin + k4.spin);
  }
  return now;
}

}  // namespace exact
