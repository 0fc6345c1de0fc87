#pragma once

#include <opencv2/core.hpp>

namespace corridor {

// The rasterisers write 0 where they have no estimate; the pipeline's depth says so with NaN,
// which depth_image_proc and point-cloud code read as no point (0 would be a point at the origin):
// every pixel of the CV_32F `depth` that is not positive becomes NaN.
void MarkNoEstimateNaN(cv::Mat* depth);

}  // namespace corridor
