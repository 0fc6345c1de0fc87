#pragma once

// Private helper of the ceiling and end-wall searches: corridor-frame points to raw pixels.

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_frame.h"

namespace corridor {

// Raw pixel of the corridor-frame point (x, y, z): false when it is behind the camera (z_C below
// 5 cm) or closer than `margin` px to the image border. `distorted` is camera.HasDistortion(),
// hoisted out of the callers' loops.
inline bool ProjectCorridorPoint(const Camera& camera, bool distorted,
                                 const CorridorRotation<double>& r, double x, double y, double z,
                                 int margin, cv::Point* pixel) {
  const Vec3<double> c = r.ToCamera({x, y, z});
  if (c.z < 0.05) return false;
  const Eigen::Vector2d ideal = camera.Project({c.x, c.y, c.z});
  const Eigen::Vector2d raw = distorted ? camera.Distort(ideal) : ideal;
  if (!raw.allFinite()) return false;
  pixel->x = cvRound(raw.x());
  pixel->y = cvRound(raw.y());
  return pixel->x >= margin && pixel->y >= margin && pixel->x < camera.image_width - margin &&
         pixel->y < camera.image_height - margin;
}

}  // namespace corridor
