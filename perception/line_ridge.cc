#include "perception/line_ridge.h"

#include <algorithm>
#include <cmath>

namespace corridor {
namespace {

// Grey level of a BGR pixel (ITU-R BT.601 weights, as cv::COLOR_BGR2GRAY).
double Grey(const cv::Vec3b& p) { return 0.114 * p[0] + 0.587 * p[1] + 0.299 * p[2]; }

// Mean grey of the points centre + j * step for j in [-reach, reach]; false when one is outside
// the ROI rows [roi_top, roi_top + bgr.rows).
bool MeanGrey(const cv::Mat& bgr, int roi_top, const Eigen::Vector2d& centre,
              const Eigen::Vector2d& step, int reach, double* grey) {
  double sum = 0;
  for (int j = -reach; j <= reach; ++j) {
    const Eigen::Vector2d q = centre + j * step;
    const int u = cvRound(q.x()), v = cvRound(q.y()) - roi_top;
    if (u < 0 || v < 0 || u >= bgr.cols || v >= bgr.rows) return false;
    sum += Grey(bgr.at<cv::Vec3b>(v, u));
  }
  *grey = sum / (2 * reach + 1);
  return true;
}

}  // namespace

double RidgeFraction(const cv::Mat& bgr, const MergedLine& line, int roi_top, int scale,
                     double min_contrast) {
  const Eigen::Vector2d normal = line.line.head<2>();  // Points down (toward the floor).
  const Eigen::Vector2d along = (line.end - line.start).normalized();
  const double s = std::max(1, scale);
  const int samples = 24;
  int usable = 0, ridges = 0;
  for (int i = 0; i < samples; ++i) {
    const Eigen::Vector2d p = line.start + (line.end - line.start) * ((i + 0.5) / samples);
    // The sides: 3x3 means 4 s px away, as the colour probes of BoundaryScore.
    double above = 0, below = 0, row = 0;
    bool inside = true;
    for (int k = -1; k <= 1 && inside; ++k) {
      double a = 0, b = 0;
      inside = MeanGrey(bgr, roi_top, p + (k * s - 4 * s) * normal, s * along, 1, &a) &&
               MeanGrey(bgr, roi_top, p + (k * s + 4 * s) * normal, s * along, 1, &b);
      above += a / 3;
      below += b / 3;
    }
    double darkest = 255, lightest = 0;
    for (int k = -1; k <= 1 && inside; ++k) {
      inside = MeanGrey(bgr, roi_top, p + k * s * normal, s * along, 1, &row);
      darkest = std::min(darkest, row);
      lightest = std::max(lightest, row);
    }
    if (!inside) continue;
    ++usable;
    const double dark = std::min(above, below) - darkest;
    const double light = lightest - std::max(above, below);
    if (std::max(dark, light) > std::max(min_contrast, std::abs(above - below))) ++ridges;
  }
  return usable >= 6 ? static_cast<double>(ridges) / usable : -1.0;
}

}  // namespace corridor
