#pragma once

// Private to the floor-texture and floor-band measures: the columns of one gradient-map row that
// lie on one side of an image line.

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

namespace corridor {

// Narrows [lo, hi) (columns of a gradient map, u = scale * column, at image row v) to where
// sign * line . (u, v, 1) > margin: below a line whose normal points down for sign = 1, above it
// for sign = -1.
inline void KeepLineSide(const Eigen::Vector3d& line, double sign, double v, double margin,
                         int scale, double* lo, double* hi) {
  const double a = sign * line.x(), rest = sign * (line.y() * v + line.z()) - margin;
  if (a == 0) {
    if (!(rest > 0)) *hi = *lo;
    return;
  }
  const double bound = -rest / a / scale;  // The column where the line is `margin` away.
  if (a > 0) {
    *lo = std::max(*lo, std::floor(bound) + 1);
  } else {
    *hi = std::min(*hi, std::ceil(bound));
  }
}

}  // namespace corridor
