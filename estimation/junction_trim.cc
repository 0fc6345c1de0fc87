#include "estimation/junction_trim.h"

#include <algorithm>
#include <cmath>

#include "estimation/junction_line_residual.h"

namespace corridor {

bool TrimToFit(const CorridorObservation& all, const FloorIntrinsics& intrinsics, const double x[4],
               double trim_sigmas, CorridorObservation* kept, std::vector<char>* mask) {
  thread_local std::vector<double> thread_distance, thread_sorted;
  std::vector<double>& distance = thread_distance;
  std::vector<double>& sorted = thread_sorted;
  mask->clear();
  kept->fx = all.fx;
  kept->fy = all.fy;
  kept->cx = all.cx;
  kept->cy = all.cy;
  kept->camera_height = all.camera_height;
  kept->left.clear();
  kept->right.clear();
  kept->left_weights.clear();
  kept->right_weights.clear();
  for (int side = -1; side <= 1; side += 2) {
    const std::vector<Eigen::Vector2d>& points = side < 0 ? all.left : all.right;
    Vec3<double> line;
    if (!JunctionLineResidual::ScaledLine(intrinsics, x, side, &line)) return false;
    distance.clear();
    for (const auto& p : points) {
      const double r = JunctionLineResidual::Distance(intrinsics, line, p.x(), p.y());
      if (!std::isfinite(r)) return false;
      distance.push_back(std::abs(r) * std::sqrt(all.Weight(side, distance.size())));
    }
    sorted.assign(distance.begin(), distance.end());
    const size_t mid = sorted.size() / 2;
    std::nth_element(sorted.begin(), sorted.begin() + mid, sorted.end());
    const double threshold = trim_sigmas * std::max(1.4826 * sorted[mid], kMinSigmaPx);
    std::vector<Eigen::Vector2d>& out = side < 0 ? kept->left : kept->right;
    std::vector<double>& out_weights = side < 0 ? kept->left_weights : kept->right_weights;
    const bool weighted = !(side < 0 ? all.left_weights : all.right_weights).empty();
    int positive = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      const bool keep = distance[i] <= threshold;
      mask->push_back(keep ? 1 : 0);
      if (!keep) continue;
      out.push_back(points[i]);
      if (weighted) out_weights.push_back(all.Weight(side, i));
      positive += all.Weight(side, i) > 0 ? 1 : 0;
    }
    if (positive < 2) return false;
  }
  return true;
}

TrimBuffers& ThreadTrimBuffers(size_t points) {
  thread_local TrimBuffers buffers;
  buffers.previous.assign(points, 1);
  return buffers;
}

bool RobustSigma(const CorridorObservation& observation, const FloorIntrinsics& intrinsics,
                 const double x[4], int which, double* sigma) {
  thread_local std::vector<double> thread_distance;
  std::vector<double>& distance = thread_distance;
  distance.clear();
  for (int side = -1; side <= 1; side += 2) {
    if (which != 0 && side != which) continue;
    const std::vector<Eigen::Vector2d>& points = side < 0 ? observation.left : observation.right;
    Vec3<double> line;
    if (!JunctionLineResidual::ScaledLine(intrinsics, x, side, &line)) return false;
    for (size_t i = 0; i < points.size(); ++i) {
      const double r = JunctionLineResidual::Distance(intrinsics, line, points[i].x(), points[i].y());
      if (!std::isfinite(r)) return false;
      distance.push_back(std::abs(r) * std::sqrt(observation.Weight(side, i)));
    }
  }
  if (distance.empty()) return false;
  const size_t mid = distance.size() / 2;
  std::nth_element(distance.begin(), distance.begin() + mid, distance.end());
  *sigma = 1.4826 * distance[mid];
  return true;
}

}  // namespace corridor
