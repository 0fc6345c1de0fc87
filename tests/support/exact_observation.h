#pragma once

// Exact junction points for a known pose, projected with Eigen's own rotations (not with the
// estimator's CorridorRotation), so the solvers are checked against an independent path.

#include <vector>

#include <Eigen/Geometry>

#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/corridor_observation.h"

namespace corridor {
namespace testing {

inline Eigen::Matrix3d TrueRotation(double pitch, double yaw) {
  return (Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()))
      .toRotationMatrix();
}

inline CorridorGeometry MakeGeometry(double yaw, double pitch, double offset, double width,
                                     double height) {
  CorridorGeometry g;
  g.yaw = yaw;
  g.pitch = pitch;
  g.offset = offset;
  g.width = width;
  g.camera_height = height;
  return g;
}

// The solver tests' corridors: level and centred; yawed, pitched down and off-centre; wide, yawed
// the other way and pitched up; and, when narrow_camera_height > 0, a narrow one seen from that
// camera height.
inline std::vector<CorridorGeometry> ExampleCorridors(double narrow_camera_height = 0) {
  std::vector<CorridorGeometry> corridors = {
      MakeGeometry(0.0, 0.0, 0.0, 2.0, 0.66),
      MakeGeometry(0.12, 0.06, 0.25, 2.4, 0.62),
      MakeGeometry(-0.2, 0.1, -0.35, 3.1, 0.66),
  };
  if (narrow_camera_height > 0) {
    corridors.push_back(MakeGeometry(0.05, -0.04, 0.1, 1.8, narrow_camera_height));
  }
  return corridors;
}

// Projects the junction points (-d_l, h, Z) and (d_r, h, Z) for Z in [z_near, z_far].
inline CorridorObservation ExactObservation(const CorridorGeometry& g, int points_per_side = 20,
                                            double z_near = 2.0, double z_far = 12.0) {
  CorridorObservation obs;
  obs.fx = 250;
  obs.fy = 250;
  obs.cx = 209.5;
  obs.cy = 179.5;
  obs.camera_height = g.camera_height;
  const Eigen::Matrix3d r = TrueRotation(g.pitch, g.yaw);
  const double d_left = g.width / 2 + g.offset, d_right = g.width / 2 - g.offset;
  for (int i = 0; i < points_per_side; ++i) {
    const double z = z_near + (z_far - z_near) * i / (points_per_side - 1);
    for (int side = 0; side < 2; ++side) {
      const Eigen::Vector3d pw(side == 0 ? -d_left : d_right, g.camera_height, z);
      const Eigen::Vector3d pc = r * pw;
      const Eigen::Vector2d px(obs.fx * pc.x() / pc.z() + obs.cx, obs.fy * pc.y() / pc.z() + obs.cy);
      (side == 0 ? obs.left : obs.right).push_back(px);
    }
  }
  return obs;
}

}  // namespace testing
}  // namespace corridor
