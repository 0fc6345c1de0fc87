#include "perception/focal_lines.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <opencv2/imgproc.hpp>

#include "core/symmetric_eigen.h"
#include "perception/line_segments.h"

namespace corridor {
namespace {

ImageLine MakeImageLine(const MergedLine& m) {
  ImageLine l;
  l.a = m.start.homogeneous();
  l.b = m.end.homogeneous();
  l.mid = (0.5 * (m.start + m.end)).homogeneous();
  l.through = l.a.cross(l.b);
  l.line = m.line;
  l.length = m.length;
  return l;
}

constexpr double kPartnerReach = 5.0;  // px: how far the other edge of a thin bar may lie.

// Sub-pixel position of the peak at index k of samples g.
double PeakOffset(const std::vector<double>& g, int k) {
  const double curvature = g[k - 1] - 2 * g[k] + g[k + 1];
  return curvature < 0 ? 0.5 * (g[k - 1] - g[k + 1]) / curvature : 0.0;
}

// Sub-pixel edge points of the line: on each pixel row it crosses (each column for a flat
// line), the peak of the gradient across it (of the given sign) within `reach` of it, by a
// parabola through the whole pixels (interpolated samples would lock the peaks to the grid);
// the weak peaks (under a third of the median) are dropped. When most peaks have a partner, a
// peak of the opposite sign at least half as strong within kPartnerReach, the line is a thin bar
// (floor grout, a door-frame band) and its points are the bars' centres instead: blur pushes
// the edges of a bar narrower than itself apart, and a bar narrows towards its vanishing point,
// which tilts either edge's line, while the centre stays put.
std::vector<Eigen::Vector2d> EdgePoints(const cv::Mat& dx, const cv::Mat& dy, const MergedLine& m,
                                        double reach, double sign) {
  const Eigen::Vector3d& l = m.line;
  const bool flat = std::abs(l.y()) >= std::abs(l.x());  // Steps along u, peaks across in v.
  const int half = static_cast<int>(std::ceil(reach));
  const int partner = static_cast<int>(std::ceil(kPartnerReach));
  const int wide = half + partner, middle = wide + 1;
  const int lo = static_cast<int>(std::ceil(flat ? std::min(m.start.x(), m.end.x())
                                                 : std::min(m.start.y(), m.end.y())));
  const int hi = static_cast<int>(std::floor(flat ? std::max(m.start.x(), m.end.x())
                                                  : std::max(m.start.y(), m.end.y())));
  const int across_size = flat ? dx.rows : dx.cols;
  std::vector<double> g(2 * wide + 3);
  std::vector<Eigen::Vector2d> edges, centres;
  std::vector<double> strength;
  for (int t = std::max(lo, 0); t <= std::min(hi, (flat ? dx.cols : dx.rows) - 1); ++t) {
    const double at = flat ? -(l.x() * t + l.z()) / l.y() : -(l.y() * t + l.z()) / l.x();
    const int base = static_cast<int>(std::lround(at));
    if (base - wide - 1 < 0 || base + wide + 1 >= across_size) continue;
    for (int k = -wide - 1; k <= wide + 1; ++k) {
      const int u = flat ? t : base + k, v = flat ? base + k : t;
      g[k + middle] = sign * (l.x() * dx.at<float>(v, u) + l.y() * dy.at<float>(v, u));
    }
    int best = middle - half;
    for (int k = middle - half; k <= middle + half; ++k) {
      if (g[k] > g[best]) best = k;
    }
    if (!(g[best] > 0) || g[best] < g[best - 1] || g[best] < g[best + 1]) continue;
    const double own = base + best - middle + PeakOffset(g, best);
    int other = -1;  // The strongest opposite peak near it.
    for (int k = std::max(1, best - partner); k <= std::min(2 * wide + 1, best + partner); ++k) {
      if (std::abs(k - best) < 2 || -g[k] < -g[k - 1] || -g[k] < -g[k + 1]) continue;
      if (other < 0 || g[k] < g[other]) other = k;
    }
    const auto point = [&](double across) {
      return flat ? Eigen::Vector2d(t, across) : Eigen::Vector2d(across, t);
    };
    edges.push_back(point(own));
    strength.push_back(g[best]);
    if (other >= 0 && -g[other] >= 0.5 * g[best]) {
      for (double& x : g) x = -x;
      centres.push_back(point(0.5 * (own + base + other - middle + PeakOffset(g, other))));
    }
  }
  if (edges.empty()) return edges;
  if (2 * centres.size() > edges.size()) return centres;
  std::vector<double> sorted = strength;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double floor = sorted[sorted.size() / 2] / 3;
  std::vector<Eigen::Vector2d> strong;
  for (size_t i = 0; i < edges.size(); ++i) {
    if (strength[i] >= floor) strong.push_back(edges[i]);
  }
  return strong;
}

// Refits the line (total least squares) on its sub-pixel edge points, of the polarity most of
// it has, three times, each time from the last fit and without the points more than 0.75 px
// off it; false when it has too few such points (too close to the image border, or not a
// clean edge), and the line is then left as it was. A thin dark line (floor grout) has two edges of opposite polarity a few pixels apart,
// which Hough segments and their merge may mix into one tilted line.
bool RefitSubpixel(const cv::Mat& dx, const cv::Mat& dy, double reach, MergedLine* m) {
  if (!(m->length > 4)) return false;
  double polarity = 0;
  const Eigen::Vector2d along = (m->end - m->start) / m->length;
  for (int t = 0; t <= static_cast<int>(m->length); ++t) {
    const Eigen::Vector2d p = m->start + t * along;
    const int u = static_cast<int>(std::lround(p.x())), v = static_cast<int>(std::lround(p.y()));
    if (u < 0 || v < 0 || u >= dx.cols || v >= dx.rows) continue;
    polarity += m->line.x() * dx.at<float>(v, u) + m->line.y() * dy.at<float>(v, u);
  }
  const double sign = polarity >= 0 ? 1.0 : -1.0;
  for (int round = 0; round < 3; ++round) {
    std::vector<Eigen::Vector2d> points = EdgePoints(dx, dy, *m, round == 0 ? reach : 1.0, sign);
    if (round > 0) {
      std::vector<Eigen::Vector2d> kept;
      for (const auto& q : points) {
        if (std::abs(m->line.dot(q.homogeneous())) < 0.75) kept.push_back(q);
      }
      points.swap(kept);
    }
    if (points.size() < std::max<size_t>(8, static_cast<size_t>(0.5 * m->length))) return round > 0;
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const auto& q : points) mean += q;
    mean /= static_cast<double>(points.size());
    Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
    for (const auto& q : points) scatter += (q - mean) * (q - mean).transpose();
    const Eigen::Vector2d normal = SmallestEigenvector(scatter);
    const MergedLine refit = LineThrough(m->start - normal.dot(m->start - mean) * normal,
                                         m->end - normal.dot(m->end - mean) * normal);
    if (!refit.line.allFinite() || refit.line.head<2>().dot(m->line.head<2>()) < 0.99) {
      return round > 0;
    }
    *m = refit;
  }
  return true;
}

}  // namespace

// Whole-image segments, merged, refit on sub-pixel edge points, the short ones dropped.
std::vector<ImageLine> FindFocalLines(const cv::Mat& color, const FocalEstimatorOptions& o) {
  const double diagonal = std::hypot(color.cols, color.rows);
  const SegmentOptions segment_options{
      o.blur_sigma, 0.0, o.canny_low_ratio, o.canny_auto_percentile, o.canny_auto_min,
      o.hough_threshold, std::max(6.0, o.hough_min_length_fraction * diagonal), o.hough_max_gap,
      0.0};
  const EdgeSegments found = DetectSegments(color, 0, segment_options);
  // The gradients Canny ran on (the whole image, blurred): the sub-pixel refit's too.
  cv::Mat dx, dy;
  found.dx.convertTo(dx, CV_32F);
  found.dy.convertTo(dy, CV_32F);
  std::vector<ImageLine> lines;
  for (const MergedLine& m : MergeSegments(found.segments, o.merge_angle_deg, o.merge_distance_px)) {
    if (m.length < o.min_line_length_fraction * diagonal) continue;
    MergedLine fitted = m;
    // A line without sub-pixel support keeps the Hough endpoints' whole-pixel error: dropped.
    if (o.refit_distance_px > 0 && !RefitSubpixel(dx, dy, o.refit_distance_px, &fitted)) continue;
    lines.push_back(MakeImageLine(fitted));
  }
  return lines;
}

}  // namespace corridor
