#include "perception/junction_refit.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "perception/line_edge_points.h"
#include "perception/robust_line_fit.h"

namespace corridor {

bool RefitJunctionAtFullResolution(const cv::Mat& bgr, const JunctionRefitOptions& options,
                                   JunctionLine* junction) {
  if (bgr.empty() || bgr.type() != CV_8UC3) return false;
  const Eigen::Vector3d& coarse = junction->line;
  const Eigen::Vector2d direction(coarse.y(), -coarse.x());
  const Eigen::Vector2d origin = -coarse.z() * coarse.head<2>();
  const double t_near = (junction->near_end - origin).dot(direction);
  const double t_far = (junction->far_end - origin).dot(direction);
  EdgePeakSearch search;
  search.reach_px = options.reach_px;
  search.threshold = options.threshold;
  search.step_px = options.step_px;
  std::vector<EdgePeak> peaks;
  EdgePeaksAlong(bgr, coarse, std::min(t_near, t_far), std::max(t_near, t_far), search, &peaks);
  std::vector<Eigen::Vector2d> points;
  points.reserve(peaks.size());
  for (const EdgePeak& peak : peaks) points.push_back(peak.point);
  // The line of least distance (robust to the odd point on another edge), then again on the
  // points near it.
  Eigen::Vector3d line;
  if (!FitLineLeastDistance(points, &line)) return false;
  std::vector<Eigen::Vector2d> near;
  for (const auto& p : points) {
    if (std::abs(line.dot(p.homogeneous())) <= options.support_distance_px) near.push_back(p);
  }
  Eigen::Vector3d refit;
  if (FitLineLeastDistance(near, &refit)) line = refit;
  // The same orientation as the coarse line (normal pointing the same way).
  if (line.head<2>().dot(coarse.head<2>()) < 0) line = -line;
  const auto onto = [&](const Eigen::Vector2d& p) -> Eigen::Vector2d {
    return p - line.dot(p.homogeneous()) * line.head<2>();
  };
  junction->line = line;
  junction->near_end = onto(junction->near_end);
  junction->far_end = onto(junction->far_end);
  junction->support = near.size() >= 8 ? near : points;
  return true;
}

}  // namespace corridor
