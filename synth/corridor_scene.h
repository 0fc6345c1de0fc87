#pragma once

#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "synth/scene_options.h"

namespace corridor {
namespace synth {

// The generator's own world frame (independent of the estimator's conventions): x to the right
// of the corridor's axis, y UP from the floor, z along the corridor from its start. Floor y = 0,
// ceiling y = ceiling_height, walls x = -width/2 and x = +width/2, end wall z = length.

// A door set back into a wall: the wall is open over [z0, z1] x [0, height]; the leaf stands
// `recess` behind the wall plane; a frame band surrounds the opening on the wall.
struct Door {
  int side = -1;              // -1 left wall, +1 right wall.
  double z0 = 0, z1 = 0;      // Along the corridor, m.
  double height = 2.05;       // Opening height, m.
  double recess = 0.15;       // Depth of the leaf behind the wall plane, m.
  cv::Vec3f leaf_color;       // BGR in [0, 1].
  cv::Vec3f frame_color;      // BGR in [0, 1].
};

// An axis-aligned box standing on the floor (boxes, bins, cabinets).
struct Obstacle {
  Eigen::Vector3d min, max;  // Corners in the world frame, m.
  cv::Vec3f color;           // BGR in [0, 1].
};

// A ceiling light panel.
struct Light {
  double x0, x1, z0, z1;  // Extent on the ceiling, m.
};

struct CorridorScene {
  SceneOptions options;
  std::vector<Door> doors;
  std::vector<Obstacle> obstacles;
  std::vector<Light> lights;
  cv::Vec3f wall_color, floor_color, grout_color, baseboard_color, ceiling_color, end_color;
};

// The scene's random content, a function of the options (and their seed) only.
CorridorScene BuildScene(const SceneOptions& options);

}  // namespace synth
}  // namespace corridor
