#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <Eigen/Geometry>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "synth/corridor_renderer.h"
#include "synth/presets.h"

namespace corridor {
namespace testing_util {

// One frame of a generated corridor (the generator's ray caster, with its truth), for the tests
// that need a plain scene: the scene options they vary, the rest the generator's defaults.
// Empty (and a test failure) when it cannot be rendered.
inline synth::Frame RenderCorridorFrame(const Camera& camera, double width, double ceiling_height,
                                        uint32_t seed, const synth::CameraPose& pose,
                                        double clutter = synth::SceneOptions().clutter) {
  synth::SceneOptions scene;
  scene.width = width;
  scene.ceiling_height = ceiling_height;
  scene.clutter = clutter;
  scene.seed = seed;
  synth::Frame frame;
  EXPECT_TRUE(synth::RenderFrame(synth::BuildScene(scene), camera, pose, &frame).ok());
  return frame;
}

// `truth` with side `side`'s wall distance (0 left, 1 right) multiplied by `factor`: a wall put too
// near (< 1) or too far (> 1), the other where it is.
inline CorridorGeometry WithWallScaled(const CorridorGeometry& truth, int side, double factor) {
  double distance[2] = {truth.LeftDistance(), truth.RightDistance()};
  distance[side] *= factor;
  CorridorGeometry g = truth;
  g.SetWallDistances(distance[0], distance[1]);
  return g;
}

// The paper preset's scene `name` (a test failure, and an empty preset, when there is none).
inline synth::ScenePreset PaperScene(const std::string& name) {
  for (const auto& preset : synth::PaperPreset()) {
    if (preset.name == name) return preset;
  }
  ADD_FAILURE() << "no " << name << " in the paper preset";
  return synth::ScenePreset();
}

// The pixel of the floor point (x, h, z) (x across the corridor from the camera, z ahead)
// projected by hand: P_C = R_x(pitch) R_y(yaw) P_W.
inline Eigen::Vector2d ProjectFloorPoint(const CorridorGeometry& g, const Camera& c, double x,
                                         double z) {
  const double x1 = std::cos(g.yaw) * x + std::sin(g.yaw) * z;
  const double z1 = -std::sin(g.yaw) * x + std::cos(g.yaw) * z;
  const double yc = std::cos(g.pitch) * g.camera_height - std::sin(g.pitch) * z1;
  const double zc = std::sin(g.pitch) * g.camera_height + std::cos(g.pitch) * z1;
  return Eigen::Vector2d(c.fx * x1 / zc + c.cx, c.fy * yc / zc + c.cy);
}

// The image line of the floor/wall junction (X, h, Z), Z in R (side < 0: left), through two
// points projected by hand (ProjectFloorPoint), normalised (a^2 + b^2 = 1).
inline Eigen::Vector3d TrueJunction(const CorridorGeometry& g, const Camera& c, int side) {
  const double x = side < 0 ? -(g.width / 2 + g.offset) : g.width / 2 - g.offset;
  Eigen::Vector3d points[2];
  for (int i = 0; i < 2; ++i) {
    points[i] = ProjectFloorPoint(g, c, x, i == 0 ? 3.0 : 12.0).homogeneous();
  }
  Eigen::Vector3d line = points[0].cross(points[1]);
  return line / line.head<2>().norm();
}

// A generated corridor (1.8 m wide, no baseboard, 2 m floor tiles: no grout line near the walls)
// whose right floor/wall junction is broken every 22 px along the line by a door's dark bottom
// 10 px long, mirrored by a glossy floor (as the doors of the real photo rtabmap_6 break its faint
// junction): a dark patch across the junction with a flat top and bottom and vertical sides, none
// of them along a junction. The pieces left are too short for the junction search's first Hough.
inline synth::Frame CorridorWithBrokenRightJunction(const Camera& camera,
                                                    const synth::CameraPose& pose) {
  synth::SceneOptions scene;
  scene.width = 1.8;
  scene.tile_size = 2.0;
  scene.baseboard_height = 0.0;
  scene.door_density = 0.0;
  scene.seed = 5;
  synth::Frame frame;
  EXPECT_TRUE(synth::RenderFrame(synth::BuildScene(scene), camera, pose, &frame).ok());
  if (frame.bgr.empty()) return frame;
  const Eigen::Vector3d left = TrueJunction(frame.truth, camera, -1);
  const Eigen::Vector3d right = TrueJunction(frame.truth, camera, 1);
  const Eigen::Vector3d vp3 = left.cross(right);
  const Eigen::Vector2d vp = vp3.head<2>() / vp3.z();
  // Along the right junction, from the vanishing point down to the bottom row.
  const Eigen::Vector2d direction =
      Eigen::Vector2d(right.y(), -right.x()) * (right.x() < 0 ? 1.0 : -1.0);
  EXPECT_GT(direction.y(), 0);
  if (!(direction.y() > 0)) return frame;
  const double period = 22, gap = 10;
  for (double t = 12; vp.y() + t * direction.y() < camera.image_height; t += period) {
    const Eigen::Vector2d a = vp + t * direction, b = vp + (t + gap) * direction;
    cv::rectangle(frame.bgr, cv::Point(cvRound(a.x()), cvRound(std::min(a.y(), b.y())) - 8),
                  cv::Point(cvRound(b.x()), cvRound(std::max(a.y(), b.y())) + 8),
                  cv::Scalar(50, 45, 45), cv::FILLED);
  }
  return frame;
}

}  // namespace testing_util
}  // namespace corridor
