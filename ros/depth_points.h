#pragma once

#include <opencv2/core.hpp>
#include <sensor_msgs/PointCloud2.h>

#include "depth/ray_table.h"

namespace corridor {

// depth/points: an organised PointCloud2 (fields x, y, z: float32, 12 bytes a point) in the
// camera's optical frame, of every `stride`-th row and column of the depth (ceil(H / stride) rows
// of ceil(W / stride) points). A point is z * (ray x, ray y, 1), the rays from `rays` (lens
// distortion removed), so that without distortion it is depth_image_proc's
// ((u - cx) z / fx, (v - cy) z / fy, z). Pixels without an estimate (0, negative or non-finite)
// are NaN points and the cloud is not dense. The header is left to the caller.
void FillDepthPoints(const RayTable& rays, const cv::Mat& depth_m, int stride,
                     sensor_msgs::PointCloud2* cloud);

}  // namespace corridor
