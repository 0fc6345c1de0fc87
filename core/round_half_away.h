#pragma once

#include <cmath>

namespace corridor {

// std::lround(x) for an image coordinate, without libm's call: truncated, then one step away from
// zero when the rest (exact: x less an integer of its magnitude) is at least a half. Far outside
// any image (or not a number): -1, outside too.
inline int RoundHalfAway(double x) {
  if (!(std::abs(x) < 1e9)) return -1;
  int t = static_cast<int>(x);
  const double rest = x - t;
  if (rest >= 0.5) {
    ++t;
  } else if (rest <= -0.5) {
    --t;
  }
  return t;
}

}  // namespace corridor
