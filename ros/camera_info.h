#pragma once

#include <sensor_msgs/CameraInfo.h>

#include "corridor_depth/camera.h"
#include "corridor_depth/status.h"

namespace corridor {

// The camera of a CameraInfo message for an image of width x height pixels (mount_height stays 0).
// InvalidArgument, saying why, for a message the node cannot use: a zero or non-finite focal
// length or principal point, a size that is not the image's, binning or a region of interest,
// or a distortion other than plumb_bob (or rational_polynomial with zero extra terms).
Status CameraFromInfo(const sensor_msgs::CameraInfo& info, int width, int height, Camera* camera);

}  // namespace corridor
