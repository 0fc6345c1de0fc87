#pragma once

// Where a junction line's support lies along it, and the detector's confidence in the line.

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

namespace corridor {

// The positions t = (p - o) . (b, -a) of a line's support points p along it (o the line's point
// nearest the origin): their least and greatest, and the distinct whole pixels (floor(t)) they
// fall on.
struct SupportExtent {
  double lo = 1e300, hi = -1e300;
  int covered = 0;
};

// The extent of `support` along `line` (a, b, c with a^2 + b^2 = 1); `bins` is scratch.
inline SupportExtent MeasureSupport(const std::vector<Eigen::Vector2d>& support,
                                    const Eigen::Vector3d& line, std::vector<int>* bins) {
  const Eigen::Vector2d direction(line.y(), -line.x());
  const Eigen::Vector2d origin = -line.z() * line.head<2>();
  SupportExtent out;
  bins->clear();
  for (const auto& p : support) {
    const double t = (p - origin).dot(direction);
    out.lo = std::min(out.lo, t);
    out.hi = std::max(out.hi, t);
    bins->push_back(static_cast<int>(std::floor(t)));
  }
  std::sort(bins->begin(), bins->end());
  out.covered = static_cast<int>(std::unique(bins->begin(), bins->end()) - bins->begin());
  return out;
}

// The detector's confidence in a junction line: its boundary score (clamped to [0, 1]) times its
// support length over a quarter of the image height (at most 1).
inline double JunctionConfidence(double boundary, double support_length, double image_height) {
  return std::clamp(boundary, 0.0, 1.0) * std::min(1.0, support_length / (0.25 * image_height));
}

}  // namespace corridor
