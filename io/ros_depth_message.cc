// Depth images and CameraInfo as ROS messages.
#include "io/ros_depth_message.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "corridor_depth/image_io.h"

namespace corridor {

bool IsDepthEncoding(const std::string& encoding) {
  return encoding == "32FC1" || encoding == "16UC1";
}

Status FillDepthImage(const cv::Mat& depth_m, const std::string& encoding,
                      sensor_msgs::Image* image) {
  if (depth_m.type() != CV_32FC1 || depth_m.empty()) {
    return Status::InvalidArgument("depth to publish must be a non-empty 32FC1 image");
  }
  if (!IsDepthEncoding(encoding)) {
    return Status::InvalidArgument("depth encoding '" + encoding + "' (supported: 32FC1, 16UC1)");
  }
  image->height = static_cast<uint32_t>(depth_m.rows);
  image->width = static_cast<uint32_t>(depth_m.cols);
  image->encoding = encoding;
  image->is_bigendian = 0;  // Every ROS host is little-endian; the bytes are written so.
  const bool metres = encoding == "32FC1";
  image->step = image->width * (metres ? 4 : 2);
  image->data.resize(static_cast<size_t>(image->step) * image->height);
  const float none = std::numeric_limits<float>::quiet_NaN();
  const cv::Mat mm = metres ? cv::Mat() : DepthToMillimetres(depth_m);
  for (int r = 0; r < depth_m.rows; ++r) {
    uint8_t* dst = image->data.data() + static_cast<size_t>(r) * image->step;
    if (metres) {
      const float* src = depth_m.ptr<float>(r);
      for (int c = 0; c < depth_m.cols; ++c) {
        const float d = std::isfinite(src[c]) && src[c] > 0 ? src[c] : none;
        uint32_t bits;
        std::memcpy(&bits, &d, 4);
        for (int b = 0; b < 4; ++b) dst[4 * c + b] = static_cast<uint8_t>(bits >> (8 * b));
      }
    } else {
      const uint16_t* src = mm.ptr<uint16_t>(r);
      for (int c = 0; c < depth_m.cols; ++c) {
        dst[2 * c] = static_cast<uint8_t>(src[c] & 0xFF);
        dst[2 * c + 1] = static_cast<uint8_t>(src[c] >> 8);
      }
    }
  }
  return Status::Ok();
}

void FillCameraInfo(const Camera& camera, sensor_msgs::CameraInfo* info) {
  info->width = static_cast<uint32_t>(camera.image_width);
  info->height = static_cast<uint32_t>(camera.image_height);
  info->distortion_model = "plumb_bob";
  info->D.assign(camera.distortion.begin(), camera.distortion.end());
  info->K = {camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1};
  info->R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info->P = {camera.fx, 0, camera.cx, 0, 0, camera.fy, camera.cy, 0, 0, 0, 1, 0};
}

}  // namespace corridor
