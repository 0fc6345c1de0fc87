#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace corridor {

// Whether the floor mirrors the ceiling's lights: of the 8-bit BGR `image`'s pixels between the
// junction lines `left` and `right` (homogeneous, through `vanishing_point`) and below it, at
// least `min_fraction` are brighter (mean of the channels) than the 90th percentile of the
// pixels outside them below the vanishing point (the walls, doors and whatever stands there). A
// diffuse floor is lit no brighter than the walls beside it; a polished one shows the lights.
bool FloorMirrorsLights(const cv::Mat& image, const Eigen::Vector3d& left,
                        const Eigen::Vector3d& right, const Eigen::Vector2d& vanishing_point,
                        double min_fraction);

}  // namespace corridor
