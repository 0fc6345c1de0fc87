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
  int side = -1;          // -1 left wall, +1 right wall.
  double z0 = 0, z1 = 0;  // Along the corridor, m.
  double height = 2.05;   // Opening height, m.
  double recess = 0.15;   // Depth of the leaf behind the wall plane, m.
  cv::Vec3f leaf_color;   // BGR in [0, 1].
  cv::Vec3f frame_color;  // BGR in [0, 1].
};

// An axis-aligned solid box: clutter on the floor, and the solid parts of real buildings.
struct Obstacle {
  enum Kind { kClutter,
              kHandrail,
              kChairRail,
              kFurniture,
              kPillar,
              kSill };
  Eigen::Vector3d min, max;  // Corners in the world frame, m.
  cv::Vec3f color;           // BGR in [0, 1].
  Kind kind = kClutter;
};

// A run of glass in a wall (side -1 or +1) over [z0, z1] x [0, top]. The glass plane is the
// surface (its depth is the truth); its colour is mostly the lit room behind it: a floor, a back
// wall `room_depth` behind the glass with desks (a band up to desk_height) and shelf uprights,
// its own ceiling. Mullions and a base rail are paint on the plane.
struct GlassRun {
  int side = -1;
  double z0 = 0, z1 = 0, top = 2.7;
  double room_depth = 4.0;       // Back wall behind the glass plane, m.
  double room_light = 1.0;       // Brightness of the room behind relative to the corridor.
  double desk_height = 0.75;     // Top of the desk band on the back wall, m.
  double mullion_spacing = 1.2;  // Vertical frame bars, m apart.
  double mullion_width = 0.05;   // m.
  double base_height = 0.06;     // Frame rail along the floor, m.
  cv::Vec3f frame_color, room_floor_color, room_wall_color, desk_color;
};

// A band of windows in a wall over [z0, z1] between heights sill and top, panes `pane` wide
// separated by `mullion`; the view outside is bright (emissive) sky above a darker band.
struct WindowBand {
  int side = -1;
  double z0 = 0, z1 = 0, sill = 0.9, top = 2.0;
  double pane = 1.4, mullion = 0.15;
  double horizon = 0.4;  // Fraction of the pane height below which the view is dark.
  cv::Vec3f sky_color, ground_color, frame_color;
};

// Paint on the walls and the floor.
struct Paintwork {
  double wainscot_height = 0;  // Top of the lower wall panel, m (0 = none).
  double wainscot_cap = 0;     // Height of the cap line above the panel, m.
  cv::Vec3f wainscot_color, wainscot_cap_color;
  double runner_x0 = 0, runner_x1 = 0;  // Carpet runner across the corridor, m (empty = none).
  double runner_border = 0;             // Border band width along the runner's edges, m.
  cv::Vec3f runner_color, runner_border_color;
  double stripe_inset = 0;  // Floor stripes' distance from each wall, m (0 = none).
  double stripe_width = 0;  // m.
  cv::Vec3f stripe_color;
  double carpet_grain = 0;      // Carpet texture cell, m (0 = tiles with grout).
  double carpet_amplitude = 0;  // Relative brightness variation of the carpet texture.
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
  std::vector<GlassRun> glass;
  std::vector<WindowBand> windows;
  Paintwork paint;
  cv::Vec3f wall_color, floor_color, grout_color, baseboard_color, ceiling_color, end_color;
};

// The scene's random content, a function of the options (and their seed) only.
CorridorScene BuildScene(const SceneOptions& options);

}  // namespace synth
}  // namespace corridor
