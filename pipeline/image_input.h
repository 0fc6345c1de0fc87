#pragma once

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/status.h"

namespace corridor {

// The input image as 8-bit BGR: 8- or 16-bit, grey, grey+alpha, BGR or BGRA, of the camera's
// size; InvalidArgument naming what is wrong otherwise. Shares the data when it is 8-bit BGR.
Status ToBgr(const cv::Mat& image, const Camera& camera, cv::Mat* bgr);

// Builds OpenCV's colour-conversion tables once, before frames are recovered concurrently.
void BuildOpenCvTablesOnce();

}  // namespace corridor
