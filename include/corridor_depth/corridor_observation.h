#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "corridor_depth/camera.h"

namespace corridor {

// What the solvers see: the intrinsics, the camera height, and points on the two floor/wall
// junctions in ideal (undistorted) pixel coordinates, each with a weight (the inverse of its
// position's variance, in units of one point of average noise: a weight w counts as w points of
// weight 1). Every solver minimises the weighted sum of its residuals (squared, or absolute for
// the grid's L1 cost, where a residual is scaled by sqrt(w)).
struct CorridorObservation {
  double fx = 0, fy = 0, cx = 0, cy = 0;  // Pinhole intrinsics, pixels.
  double camera_height = 0;               // h, metres above the floor.
  std::vector<Eigen::Vector2d> left;      // Points on the left junction (ideal pixels).
  std::vector<Eigen::Vector2d> right;     // Points on the right junction (ideal pixels).
  std::vector<double> left_weights;       // One per left point, or empty: every weight 1.
  std::vector<double> right_weights;      // One per right point, or empty: every weight 1.

  static CorridorObservation FromCamera(const Camera& camera);
  // True when the solvers can use it (>= 2 points a side, finite, positive focal and height,
  // weights empty or one per point, finite, >= 0, with at least 2 positive a side).
  bool Check(std::string* why) const;
  // The weight of the side's (side < 0: left) i-th point.
  double Weight(int side, size_t i) const {
    const std::vector<double>& w = side < 0 ? left_weights : right_weights;
    return w.empty() ? 1.0 : w[i];
  }
};

}  // namespace corridor
