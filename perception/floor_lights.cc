#include "perception/floor_lights.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace corridor {

namespace {

// The columns of row v on the floor's side (`sign`) of `line`, narrowing [*lo, *hi) to them: the
// side is a half-row, its end where the line crosses the row.
void KeepFloorSide(const Eigen::Vector3d& line, double sign, int v, int cols, int* lo, int* hi) {
  const double a = sign * line.x(), rest = sign * (line.y() * v + line.z());
  if (std::abs(a) < 1e-12) {
    if (!(rest > 0)) *hi = *lo;  // The whole row is on the wall's side.
    return;
  }
  // a u + rest > 0: u beyond the crossing, on the side a points to.
  const double crossing = -rest / a;
  if (a > 0) {
    *lo = std::max(*lo, static_cast<int>(std::clamp(std::floor(crossing) + 1, 0.0, 1.0 * cols)));
  } else {
    *hi = std::min(*hi, static_cast<int>(std::clamp(std::ceil(crossing), 0.0, 1.0 * cols)));
  }
}

}  // namespace

bool FloorMirrorsLights(const cv::Mat& image, const Eigen::Vector3d& left,
                        const Eigen::Vector3d& right, const Eigen::Vector2d& vanishing_point,
                        double min_fraction) {
  if (image.empty() || image.type() != CV_8UC3 || !vanishing_point.allFinite() ||
      !left.allFinite() || !right.allFinite()) {
    return false;
  }
  // The floor's side of each line: that of the image's bottom middle.
  const Eigen::Vector3d bottom(0.5 * (image.cols - 1), image.rows - 1, 1);
  const double left_sign = left.dot(bottom) >= 0 ? 1 : -1;
  const double right_sign = right.dot(bottom) >= 0 ? 1 : -1;
  const int top = std::clamp(static_cast<int>(std::ceil(vanishing_point.y())) + 1, 0, image.rows);
  // Brightness histograms (sum of the three channels) of the floor and of the rest.
  std::array<long, 766> floor{}, walls{};
  long floor_count = 0, wall_count = 0;
  for (int v = top; v < image.rows; ++v) {
    const cv::Vec3b* row = image.ptr<cv::Vec3b>(v);
    int lo = 0, hi = image.cols;
    KeepFloorSide(left, left_sign, v, image.cols, &lo, &hi);
    KeepFloorSide(right, right_sign, v, image.cols, &lo, &hi);
    for (int u = 0; u < image.cols; ++u) {
      const bool on_floor = u >= lo && u < hi;
      const int level = row[u][0] + row[u][1] + row[u][2];
      if (on_floor) {
        ++floor[level];
        ++floor_count;
      } else {
        ++walls[level];
        ++wall_count;
      }
    }
  }
  if (floor_count == 0 || wall_count == 0) return false;
  // The walls' 90th percentile (a door or a lit patch may be brighter), and the floor above it.
  long seen = 0;
  int percentile = 765;
  for (int level = 0; level <= 765; ++level) {
    seen += walls[level];
    if (seen >= 0.9 * static_cast<double>(wall_count)) {
      percentile = level;
      break;
    }
  }
  long brighter = 0;
  for (int level = percentile + 1; level <= 765; ++level) brighter += floor[level];
  return brighter >= min_fraction * static_cast<double>(floor_count);
}

}  // namespace corridor
