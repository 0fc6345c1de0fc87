#include "synth/corridor_scene.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace corridor {
namespace synth {
namespace {

class Random {
 public:
  explicit Random(uint32_t seed) : engine_(seed) {}
  // Uniform in [lo, hi), from raw 32-bit draws so that it is the same on every platform.
  double Uniform(double lo, double hi) { return lo + (hi - lo) * (engine_() / 4294967296.0); }
  bool Chance(double p) { return Uniform(0, 1) < p; }

 private:
  std::mt19937 engine_;
};

cv::Vec3f Mix(const cv::Vec3f& a, const cv::Vec3f& b, double t) {
  return a * static_cast<float>(1 - t) + b * static_cast<float>(t);
}

}  // namespace

CorridorScene BuildScene(const SceneOptions& options) {
  CorridorScene scene;
  scene.options = options;
  Random random(options.seed);
  // Painted walls: a light, slightly warm grey; the floor a darker, more saturated tone.
  scene.wall_color = cv::Vec3f(static_cast<float>(random.Uniform(0.62, 0.78)),
                               static_cast<float>(random.Uniform(0.68, 0.80)),
                               static_cast<float>(random.Uniform(0.72, 0.84)));
  const cv::Vec3f floor_tone(static_cast<float>(random.Uniform(0.20, 0.40)),
                             static_cast<float>(random.Uniform(0.30, 0.45)),
                             static_cast<float>(random.Uniform(0.40, 0.60)));
  scene.floor_color = Mix(scene.wall_color * 0.9f, floor_tone, options.floor_wall_contrast);
  scene.grout_color = scene.floor_color * 0.75f;
  scene.baseboard_color = scene.wall_color * static_cast<float>(1 - 0.8 * options.baseboard_contrast);
  scene.ceiling_color = cv::Vec3f(0.85f, 0.86f, 0.86f);
  scene.end_color = scene.wall_color * 0.92f;
  const double half = 0.5 * options.width;

  for (int side = -1; side <= 1; side += 2) {
    for (double z = random.Uniform(1.5, 4.0); z + 1.2 < options.length - 1.0;
         z += random.Uniform(4.0, 6.0)) {
      if (!random.Chance(options.door_density)) continue;
      Door door;
      door.side = side;
      door.z0 = z;
      door.z1 = z + random.Uniform(0.85, 1.1);
      door.height = random.Uniform(1.95, 2.15);
      door.recess = random.Uniform(0.05, 0.3);
      const double wood = random.Uniform(0, 1);
      door.leaf_color = wood < 0.5 ? cv::Vec3f(0.18f, 0.32f, 0.48f) * static_cast<float>(random.Uniform(0.7, 1.2))
                                   : cv::Vec3f(0.45f, 0.42f, 0.38f) * static_cast<float>(random.Uniform(0.6, 1.1));
      door.frame_color = scene.wall_color * static_cast<float>(random.Uniform(0.45, 0.7));
      scene.doors.push_back(door);
    }
  }
  const int obstacles = static_cast<int>(std::round(options.clutter * options.length / 3.0));
  for (int i = 0; i < obstacles; ++i) {
    const int side = random.Chance(0.5) ? -1 : 1;
    const double depth = random.Uniform(0.3, std::min(0.8, 0.35 * options.width));
    const double gap = random.Uniform(0.0, 0.15);  // Against the wall: hides the junction.
    const double z = random.Uniform(2.0, options.length - 2.0);
    Obstacle box;
    const double wall = side * half;
    const double inner = wall - side * (gap + depth), outer = wall - side * gap;
    box.min = Eigen::Vector3d(std::min(inner, outer), 0.0, z);
    box.max = Eigen::Vector3d(std::max(inner, outer), random.Uniform(0.3, 1.1),
                              z + random.Uniform(0.3, 0.9));
    box.color = cv::Vec3f(static_cast<float>(random.Uniform(0.1, 0.7)),
                          static_cast<float>(random.Uniform(0.1, 0.7)),
                          static_cast<float>(random.Uniform(0.1, 0.7)));
    scene.obstacles.push_back(box);
  }
  if (options.lights) {
    for (double z = 1.5; z + 1.2 < options.length; z += 3.0) {
      scene.lights.push_back({-0.3, 0.3, z, z + 1.2});
    }
  }
  return scene;
}

}  // namespace synth
}  // namespace corridor
