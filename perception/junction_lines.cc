#include "corridor_depth/junction_lines.h"

namespace corridor {

std::vector<Eigen::Vector2d> SampleAlongLine(const JunctionLine& line, int n) {
  std::vector<Eigen::Vector2d> points;
  if (n <= 0) return points;
  if (n == 1) return {line.near_end};
  points.reserve(n);
  for (int i = 0; i < n; ++i) {
    points.push_back(line.near_end + (line.far_end - line.near_end) * (i / (n - 1.0)));
  }
  return points;
}

}  // namespace corridor
