#pragma once

#include <opencv2/core.hpp>

#include "corridor_depth/status.h"

namespace corridor {

// Canny's non-maximum suppression and hysteresis on given derivatives: the edges cv::Canny(dx, dy,
// edges, low, high, l2) gives (255 on an edge, 0 elsewhere), faster (Stages/canny,
// docs/results.md): the suppression tests eight pixels at a time with AVX2 and skips runs of pixels
// below `low`. The magnitude is |dx| + |dy|, or dx^2 + dy^2 with `l2` (then compared with the
// squared thresholds, as OpenCV does). A pixel is kept when its magnitude exceeds `low`, is a
// maximum along the gradient's direction (one of four, split at 22.5 and 67.5 degrees), and is
// joined through kept pixels (8-connected) to one whose magnitude exceeds `high`. Pixels outside
// the image count as zero. InvalidArgument unless dx and dy are non-empty CV_16SC1 of one size.
Status CannyFromGradients(const cv::Mat& dx, const cv::Mat& dy, double low, double high, bool l2,
                          cv::Mat* edges);

}  // namespace corridor
