#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "synth/corridor_scene.h"

namespace corridor {
namespace synth {

// The first surface a ray meets.
struct Hit {
  double t = 0;            // Ray parameter of the hit (origin + t * direction).
  bool found = false;      // False when the ray escapes (never, inside a closed corridor).
  Eigen::Vector3d normal;  // Surface normal facing the ray.
  cv::Vec3f albedo;        // Surface colour, BGR in [0, 1].
  bool emissive = false;   // Light panels shine by themselves.
};

// Casts a ray (world frame of corridor_scene.h) through the scene.
Hit CastRay(const CorridorScene& scene, const Eigen::Vector3d& origin,
            const Eigen::Vector3d& direction);

}  // namespace synth
}  // namespace corridor
