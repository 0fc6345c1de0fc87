#include "perception/junction_edge_points.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "perception/line_edge_points.h"
#include "perception/junction_memory.h"

namespace corridor {

bool JunctionEdgePointOptions::Check(std::string* why) const {
  std::string reason;
  if (!(reach_px >= 1 && reach_px <= 16)) {
    reason = "reach_px must be in [1, 16]";
  } else if (!(max_distance_px > 0 && std::isfinite(max_distance_px))) {
    reason = "max_distance_px must be positive";
  } else if (!(threshold >= 0 && std::isfinite(threshold))) {
    reason = "threshold must be >= 0";
  } else if (!(weight_power >= 0 && weight_power <= 4)) {
    reason = "weight_power must be in [0, 4]";
  } else if (!(max_weight >= 1 && std::isfinite(max_weight))) {
    reason = "max_weight must be >= 1";
  }
  if (reason.empty()) return true;
  if (why != nullptr) *why = reason;
  return false;
}

void MeasureJunctionEdgePoints(const cv::Mat& bgr, const JunctionEdgePointOptions& options,
                               JunctionLine* junction) {
  junction->edge_points.clear();
  junction->edge_weights.clear();
  if (bgr.empty() || bgr.type() != CV_8UC3 || junction->support.empty()) return;
  const Eigen::Vector3d& line = junction->line;
  if (!line.allFinite() || !(line.head<2>().norm() > 0.5)) return;
  const bool by_rows = CrossedByRows(line);
  const int majors = by_rows ? bgr.rows : bgr.cols;
  // The rows (columns) with a support pixel, and their neighbours: a support found at a coarser
  // step (a refit at full resolution every other row) covers the rows between.
  thread_local std::vector<char> thread_wanted;
  std::vector<char>& wanted = thread_wanted;
  wanted.assign(static_cast<size_t>(majors), 0);
  double t0 = 1e300, t1 = -1e300;
  for (const Eigen::Vector2d& p : junction->support) {
    const int k = static_cast<int>(std::lround(by_rows ? p.y() : p.x()));
    for (int j = std::max(0, k - 1); j <= std::min(majors - 1, k + 1); ++j) wanted[j] = 1;
    const double t = PositionAlong(line, p);
    t0 = std::min(t0, t);
    t1 = std::max(t1, t);
  }
  if (!(t0 <= t1)) return;
  // One row (column) more at each end, for the neighbours marked there.
  const double along = by_rows ? std::abs(line.x()) : std::abs(line.y());
  const double pad = 1.0 / std::max(along, 1e-3);
  EdgePeakSearch search;
  search.reach_px = options.reach_px;
  search.threshold = options.threshold;
  search.step_px = 1;
  search.nearest_only = true;
  thread_local std::vector<EdgePeak> thread_peaks;
  std::vector<EdgePeak>& peaks = thread_peaks;
  peaks.clear();
  EdgePeaksAlong(bgr, line, t0 - pad, t1 + pad, search, &peaks);
  // The result's vectors, with a spare's memory (junction_memory.h) when they have none.
  if (junction->edge_points.capacity() == 0) junction->edge_points = SpareEdgePoints();
  if (junction->edge_weights.capacity() == 0) junction->edge_weights = SpareEdgeWeights();
  std::vector<double>& weights = junction->edge_weights;
  for (const EdgePeak& peak : peaks) {
    if (peak.major < 0 || peak.major >= majors || !wanted[peak.major]) continue;
    if (std::abs(line.dot(peak.point.homogeneous())) > options.max_distance_px) continue;
    junction->edge_points.push_back(peak.point);
    weights.push_back(peak.strength);
  }
  if (weights.size() < 2) {
    junction->edge_points.clear();
    weights.clear();
    return;
  }
  thread_local std::vector<double> thread_sorted;
  std::vector<double>& sorted = thread_sorted;
  sorted.assign(weights.begin(), weights.end());
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = std::max(sorted[sorted.size() / 2], 1e-9);
  double sum = 0;
  for (double& w : weights) {
    w = std::min(std::pow(w / median, options.weight_power), options.max_weight);
    sum += w;
  }
  const double scale = static_cast<double>(weights.size()) / sum;
  for (double& w : weights) w *= scale;
}

}  // namespace corridor
