#pragma once

// One frame of the generator's real-buildings preset, rendered as the preset renders it, with the
// scene's true width: for tests that need a class's frame (a handrail, a bench, a head-mounted
// camera) with exact truth.

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "corridor_depth/camera.h"
#include "corridor_depth/recover_depth.h"
#include "synth/corridor_renderer.h"
#include "synth/real_buildings.h"

namespace corridor {
namespace testing_util {

struct PresetFrame {
  synth::Frame frame;  // Empty bgr when the preset or the render failed.
  Camera camera;
  double true_width = 0;
};

// Frame `index` of scene `scene` of the class `class_name` ("rail", "furniture", "head", ...),
// rendered `width_px` x `height_px` (the preset's 80-degree view).
inline PresetFrame RenderPreset(const std::string& class_name, int scene, int index,
                                int width_px = 640, int height_px = 480) {
  synth::RealBuildingsOptions options;
  options.scenes = scene + 1;
  options.frames = index + 1;
  options.width_px = width_px;
  options.height_px = height_px;
  std::vector<synth::ScenePreset> presets;
  PresetFrame out;
  if (!synth::RealBuildingsPreset(class_name, options, &presets).ok()) return out;
  const synth::ScenePreset& preset = presets.at(static_cast<size_t>(scene));
  out.camera = preset.camera;
  out.true_width = preset.scene.width;
  if (!synth::RenderFrame(preset.scene, preset.camera, preset.poses.at(static_cast<size_t>(index)),
                          &out.frame)
           .ok()) {
    out.frame.bgr.release();
  }
  return out;
}

// The relative width error of `f` recovered with `options`; NaN when the frame is not ok.
inline double RecoveredWidthError(const PresetFrame& f, const RecoverDepthOptions& options) {
  RecoverDepthResult result;
  if (!RecoverDepth(f.frame.bgr, f.camera, options, &result).ok()) return std::nan("");
  return std::abs(result.geometry.width - f.true_width) / f.true_width;
}

// Recovers `f` with no confidence bar, expecting a width more than `off` (relative) from the true
// one, then with the default options, expecting a refusal for low confidence whose message
// contains `because`; `label` names the frame in failures. Returns the unbarred result, for the
// caller's checks of its evidence.
inline RecoverDepthResult ExpectOffThenRefused(const PresetFrame& f, double off,
                                               const std::string& because,
                                               const std::string& label) {
  RecoverDepthOptions unbarred;
  unbarred.min_confidence = 0;
  RecoverDepthResult result;
  EXPECT_TRUE(RecoverDepth(f.frame.bgr, f.camera, unbarred, &result).ok()) << label;
  EXPECT_GT(std::abs(result.geometry.width - f.true_width) / f.true_width, off) << label;
  RecoverDepthResult refused;
  const Status status = RecoverDepth(f.frame.bgr, f.camera, RecoverDepthOptions(), &refused);
  EXPECT_EQ(status.code(), StatusCode::kLowConfidence) << label << ": " << status.ToString();
  EXPECT_NE(status.message().find(because), std::string::npos) << label << ": "
                                                               << status.message();
  return result;
}

}  // namespace testing_util
}  // namespace corridor
