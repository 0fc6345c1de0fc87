#include "perception/junction_refit.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "perception/robust_line_fit.h"

namespace corridor {
namespace {

// The colour gradient across the line of unit normal n at `count` pixels in a row from (u0, v)
// (by_rows) or in a column from (k, v0) (!by_rows), all at least one pixel inside the image:
// |n . (dx, dy)| of the 3x3 Sobel, the strongest of the three channels, into m[0..count). The
// Sobel's sums across the run are shared between neighbours: `smooth` (1 2 1 across the run) and
// `step` (the difference across it), one per pixel and channel of the run and its two ends.
void GradientsAcross(const cv::Mat& bgr, bool by_rows, int major, int first, int count,
                     const Eigen::Vector2d& n, std::vector<int>* smooth, std::vector<int>* step,
                     double* m) {
  const int cells = 3 * (count + 2);
  smooth->resize(cells);
  step->resize(cells);
  // Pixel i of the run (i = -1 .. count), channel c, its neighbours on either side of the run.
  const auto at = [&](int i, int side, int c) -> int {
    const int along = first + i;
    return by_rows ? bgr.ptr<uchar>(major + side)[3 * along + c]
                   : bgr.ptr<uchar>(along)[3 * (major + side) + c];
  };
  for (int i = -1; i <= count; ++i) {
    for (int c = 0; c < 3; ++c) {
      const int before = at(i, -1, c), mid = at(i, 0, c), after = at(i, 1, c);
      (*smooth)[3 * (i + 1) + c] = before + 2 * mid + after;
      (*step)[3 * (i + 1) + c] = after - before;
    }
  }
  // Along the run: the derivative of `smooth`; across it: `step` smoothed (1 2 1).
  const double n_along = by_rows ? n.x() : n.y(), n_across = by_rows ? n.y() : n.x();
  for (int i = 0; i < count; ++i) {
    double best = 0;
    for (int c = 0; c < 3; ++c) {
      const int along = (*smooth)[3 * (i + 2) + c] - (*smooth)[3 * i + c];
      const int across =
          (*step)[3 * i + c] + 2 * (*step)[3 * (i + 1) + c] + (*step)[3 * (i + 2) + c];
      best = std::max(best, std::abs(n_along * along + n_across * across));
    }
    m[i] = best;
  }
}

// The edge points along `line` between t0 and t1 (positions along its direction from its origin).
std::vector<Eigen::Vector2d> EdgePointsAlong(const cv::Mat& bgr, const Eigen::Vector3d& line,
                                             double t0, double t1,
                                             const JunctionRefitOptions& o) {
  const Eigen::Vector2d n = line.head<2>();
  const Eigen::Vector2d direction(line.y(), -line.x());
  const Eigen::Vector2d origin = -line.z() * n;
  // Steep lines are crossed row by row, flat ones column by column.
  const bool by_rows = std::abs(direction.y()) >= std::abs(direction.x());
  const Eigen::Vector2d a = origin + t0 * direction, b = origin + t1 * direction;
  const int major_lo = static_cast<int>(std::ceil(std::min(by_rows ? a.y() : a.x(),
                                                           by_rows ? b.y() : b.x())));
  const int major_hi = static_cast<int>(std::floor(std::max(by_rows ? a.y() : a.x(),
                                                            by_rows ? b.y() : b.x())));
  const int major_size = by_rows ? bgr.rows : bgr.cols, minor_size = by_rows ? bgr.cols : bgr.rows;
  const int reach = static_cast<int>(std::ceil(o.reach_px));
  std::vector<Eigen::Vector2d> points;
  std::vector<double> m(2 * reach + 3);
  std::vector<int> smooth, step;
  const int stride = std::max(1, o.step_px);
  for (int k = std::max(1, major_lo); k <= std::min(major_size - 2, major_hi); k += stride) {
    // Where the line crosses this row (column): a u + b v + c = 0.
    const double minor = by_rows ? -(line.y() * k + line.z()) / line.x()
                                 : -(line.x() * k + line.z()) / line.y();
    if (!std::isfinite(minor)) continue;
    const int centre = static_cast<int>(std::lround(minor));
    const int first = centre - reach - 1;  // m[0] is one beyond the reach, for the peak test.
    if (first < 1 || first + 2 * reach + 2 > minor_size - 2) continue;
    GradientsAcross(bgr, by_rows, k, first, 2 * reach + 3, n, &smooth, &step, m.data());
    int best = -1;
    for (int i = 1; i <= 2 * reach + 1; ++i) {
      if (m[i] < o.threshold || m[i] < m[i - 1] || m[i] <= m[i + 1]) continue;
      if (best < 0 || std::abs(first + i - minor) < std::abs(first + best - minor)) best = i;
    }
    if (best < 0) continue;
    const double curve = m[best - 1] - 2 * m[best] + m[best + 1];
    const double offset =
        curve < 0 ? std::clamp(0.5 * (m[best - 1] - m[best + 1]) / curve, -0.5, 0.5) : 0.0;
    const double at = first + best + offset;
    points.emplace_back(by_rows ? at : k, by_rows ? k : at);
  }
  return points;
}

}  // namespace

bool RefitJunctionAtFullResolution(const cv::Mat& bgr, const JunctionRefitOptions& options,
                                   JunctionLine* junction) {
  if (bgr.empty() || bgr.type() != CV_8UC3) return false;
  const Eigen::Vector3d& coarse = junction->line;
  const Eigen::Vector2d direction(coarse.y(), -coarse.x());
  const Eigen::Vector2d origin = -coarse.z() * coarse.head<2>();
  const double t_near = (junction->near_end - origin).dot(direction);
  const double t_far = (junction->far_end - origin).dot(direction);
  const std::vector<Eigen::Vector2d> points =
      EdgePointsAlong(bgr, coarse, std::min(t_near, t_far), std::max(t_near, t_far), options);
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
