#pragma once

namespace corridor {

// One point of a line search along a direction: the cost at step x and its derivative along the
// direction, each with whether it could be evaluated.
struct LineSample {
  double x = 0, value = 0, gradient = 0;
  bool value_ok = false, gradient_ok = false;
};

// The next step an Armijo line search with cubic interpolation tries after `current` failed the
// sufficient-decrease test, as Ceres chooses it: half of current.x when the cost there could not
// be evaluated; otherwise the minimiser over [min_step, max_step] of the polynomial through the
// values and derivatives of `initial` (x = 0), `current` and, when valid, `previous`.
double InterpolatedStep(const LineSample& initial, const LineSample& previous,
                        const LineSample& current, double min_step, double max_step);

}  // namespace corridor
