#include "corridor_depth/junction_lines.h"

namespace corridor {

std::vector<Eigen::Vector2d> SampleAlongLine(const JunctionLine& line, int n) {
  std::vector<Eigen::Vector2d> points;
  SampleAlongLine(line, n, &points);
  return points;
}

void SampleAlongLine(const JunctionLine& line, int n, std::vector<Eigen::Vector2d>* points) {
  points->clear();
  if (n <= 0) return;
  if (n == 1) {
    points->push_back(line.near_end);
    return;
  }
  points->reserve(n);
  for (int i = 0; i < n; ++i) {
    points->push_back(line.near_end + (line.far_end - line.near_end) * (i / (n - 1.0)));
  }
}

}  // namespace corridor
