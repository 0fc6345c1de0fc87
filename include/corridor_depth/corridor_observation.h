#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "corridor_depth/camera.h"

namespace corridor {

// What the solvers see: the intrinsics, the camera height, and points on the two floor/wall
// junctions in ideal (undistorted) pixel coordinates.
struct CorridorObservation {
  double fx = 0, fy = 0, cx = 0, cy = 0;  // Pinhole intrinsics, pixels.
  double camera_height = 0;               // h, metres above the floor.
  std::vector<Eigen::Vector2d> left;      // Points on the left junction (ideal pixels).
  std::vector<Eigen::Vector2d> right;     // Points on the right junction (ideal pixels).

  static CorridorObservation FromCamera(const Camera& camera);
  // True when the solvers can use it (>= 2 points a side, finite, positive focal and height).
  bool Check(std::string* why) const;
};

}  // namespace corridor
