#include "corridor_depth/line_inliers.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "estimation/closed_form.h"

namespace corridor {

namespace {

// LineInlierMask's working memory, the thread's, reused from call to call.
struct InlierScratch {
  std::vector<Eigen::Vector2d> subset;
  std::vector<double> distance, kept_distance;
  std::vector<char> next;
};

}  // namespace

std::vector<char> LineInlierMask(const std::vector<Eigen::Vector2d>& points) {
  std::vector<char> keep;
  LineInlierMask(points, &keep);
  return keep;
}

void LineInlierMask(const std::vector<Eigen::Vector2d>& points, std::vector<char>* keep_out) {
  std::vector<char>& keep = *keep_out;
  keep.assign(points.size(), 1);
  if (points.size() < 3) return;
  thread_local InlierScratch thread_scratch;
  InlierScratch& scratch = thread_scratch;
  std::vector<Eigen::Vector2d>& subset = scratch.subset;
  subset.assign(points.begin(), points.end());
  std::vector<double>& distance = scratch.distance;
  std::vector<double>& kept_distance = scratch.kept_distance;
  distance.resize(points.size());
  std::vector<char>& next = scratch.next;
  constexpr int kRounds = 3;
  for (int round = 0; round < kRounds; ++round) {
    Eigen::Vector3d line;
    if (!FitImageLine(subset, &line)) return;
    kept_distance.clear();
    for (size_t i = 0; i < points.size(); ++i) {
      distance[i] = std::abs(line.dot(points[i].homogeneous()));
      if (keep[i]) kept_distance.push_back(distance[i]);
    }
    const size_t mid = kept_distance.size() / 2;
    std::nth_element(kept_distance.begin(), kept_distance.begin() + mid, kept_distance.end());
    const double threshold = std::max(3.0 * 1.4826 * kept_distance[mid], 1.0);
    next.resize(points.size());
    subset.clear();
    for (size_t i = 0; i < points.size(); ++i) {
      next[i] = distance[i] <= threshold;
      if (next[i]) subset.push_back(points[i]);
    }
    if (subset.size() < 2) return;
    if (next == keep) break;
    keep.swap(next);
  }
  return;
}

}  // namespace corridor
