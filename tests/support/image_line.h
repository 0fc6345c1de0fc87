#pragma once

// The image line through two points, as the perception's lines hold it.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace corridor {
namespace testing_util {

// The line a u + b v + c = 0 through two image points, unit normal pointing down (b > 0).
inline Eigen::Vector3d DownLine(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  Eigen::Vector3d line = a.homogeneous().cross(b.homogeneous());
  line /= line.head<2>().norm();
  return line.y() < 0 ? Eigen::Vector3d(-line) : line;
}

}  // namespace testing_util
}  // namespace corridor
