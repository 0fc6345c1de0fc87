#include "estimation/junction_trim.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "estimation/junction_line_residual.h"

namespace corridor {
namespace {

// Appends to *distance each of side's points' weighted distance (sqrt(w) |r|) from its junction
// line of x; false when the line is at infinity or a distance is not finite.
bool AppendWeightedDistances(const CorridorObservation& observation,
                             const FloorIntrinsics& intrinsics, const double x[4], int side,
                             std::vector<double>* distance) {
  const std::vector<Eigen::Vector2d>& points = side < 0 ? observation.left : observation.right;
  Vec3<double> line;
  if (!JunctionLineResidual::ScaledLine(intrinsics, x, side, &line)) return false;
  for (size_t i = 0; i < points.size(); ++i) {
    const double r = JunctionLineResidual::Distance(intrinsics, line, points[i].x(), points[i].y());
    if (!std::isfinite(r)) return false;
    distance->push_back(std::abs(r) * std::sqrt(observation.Weight(side, i)));
  }
  return true;
}

// 1.4826 times the median of `values` (reordered; not empty): their robust standard deviation.
double RobustSpread(std::vector<double>* values) {
  const size_t mid = values->size() / 2;
  std::nth_element(values->begin(), values->begin() + mid, values->end());
  return 1.4826 * (*values)[mid];
}

}  // namespace

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
    distance.clear();
    if (!AppendWeightedDistances(all, intrinsics, x, side, &distance)) return false;
    sorted.assign(distance.begin(), distance.end());
    const double threshold = trim_sigmas * std::max(RobustSpread(&sorted), kMinSigmaPx);
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
    if (!AppendWeightedDistances(observation, intrinsics, x, side, &distance)) return false;
  }
  if (distance.empty()) return false;
  *sigma = RobustSpread(&distance);
  return true;
}

}  // namespace corridor
