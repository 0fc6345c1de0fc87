#include "perception/line_segments.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "core/symmetric_eigen.h"
#include "kernels/binomial_blur.h"
#include "kernels/canny_edges.h"
#include "kernels/color_gradient.h"
#include "kernels/mat_memory.h"
#include "kernels/oriented_hough.h"

namespace corridor {
namespace {

// MergeSegments' working memory: the segments' order and each group's endpoints and weights
// (only the first as many lists as there are groups are in use).
struct MergeScratch {
  std::vector<int> order;
  std::vector<std::vector<Eigen::Vector2d>> members;
  std::vector<std::vector<double>> weights;
};

// Orients the line so that its normal points down (b > 0, or a > 0 for vertical lines).
Eigen::Vector3d Normalise(Eigen::Vector3d line) {
  line /= line.head<2>().norm();
  if (line.y() < 0 || (line.y() == 0 && line.x() < 0)) line = -line;
  return line;
}

}  // namespace

void SetExtentAlongLine(const std::vector<Eigen::Vector2d>& points, MergedLine* m) {
  SetExtentAlongLine(points.data(), points.size(), m);
}

void SetExtentAlongLine(const Eigen::Vector2d* points, size_t count, MergedLine* m) {
  const Eigen::Vector2d direction(m->line.y(), -m->line.x());  // Along the line, u increasing.
  const Eigen::Vector2d origin = -m->line.z() * m->line.head<2>();
  double lo = 1e300, hi = -1e300;
  for (size_t i = 0; i < count; ++i) {
    const double t = (points[i] - origin).dot(direction);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  m->start = origin + lo * direction;
  m->end = origin + hi * direction;
  m->length = hi - lo;
  const double du = direction.x(), dv = direction.y();
  m->slope = std::abs(du) > 1e-12 ? dv / du : (dv > 0 ? 1e12 : -1e12);
  m->inclination_deg = std::atan2(std::abs(dv), std::abs(du)) * 180.0 / M_PI;
}

EdgeSegments DetectSegments(const cv::Mat& image, int roi_top, const SegmentOptions& options) {
  EdgeSegments out;
  DetectSegments(image, roi_top, options, &out);
  return out;
}

void DetectSegments(const cv::Mat& image, int roi_top, const SegmentOptions& options,
                    EdgeSegments* out) {
  out->roi_top = roi_top;
  const cv::Mat roi = image.rowRange(roi_top, image.rows);
  // The blurred rows in the thread's matrix, which keeps its memory from call to call.
  thread_local cv::Mat thread_smooth;
  const cv::Mat* smooth = &roi;
  if (options.blur_sigma > 0) {
    ReleaseUnlessSole(&thread_smooth);
    GaussianBlurView(roi, options.blur_sigma, &thread_smooth);
    smooth = &thread_smooth;
  }
  ReleaseUnlessSole(&out->dx);
  ReleaseUnlessSole(&out->dy);
  ReleaseUnlessSole(&out->edges);
  thread_local std::vector<int> thread_histogram;  // Keeps its memory from call to call.
  std::vector<int>& histogram = thread_histogram;
  const bool automatic = !(options.canny_high > 0);
  // The threshold is at least auto_min: the gradients below it need only be counted together.
  const int histogram_floor =
      automatic && options.auto_min > 0 && options.auto_min <= kGradientBins
          ? static_cast<int>(std::ceil(options.auto_min))
          : 0;
  ColorGradient(*smooth, &out->dx, &out->dy, automatic ? &histogram : nullptr, histogram_floor);
  const double high =
      automatic ? std::max(options.auto_min,
                           HistogramPercentile(histogram, static_cast<double>(out->dx.total()),
                                               options.auto_percentile))
                : options.canny_high;
  out->canny_high = high;
  CannyFromGradients(out->dx, out->dy, options.canny_low_ratio * high, high, false, &out->edges);
  HoughSegments(*out, options, &out->segments);
}

std::vector<cv::Vec4f> HoughSegments(const EdgeSegments& found, const SegmentOptions& options) {
  std::vector<cv::Vec4f> segments;
  HoughSegments(found, options, &segments);
  return segments;
}

void HoughSegments(const EdgeSegments& found, const SegmentOptions& options,
                   std::vector<cv::Vec4f>* segments) {
  segments->clear();
  // The thread's, keeping its memory from call to call (the transforms clear it first).
  thread_local std::vector<cv::Vec4i> thread_lines;
  std::vector<cv::Vec4i>& lines = thread_lines;
  lines.clear();
  if (found.edges.empty()) return;
  if (options.hough_angle_window_deg > 0) {
    OrientedHoughOptions hough;
    hough.threshold = options.hough_threshold;
    hough.min_length = options.hough_min_length;
    hough.max_gap = options.hough_max_gap;
    hough.angle_window_deg = options.hough_angle_window_deg;
    OrientedHoughSegments(found.edges, found.dx, found.dy, hough, &lines);
  } else {
    cv::HoughLinesP(found.edges, lines, 1.0, CV_PI / 180.0, options.hough_threshold,
                    options.hough_min_length, options.hough_max_gap);
  }
  segments->reserve(lines.size());
  for (const auto& l : lines) {
    segments->emplace_back(static_cast<float>(l[0]), static_cast<float>(l[1] + found.roi_top),
                           static_cast<float>(l[2]), static_cast<float>(l[3] + found.roi_top));
  }
}

Eigen::Vector2d LowEnd(const MergedLine& line) {
  return line.start.y() > line.end.y() ? line.start : line.end;
}

MergedLine LineThrough(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  MergedLine m;
  m.line = Normalise(Eigen::Vector3d(a.x(), a.y(), 1).cross(Eigen::Vector3d(b.x(), b.y(), 1)));
  const Eigen::Vector2d ends[2] = {a, b};
  SetExtentAlongLine(ends, 2, &m);
  m.covered = m.length;
  return m;
}

std::vector<MergedLine> MergeSegments(const std::vector<cv::Vec4f>& segments, double angle_deg,
                                      double distance_px) {
  std::vector<MergedLine> merged;
  MergeSegments(segments, angle_deg, distance_px, &merged);
  return merged;
}

void MergeSegments(const std::vector<cv::Vec4f>& segments, double angle_deg, double distance_px,
                   std::vector<MergedLine>* merged_lines) {
  // Longest first, so that each group is seeded by its most reliable segment. The order and the
  // groups' points live in the thread's scratch, which keeps its memory from call to call.
  thread_local MergeScratch thread_scratch;
  MergeScratch& scratch = thread_scratch;
  std::vector<int>& order = scratch.order;
  order.resize(segments.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  const auto length = [&](int i) {
    const auto& s = segments[i];
    return std::hypot(s[2] - s[0], s[3] - s[1]);
  };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return length(a) > length(b); });
  const double cos_tol = std::cos(angle_deg * M_PI / 180.0);
  std::vector<MergedLine>& merged = *merged_lines;
  merged.clear();
  merged.reserve(segments.size());
  std::vector<std::vector<Eigen::Vector2d>>& members = scratch.members;
  std::vector<std::vector<double>>& weights = scratch.weights;
  for (int i : order) {
    const auto& s = segments[i];
    const Eigen::Vector2d a(s[0], s[1]), b(s[2], s[3]);
    if ((b - a).norm() < 1e-6) continue;
    const MergedLine candidate = LineThrough(a, b);
    int group = -1;
    for (size_t g = 0; g < merged.size() && group < 0; ++g) {
      const Eigen::Vector3d& l = merged[g].line;
      if (std::abs(l.head<2>().dot(candidate.line.head<2>())) < cos_tol) continue;
      const double da = std::abs(l.dot(a.homogeneous())), db = std::abs(l.dot(b.homogeneous()));
      if (da <= distance_px && db <= distance_px) group = static_cast<int>(g);
    }
    if (group < 0) {
      // A new group: the next of the scratch's point lists, emptied (or a new one).
      const size_t g = merged.size();
      merged.push_back(candidate);
      if (members.size() <= g) members.resize(g + 1), weights.resize(g + 1);
      members[g].assign({a, b});
      weights[g].assign({candidate.length, candidate.length});
      continue;
    }
    members[group].push_back(a);
    members[group].push_back(b);
    weights[group].push_back(candidate.length);
    weights[group].push_back(candidate.length);
    // Length-weighted total least squares through the group's endpoints.
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    double total = 0;
    for (size_t k = 0; k < members[group].size(); ++k) {
      mean += weights[group][k] * members[group][k];
      total += weights[group][k];
    }
    mean /= total;
    Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
    for (size_t k = 0; k < members[group].size(); ++k) {
      const Eigen::Vector2d d = members[group][k] - mean;
      scatter += weights[group][k] * d * d.transpose();
    }
    const Eigen::Vector2d normal = SmallestEigenvector(scatter);
    MergedLine& m = merged[group];
    m.line = Normalise(Eigen::Vector3d(normal.x(), normal.y(), -normal.dot(mean)));
    const double covered = m.covered + candidate.length;
    SetExtentAlongLine(members[group], &m);
    m.covered = std::min(covered, m.length);
  }
}

}  // namespace corridor
