#pragma once

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"

namespace corridor {

// The floor the recovered geometry predicts: 255 where the box model's nearest surface is the
// floor within `max_range` metres, else 0. Lens distortion is honoured.
cv::Mat PredictFloorMask(const Camera& camera, const CorridorGeometry& geometry,
                         double max_range = 40.0);

// Intersection over union of two binary masks (> 127 = set); NaN when both are empty.
double MaskIoU(const cv::Mat& a, const cv::Mat& b);

}  // namespace corridor
