#pragma once

#include <functional>
#include <string>
#include <vector>

#include "corridor_depth/camera.h"
#include "corridor_depth/status.h"
#include "synth/scene_options.h"

namespace corridor {
namespace synth {

// A scene to generate: its content, camera and poses.
struct ScenePreset {
  std::string name;               // Scene folder name, e.g. "Cord_E01".
  SceneOptions scene;             // Content.
  Camera camera;                  // Intrinsics; mount_height is written to camera.yaml.
  std::vector<CameraPose> poses;  // One frame per pose.
};

// The paper's dataset, mirrored: 9 scenes of 15 frames at 420x360 (fx = fy = 250), 6 easy
// (Cord_E01..E06) and 3 hard (Cord_H01..H03: clutter, low floor/wall contrast, doors, boxes that
// hide a junction), widths 1.8-3.1 m, camera heights 0.62 and 0.66 m. `scale` renders the same
// scenes and poses through PaperCamera(height, scale): the same view at finer or coarser pixels.
std::vector<ScenePreset> PaperPreset(double scale = 1.0);

// The paper's 420x360 pinhole (fx = fy = 250, centred principal point) at `mount_height`; with
// `scale`, round(420 scale) x round(360 scale) pixels and fx = fy = 250 scale, centred (the same
// field of view).
Camera PaperCamera(double mount_height, double scale = 1.0);

// Writes one scene in the dataset layout: <root>/<name>/rgb/<frame>.png,
// <root>/<name>/depth/<frame>.png (16-bit mm), camera.yaml and truth.yaml; frames "000000", ...
// `progress` (may be empty) is called after each frame with (done, total).
Status WriteScene(const std::string& root, const ScenePreset& preset,
                  const std::function<void(int, int)>& progress);

}  // namespace synth
}  // namespace corridor
