#include "perception/floor_texture.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace corridor {
namespace {

// Narrows [lo, hi) (columns of the gradient map) to the u where line . (u, v, 1) > margin, with
// u = scale * column.
void KeepBelow(const Eigen::Vector3d& line, double v, double margin, int scale, double* lo,
               double* hi) {
  const double a = line.x(), rest = line.y() * v + line.z() - margin;  // a u + rest > 0.
  if (a == 0) {
    if (!(rest > 0)) *hi = *lo;
    return;
  }
  const double bound = -rest / a / scale;  // The column where the line is `margin` above.
  if (a > 0) {
    *lo = std::max(*lo, std::floor(bound) + 1);
  } else {
    *hi = std::min(*hi, std::ceil(bound));
  }
}

}  // namespace

FloorTexture MeasureFloorTexture(const cv::Mat& dx, const cv::Mat& dy, const GradientGrid& grid,
                                 const Eigen::Vector3d& left, const Eigen::Vector3d& right,
                                 double vanishing_row, double margin, int strong) {
  FloorTexture out;
  long strong_pixels = 0;
  if (dx.type() != CV_16S || dy.type() != CV_16S || dx.size() != dy.size()) return out;
  for (int j = 0; j < dx.rows; ++j) {
    const double v = grid.first_row + static_cast<double>(grid.scale) * j;
    if (!(v > vanishing_row + margin)) continue;
    double lo = 0, hi = dx.cols;
    KeepBelow(left, v, margin, grid.scale, &lo, &hi);
    KeepBelow(right, v, margin, grid.scale, &lo, &hi);
    if (!(lo < hi)) continue;
    const int begin = static_cast<int>(lo), end = static_cast<int>(hi);
    const short* gx = dx.ptr<short>(j);
    const short* gy = dy.ptr<short>(j);
    int row_strong = 0;
    for (int i = begin; i < end; ++i) {
      row_strong += std::abs(gx[i]) + std::abs(gy[i]) >= strong ? 1 : 0;
    }
    strong_pixels += row_strong;
    out.floor_pixels += end - begin;
  }
  if (out.floor_pixels > 0) {
    out.strong_fraction = static_cast<double>(strong_pixels) / out.floor_pixels;
  }
  return out;
}

}  // namespace corridor
