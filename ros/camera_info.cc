#include "ros/camera_info.h"

#include <cmath>
#include <string>

namespace corridor {

Status CameraFromInfo(const sensor_msgs::CameraInfo& info, int width, int height,
                      Camera* camera) {
  const std::string size = std::to_string(info.width) + "x" + std::to_string(info.height);
  if (static_cast<int>(info.width) != width || static_cast<int>(info.height) != height) {
    return Status::InvalidArgument("camera_info is " + size + " but the image is " +
                                   std::to_string(width) + "x" + std::to_string(height));
  }
  if (info.binning_x > 1 || info.binning_y > 1 || info.roi.width != 0 || info.roi.height != 0) {
    return Status::InvalidArgument("camera_info with binning or a region of interest");
  }
  Camera c;
  c.image_width = width;
  c.image_height = height;
  c.fx = info.K[0];
  c.fy = info.K[4];
  c.cx = info.K[2];
  c.cy = info.K[5];
  if (!(std::isfinite(c.fx) && std::isfinite(c.fy) && c.fx > 0 && c.fy > 0)) {
    return Status::InvalidArgument("camera_info focal length fx " + std::to_string(c.fx) +
                                   ", fy " + std::to_string(c.fy) + " (must be positive)");
  }
  if (!(std::isfinite(c.cx) && std::isfinite(c.cy))) {
    return Status::InvalidArgument("camera_info principal point is not finite");
  }
  const bool plumb_bob = info.distortion_model == "plumb_bob" || info.distortion_model.empty();
  const bool rational = info.distortion_model == "rational_polynomial";
  if (!plumb_bob && !rational) {
    return Status::InvalidArgument("camera_info distortion model '" + info.distortion_model +
                                   "' (supported: plumb_bob)");
  }
  for (size_t i = 0; i < info.D.size(); ++i) {
    if (!std::isfinite(info.D[i])) return Status::InvalidArgument("camera_info D is not finite");
    if (i < c.distortion.size()) {
      c.distortion[i] = info.D[i];
    } else if (info.D[i] != 0) {
      return Status::InvalidArgument("camera_info distortion beyond plumb_bob's five terms");
    }
  }
  std::string why;
  if (!c.CheckIntrinsics(&why)) return Status::InvalidArgument("camera_info: " + why);
  *camera = c;
  return Status::Ok();
}

}  // namespace corridor
