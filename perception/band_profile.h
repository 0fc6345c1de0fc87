#pragma once

// Colours along lines through a vanishing point, turned from a junction by small angles: the
// profiles that the searches for a baseboard's foot (lower_edge.h) and for a polished floor's
// reflection (reflected_band.h) read bands from.

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/round_half_away.h"
#include "kernels/line_colour.h"

namespace corridor {

// `down` (a unit direction from the vanishing point along a junction) turned toward the floor by
// `angle` radians (toward the wall when negative): toward straight down, i.e. to the right of a
// left junction.
inline Eigen::Vector2d TurnedDown(const Eigen::Vector2d& down, bool left, double angle) {
  const Eigen::Vector2d inward =
      left ? Eigen::Vector2d(down.y(), -down.x()) : Eigen::Vector2d(-down.y(), down.x());
  return std::cos(angle) * down + std::sin(angle) * inward;
}

// Whether image point p lies in `roi`, the image's rows [roi_top, roi_top + roi.rows).
inline bool InsideRoi(const cv::Mat& roi, int roi_top, const Eigen::Vector2d& p) {
  return p.x() >= 0 && p.x() <= roi.cols - 1 && p.y() >= roi_top &&
         p.y() <= roi_top + roi.rows - 1;
}

// The colour of the 8-bit BGR `roi`'s pixel nearest image point p, clamped into it.
inline cv::Vec3d ColourAt(const cv::Mat& roi, int roi_top, const Eigen::Vector2d& p) {
  const int u = std::clamp(RoundHalfAway(p.x()), 0, roi.cols - 1);
  const int v = std::clamp(RoundHalfAway(p.y()) - roi_top, 0, roi.rows - 1);
  const cv::Vec3b& c = roi.at<cv::Vec3b>(v, u);
  return cv::Vec3d(c[0], c[1], c[2]);
}

// The mean colour at the points `vp + r d`, r in `radii` (not empty): ColourAt's, summed in order.
inline cv::Vec3d MeanColourAlong(const cv::Mat& roi, int roi_top, const Eigen::Vector2d& vp,
                                 const Eigen::Vector2d& d, const std::vector<double>& radii) {
  return MeanColourAtRadii(roi, roi_top, vp.x(), vp.y(), d.x(), d.y(), radii.data(),
                           static_cast<int>(radii.size()));
}

}  // namespace corridor
