#pragma once

#include <array>
#include <string>

#include <Eigen/Core>

namespace corridor {

// A pinhole camera with optional plumb_bob (Brown-Conrady) distortion, as in ROS camera_info,
// plus the height of its optical centre above the floor.
struct Camera {
  int image_width = 0;                 // Pixels.
  int image_height = 0;                // Pixels.
  double fx = 0.0;                     // Focal length in x, pixels.
  double fy = 0.0;                     // Focal length in y, pixels.
  double cx = 0.0;                     // Principal point x, pixels (pixel centres at integers).
  double cy = 0.0;                     // Principal point y, pixels.
  std::array<double, 5> distortion{};  // plumb_bob k1, k2, p1, p2, k3; all zero = rectified.
  double mount_height = 0.0;           // Optical centre above the floor, metres (camera_height).

  // A camera from a horizontal field of view, principal point at the image centre.
  static Camera FromHorizontalFov(int width, int height, double hfov_rad, double mount_height);

  // True when every field is usable; otherwise fills *why with what is wrong.
  bool Check(std::string* why) const;
  // Like Check, but the mount height may be unset (0): for tools that take it elsewhere.
  bool CheckIntrinsics(std::string* why) const;
  bool HasDistortion() const;

  Eigen::Matrix3d K() const;
  // Normalised ray (x/z, y/z, 1) of an ideal (undistorted) pixel.
  Eigen::Vector3d Ray(double u, double v) const {
    return {(u - cx) / fx, (v - cy) / fy, 1.0};
  }
  // Ideal pixel of a camera-frame point with z > 0.
  Eigen::Vector2d Project(const Eigen::Vector3d& p) const {
    return {fx * p.x() / p.z() + cx, fy * p.y() / p.z() + cy};
  }
  // Ideal (undistorted) pixel coordinates of a raw image pixel; identity without distortion.
  Eigen::Vector2d Undistort(const Eigen::Vector2d& raw) const;
  // Raw image pixel of an ideal pixel; identity without distortion.
  Eigen::Vector2d Distort(const Eigen::Vector2d& ideal) const;
};

}  // namespace corridor
