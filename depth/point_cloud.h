#pragma once

#include <opencv2/core.hpp>

#include "corridor_depth/point_cloud.h"
#include "corridor_depth/status.h"
#include "depth/ray_table.h"

namespace corridor {

// Every pixel with a depth (z > 0, finite) as a camera-frame point z * (ray x, ray y, 1), with its
// colour from `bgr` (8-bit BGR of the same size; may be empty: black). `rays` must be the depth's
// camera (lens distortion is removed by the table). InvalidArgument on mismatched sizes or types.
Status DepthToPointCloud(const RayTable& rays, const cv::Mat& depth_m, const cv::Mat& bgr,
                         PointCloud* cloud);

}  // namespace corridor
