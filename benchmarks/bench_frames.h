#pragma once

// Rendered corridor frames shared by the corridor benchmarks: a paper-preset-like scene
// (Cord_E01's corridor and pose) at any size, the paper's 420x360 camera with fx scaled by the
// width. Rendered once per size, outside any timing loop.

#include <cmath>
#include <map>
#include <string>
#include <utility>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "synth/corridor_renderer.h"
#include "synth/presets.h"

namespace corridor {
namespace bench {

struct BenchFrame {
  Camera camera;
  synth::Frame frame;  // bgr and its ground truth.
};

// The paper camera (fx = fy = 250 at 420 px wide) scaled by the width, at width x height: the
// paper's horizontal field of view at any aspect ratio.
inline Camera ScaledPaperCamera(int width, int height, double mount_height) {
  Camera camera = synth::PaperCamera(mount_height, width / 420.0);
  camera.image_width = width;
  camera.image_height = height;
  camera.cy = 0.5 * (height - 1);
  return camera;
}

// Cord_E01 of the paper preset at frame `index` of a short drive (distance grows 0.35 m a frame).
inline synth::CameraPose PaperLikePose(int index) {
  synth::CameraPose pose;
  pose.yaw = 0.03 + 0.01 * std::sin(0.7 * index);
  pose.pitch = 0.04 + 0.005 * std::cos(0.9 * index);
  pose.offset = 0.10 + 0.05 * std::sin(0.5 * index);
  pose.height = 0.66;
  pose.distance = 2.0 + 0.35 * index;
  return pose;
}

inline synth::SceneOptions PaperLikeScene() {
  synth::SceneOptions scene;
  scene.width = 2.11;
  scene.ceiling_height = 2.7;
  scene.length = 45.0;
  scene.clutter = 0.0;
  scene.door_density = 0.3;
  scene.floor_wall_contrast = 0.9;
  scene.baseboard_contrast = 0.6;
  scene.seed = 101;
  return scene;
}

// Frame `index` (see PaperLikePose) at width x height; rendered on first use, then cached.
// Not thread-safe: call from benchmark set-up, which Google Benchmark runs on one thread.
inline const BenchFrame& PaperLikeFrame(int width, int height, int index = 0) {
  static std::map<std::pair<std::pair<int, int>, int>, BenchFrame> cache;
  const auto key = std::make_pair(std::make_pair(width, height), index);
  auto it = cache.find(key);
  if (it == cache.end()) {
    BenchFrame f;
    f.camera = ScaledPaperCamera(width, height, 0.66);
    synth::RenderFrame(PaperLikeScene(), f.camera, PaperLikePose(index), &f.frame);
    it = cache.emplace(key, std::move(f)).first;
  }
  return it->second;
}

// The image sizes of every corridor benchmark.
constexpr int kSizes[][2] = {{420, 360}, {640, 480}, {1280, 720}};

// "640x480".
inline std::string SizeName(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace bench
}  // namespace corridor
