#include "synth/presets.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "corridor_depth/camera_yaml.h"
#include "corridor_depth/dataset.h"
#include "corridor_depth/image_io.h"
#include "corridor_depth/truth_yaml.h"
#include "synth/corridor_renderer.h"
#include "synth/corridor_scene.h"
#include "synth/sequence.h"

namespace corridor {
namespace synth {
namespace {

struct PaperScene {
  const char* name;
  double width, camera_height, yaw, pitch, offset;
  double clutter, door_density, contrast, baseboard_contrast;
};

// Widths and heights in the paper's ranges; the hard scenes add clutter, low contrast and doors.
constexpr PaperScene kPaperScenes[] = {
    {"Cord_E01", 2.11, 0.66, 0.03, 0.04, 0.10, 0.0, 0.3, 0.9, 0.6},
    {"Cord_E02", 2.13, 0.66, -0.05, 0.06, -0.15, 0.0, 0.5, 0.8, 0.5},
    {"Cord_E03", 2.11, 0.62, 0.08, 0.02, 0.20, 0.1, 0.4, 0.9, 0.7},
    {"Cord_E04", 2.09, 0.62, -0.10, 0.08, -0.05, 0.0, 0.6, 0.7, 0.4},
    {"Cord_E05", 2.02, 0.66, 0.00, 0.05, 0.00, 0.1, 0.5, 0.8, 0.6},
    {"Cord_E06", 1.86, 0.62, 0.06, 0.03, -0.20, 0.0, 0.4, 1.0, 0.5},
    {"Cord_H01", 2.13, 0.66, -0.08, 0.07, 0.25, 0.6, 0.8, 0.35, 0.2},
    {"Cord_H02", 3.09, 0.62, 0.10, 0.05, -0.35, 0.8, 0.9, 0.3, 0.8},
    {"Cord_H03", 2.98, 0.66, -0.04, 0.10, 0.30, 0.7, 0.7, 0.25, 0.3},
};

}  // namespace

Camera PaperCamera(double mount_height, double scale) {
  Camera camera;
  camera.image_width = static_cast<int>(std::lround(420 * scale));
  camera.image_height = static_cast<int>(std::lround(360 * scale));
  camera.fx = camera.fy = 250.0 * scale;
  camera.cx = 0.5 * (camera.image_width - 1);
  camera.cy = 0.5 * (camera.image_height - 1);
  camera.mount_height = mount_height;
  return camera;
}

std::vector<ScenePreset> PaperPreset(double scale) {
  std::vector<ScenePreset> presets;
  uint32_t seed = 101;
  for (const PaperScene& p : kPaperScenes) {
    ScenePreset preset;
    preset.name = p.name;
    preset.scene.width = p.width;
    preset.scene.ceiling_height = 2.6 + 0.1 * (seed % 4);
    preset.scene.length = 45.0;
    preset.scene.clutter = p.clutter;
    preset.scene.door_density = p.door_density;
    preset.scene.floor_wall_contrast = p.contrast;
    preset.scene.baseboard_contrast = p.baseboard_contrast;
    preset.scene.seed = seed;
    preset.camera = PaperCamera(p.camera_height, scale);
    SequenceOptions sequence;
    sequence.frames = 15;
    sequence.base.yaw = p.yaw;
    sequence.base.pitch = p.pitch;
    sequence.base.offset = p.offset;
    sequence.base.height = p.camera_height;
    sequence.base.distance = 2.0;
    sequence.seed = seed;
    preset.poses = MakeSequence(sequence);
    presets.push_back(preset);
    seed += 17;
  }
  return presets;
}

Status WriteScene(const std::string& root, const ScenePreset& preset,
                  const std::function<void(int, int)>& progress) {
  std::string rgb_dir, depth_dir;
  Status status = MakeSceneDirs(root, preset.name, &rgb_dir, &depth_dir);
  if (!status.ok()) return status;
  const std::filesystem::path scene_dir = std::filesystem::path(root) / preset.name;
  status = WriteCameraYaml((scene_dir / "camera.yaml").string(), preset.camera);
  if (!status.ok()) return status;
  const CorridorScene scene = BuildScene(preset.scene);
  std::vector<FrameTruth> truths;
  const int total = static_cast<int>(preset.poses.size());
  for (int i = 0; i < total; ++i) {
    char name[32];
    std::snprintf(name, sizeof(name), "%06d", i);
    Frame frame;
    status = RenderFrame(scene, preset.camera, preset.poses[i], &frame);
    if (!status.ok()) return Status(status.code(), preset.name + "/" + name + ": " + status.message());
    status = WriteImageAtomic((std::filesystem::path(rgb_dir) / (std::string(name) + ".png")).string(),
                              frame.bgr);
    if (status.ok()) {
      status = WriteDepthPng(
          (std::filesystem::path(depth_dir) / (std::string(name) + ".png")).string(), frame.depth);
    }
    if (!status.ok()) return status;
    truths.push_back({std::string(name) + ".png", frame.truth});
    if (progress) progress(i + 1, total);
  }
  return WriteTruthYaml((scene_dir / "truth.yaml").string(), truths);
}

}  // namespace synth
}  // namespace corridor
