#pragma once

// Hand-written depth of the corridor box for one pixel, from docs/geometry.md section 3, using
// Eigen's rotations (independent of the rasterisers' code).

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"

namespace corridor {
namespace testing {

inline Camera TestCamera() {
  Camera c;
  c.image_width = 160;
  c.image_height = 120;
  c.fx = c.fy = 100;
  c.cx = 79.5;
  c.cy = 59.5;
  c.mount_height = 0.66;
  return c;
}

inline CorridorGeometry TestGeometry(double yaw, double pitch, double offset, double width,
                                     double ceiling = 0) {
  CorridorGeometry g;
  g.yaw = yaw;
  g.pitch = pitch;
  g.offset = offset;
  g.width = width;
  g.camera_height = 0.66;
  g.ceiling_height = ceiling;
  return g;
}

// Smallest positive camera z at which the ray of ideal pixel (u, v) meets floor, walls or
// ceiling; infinity when none. `surface`: 0 floor, 1 wall, 2 ceiling.
inline double BoxDepth(const Camera& c, const CorridorGeometry& g, double u, double v,
                       int* surface = nullptr) {
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(g.pitch, Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(g.yaw, Eigen::Vector3d::UnitY()))
                                .toRotationMatrix();
  const Eigen::Vector3d ray((u - c.cx) / c.fx, (v - c.cy) / c.fy, 1.0);
  const Eigen::Vector3d w = r.transpose() * ray;  // The ray in the corridor frame, per unit z.
  double best = std::numeric_limits<double>::infinity();
  int kind = -1;
  const auto consider = [&](double z, int k) {
    if (z > 0 && z < best) best = z, kind = k;
  };
  if (w.y() > 0) consider(g.camera_height / w.y(), 0);
  if (w.x() < 0) consider((-(g.width / 2 + g.offset)) / w.x(), 1);
  if (w.x() > 0) consider((g.width / 2 - g.offset) / w.x(), 1);
  if (g.ceiling_height > 0 && w.y() < 0) consider((g.camera_height - g.ceiling_height) / w.y(), 2);
  if (surface) *surface = kind;
  return best;
}

}  // namespace testing
}  // namespace corridor
