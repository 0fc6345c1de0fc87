#pragma once

// Private helper of the focal estimator: whole-image straight lines with sub-pixel endpoints, for
// vanishing points that must be accurate to a fraction of a pixel.

#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "perception/focal_estimator.h"

namespace corridor {

// A line of the image by its extent: homogeneous endpoints and midpoint, (u, v, 1).
struct ImageLine {
  Eigen::Vector3d a, b, mid;
  Eigen::Vector3d through;  // a x b: the line through the endpoints, unnormalised.
  Eigen::Vector3d line;     // a u + b v + c = 0 with a^2 + b^2 = 1.
  double length = 0;        // px.
};

// Whole-image segments (perception/line_segments.h), merged, refit on sub-pixel gradient peaks
// (thin bars such as grout on their centre line), the short ones and those without sub-pixel
// support dropped.
std::vector<ImageLine> FindFocalLines(const cv::Mat& color, const FocalEstimatorOptions& o);

}  // namespace corridor
