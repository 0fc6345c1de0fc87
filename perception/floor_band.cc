#include "perception/floor_band.h"

#include <algorithm>
#include <cmath>

#include "kernels/edge_scan.h"
#include "perception/line_side_span.h"

namespace corridor {

BandEdges MeasureBandEdges(const cv::Mat& edges, const cv::Mat& dx, const cv::Mat& dy,
                           const GradientGrid& grid, const Eigen::Vector3d& inner,
                           const Eigen::Vector3d& outer, const Eigen::Vector2d& vanishing_point,
                           const BandEdgeOptions& options) {
  BandEdges out;
  if (edges.type() != CV_8U || dx.type() != CV_16S || dy.type() != CV_16S ||
      dx.size() != edges.size() || dy.size() != edges.size()) {
    return out;
  }
  const double tan_tolerance = std::tan(options.tolerance_deg * M_PI / 180.0);
  const double sin_vp = std::sin(options.vp_tolerance_deg * M_PI / 180.0);
  const double margin = options.margin;
  // True when the edge at map column i, image row v, with gradient (gx, gy) runs toward the
  // vanishing point: the edge runs along (-gy, gx), the vanishing point lies along (tx, ty).
  const auto toward_vp = [&](double gx, double gy, double ax, double ay, int i, double v) {
    const double u = static_cast<double>(grid.scale) * i;
    const double tx = vanishing_point.x() - u, ty = vanishing_point.y() - v;
    const double cross = -gy * ty - gx * tx;
    return std::abs(cross) <= sin_vp * std::hypot(ax, ay) * std::hypot(tx, ty);
  };
  for (int j = 0; j < edges.rows; ++j) {
    const double v = grid.first_row + static_cast<double>(grid.scale) * j;
    if (!(v > vanishing_point.y() + margin)) continue;
    double lo = 0, hi = edges.cols;
    KeepLineSide(inner, -1.0, v, margin, grid.scale, &lo, &hi);  // Above the inner line.
    KeepLineSide(outer, 1.0, v, margin, grid.scale, &lo, &hi);   // Below the outer line.
    if (!(lo < hi)) continue;
    const int begin = static_cast<int>(lo), end = static_cast<int>(hi);
    out.pixels += end - begin;
    const short* gx = dx.ptr<short>(j);
    const short* gy = dy.ptr<short>(j);
    const long across_before = out.across;
    ForEachNonZeroByte(edges.ptr<uchar>(j), begin, end, [&](int i) {
      const double ax = std::abs(gx[i]), ay = std::abs(gy[i]);
      // An edge toward the vanishing point runs along the corridor, whatever its slope: near
      // the image's side the junctions, runner edges and grout lines stand almost vertical.
      if (toward_vp(gx[i], gy[i], ax, ay, i, v)) return;
      if (ay <= tan_tolerance * ax) {  // Gradient horizontal: the edge stands vertical.
        ++out.vertical;
      } else if (ax > tan_tolerance * ay) {  // Neither across nor vertical.
        ++out.oblique;
      } else {
        ++out.across;
      }
    });
    if (out.across > across_before) ++out.across_rows;
  }
  return out;
}

}  // namespace corridor
