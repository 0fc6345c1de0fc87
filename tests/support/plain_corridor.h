#pragma once

// A plain generated corridor (walls, floor and ceiling, no doors or clutter) for tests that add
// their own objects, and its true floor lines projected with the true pose.

#include <cmath>

#include <Eigen/Core>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_frame.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/junction_lines.h"
#include "synth/corridor_scene.h"

namespace corridor {
namespace testing_util {

// The camera the plain corridor is seen with: 640x480, 80 degrees across, 0.66 m high.
inline Camera PlainCorridorCamera() {
  return Camera::FromHorizontalFov(640, 480, 80.0 * M_PI / 180, 0.66);
}

// The corridor's options: 2.6 m wide, a 2.8 m ceiling, no clutter, seed 11.
inline synth::SceneOptions PlainCorridorOptions() {
  synth::SceneOptions options;
  options.width = 2.6;
  options.ceiling_height = 2.8;
  options.clutter = 0;
  options.seed = 11;
  return options;
}

// The corridor of `options` without doors or boxes: nothing but its walls, floor and ceiling.
inline synth::CorridorScene PlainScene(const synth::SceneOptions& options) {
  synth::CorridorScene scene = synth::BuildScene(options);
  scene.doors.clear();
  scene.obstacles.clear();
  return scene;
}

// The raw pixel of the corridor-frame point (x right, y down from the camera, z ahead).
inline Eigen::Vector2d CorridorPixel(const Camera& camera, const CorridorGeometry& g, double x,
                                     double y, double z) {
  const CorridorRotation<double> r(g.pitch, g.yaw);
  const Vec3<double> c = r.ToCamera({x, y, z});
  return camera.Project({c.x, c.y, c.z});
}

// The floor line x = `x` (corridor frame) with its support from z0 to z1 ahead.
inline JunctionLine FloorLine(const Camera& camera, const CorridorGeometry& g, double x, double z0,
                              double z1) {
  JunctionLine line;
  line.near_end = CorridorPixel(camera, g, x, g.camera_height, z0);
  line.far_end = CorridorPixel(camera, g, x, g.camera_height, z1);
  const Eigen::Vector2d d = (line.far_end - line.near_end).normalized();
  line.line = Eigen::Vector3d(-d.y(), d.x(), d.y() * line.near_end.x() - d.x() * line.near_end.y());
  line.support_length = (line.far_end - line.near_end).norm();
  return line;
}

}  // namespace testing_util
}  // namespace corridor
