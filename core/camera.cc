#include "corridor_depth/camera.h"

#include <cmath>
#include <sstream>

namespace corridor {
namespace {

bool Fail(std::string* why, const std::string& message) {
  if (why != nullptr) *why = message;
  return false;
}

constexpr double kMaxMountHeight = 10.0;  // Metres; anything higher is not a corridor robot.

}  // namespace

Camera Camera::FromHorizontalFov(int width, int height, double hfov_rad, double mount_height) {
  Camera camera;
  camera.image_width = width;
  camera.image_height = height;
  camera.fx = camera.fy = 0.5 * width / std::tan(0.5 * hfov_rad);
  camera.cx = 0.5 * (width - 1);
  camera.cy = 0.5 * (height - 1);
  camera.mount_height = mount_height;
  return camera;
}

bool Camera::CheckIntrinsics(std::string* why) const {
  std::ostringstream msg;
  if (image_width <= 0 || image_height <= 0) {
    msg << "image size " << image_width << "x" << image_height << " is not positive";
    return Fail(why, msg.str());
  }
  if (!std::isfinite(fx) || !std::isfinite(fy) || fx <= 0 || fy <= 0) {
    msg << "focal lengths fx=" << fx << ", fy=" << fy << " must be finite and positive";
    return Fail(why, msg.str());
  }
  if (!std::isfinite(cx) || !std::isfinite(cy) || cx < 0 || cy < 0 || cx > image_width ||
      cy > image_height) {
    msg << "principal point (" << cx << ", " << cy << ") lies outside the " << image_width << "x"
        << image_height << " image";
    return Fail(why, msg.str());
  }
  for (double k : distortion) {
    if (!std::isfinite(k)) return Fail(why, "distortion coefficients must be finite");
  }
  return true;
}

bool Camera::Check(std::string* why) const {
  if (!CheckIntrinsics(why)) return false;
  if (!std::isfinite(mount_height) || mount_height <= 0 || mount_height > kMaxMountHeight) {
    std::ostringstream msg;
    msg << "camera height " << mount_height << " m must be in (0, " << kMaxMountHeight << "] m";
    return Fail(why, msg.str());
  }
  return true;
}

bool Camera::HasDistortion() const {
  for (double k : distortion) {
    if (k != 0.0) return true;
  }
  return false;
}

Eigen::Matrix3d Camera::K() const {
  Eigen::Matrix3d k;
  k << fx, 0, cx, 0, fy, cy, 0, 0, 1;
  return k;
}

Eigen::Vector2d Camera::Distort(const Eigen::Vector2d& ideal) const {
  if (!HasDistortion()) return ideal;
  const double x = (ideal.x() - cx) / fx;
  const double y = (ideal.y() - cy) / fy;
  const double k1 = distortion[0], k2 = distortion[1], p1 = distortion[2], p2 = distortion[3],
               k3 = distortion[4];
  const double r2 = x * x + y * y;
  const double radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3));
  const double xd = x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x);
  const double yd = y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y;
  return {fx * xd + cx, fy * yd + cy};
}

Eigen::Vector2d Camera::Undistort(const Eigen::Vector2d& raw) const {
  if (!HasDistortion()) return raw;
  // Fixed-point iteration, as in OpenCV's undistortPoints; converges for moderate distortion.
  const double xd = (raw.x() - cx) / fx;
  const double yd = (raw.y() - cy) / fy;
  const double k1 = distortion[0], k2 = distortion[1], p1 = distortion[2], p2 = distortion[3],
               k3 = distortion[4];
  double x = xd, y = yd;
  for (int i = 0; i < 20; ++i) {
    const double r2 = x * x + y * y;
    const double radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3));
    const double dx = 2 * p1 * x * y + p2 * (r2 + 2 * x * x);
    const double dy = p1 * (r2 + 2 * y * y) + 2 * p2 * x * y;
    x = (xd - dx) / radial;
    y = (yd - dy) / radial;
  }
  return {fx * x + cx, fy * y + cy};
}

}  // namespace corridor
