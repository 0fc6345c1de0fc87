#pragma once

#include <string>

#include <opencv2/core.hpp>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include "corridor_depth/camera.h"
#include "corridor_depth/status.h"

namespace corridor {

// The depth messages that the live node publishes and corridor_depth --output_bag writes, so that
// a recorded run and a live run look alike downstream (depth_image_proc, RViz).

// The depth encodings: "32FC1" (metres, NaN = no estimate; the default) or "16UC1" (millimetres,
// rounded, clamped to 65535, 0 = no estimate).
bool IsDepthEncoding(const std::string& encoding);

// Fills the pixel fields of *image (header untouched) from CV_32F metres, where 0, a negative or a
// non-finite value means no estimate. Little-endian. InvalidArgument for another encoding or type.
Status FillDepthImage(const cv::Mat& depth_m, const std::string& encoding,
                      sensor_msgs::Image* image);

// Fills *info (header untouched) with the camera: size, K, plumb_bob D, identity R, P = [K | 0].
void FillCameraInfo(const Camera& camera, sensor_msgs::CameraInfo* info);

}  // namespace corridor
