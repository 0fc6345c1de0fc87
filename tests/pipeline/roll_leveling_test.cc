// level_roll end to end on rolled frames of the generator's head-mounted class: the roll the
// frame was recovered level from against the pose's, and the depth, turned back to the frame's
// pixels, against the ray-cast truth, with and without levelling; and a level frame that is less
// sure of its layout than the frame as seen, left untaken; a frame refused as seen, recovered
// level.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "corridor_depth/recover_depth.h"
#include "synth/corridor_renderer.h"
#include "synth/real_buildings.h"
#include "tests/support/preset_frame.h"

namespace corridor {
namespace {

// Mean |d - t| / t over the pixels with truth below 5 m and an estimate.
double AbsRelBelow5m(const cv::Mat& depth, const cv::Mat& truth) {
  double sum = 0;
  long count = 0;
  for (int v = 0; v < truth.rows; ++v) {
    for (int u = 0; u < truth.cols; ++u) {
      const float t = truth.at<float>(v, u), d = depth.at<float>(v, u);
      if (!(t > 0 && t < 5) || !std::isfinite(d)) continue;
      sum += std::abs(d - t) / t;
      ++count;
    }
  }
  return count > 0 ? sum / count : NAN;
}

// Scene `scene` of the head-mounted class, with its first `frames` poses.
synth::ScenePreset HeadScene(int scene, int frames) {
  synth::RealBuildingsOptions preset_options;
  preset_options.scenes = scene + 1;
  preset_options.frames = frames;
  std::vector<synth::ScenePreset> presets;
  EXPECT_TRUE(synth::RealBuildingsPreset("head", preset_options, &presets).ok());
  return presets.empty() ? synth::ScenePreset() : presets.back();
}

TEST(RollLevelingTest, ARolledFrameIsRecoveredLevel) {
  const synth::ScenePreset preset = HeadScene(0, 11);
  ASSERT_EQ(preset.poses.size(), 11u);
  RecoverDepthOptions as_seen_options, level_options;
  as_seen_options.level_roll = false;
  level_options.level_roll = true;
  std::unique_ptr<DepthRecoverer> as_seen, level;
  ASSERT_TRUE(DepthRecoverer::Create(as_seen_options, &as_seen).ok());
  ASSERT_TRUE(DepthRecoverer::Create(level_options, &level).ok());
  for (const int i : {9, 10}) {  // Rolls of -3.0 and -2.6 degrees.
    const synth::CameraPose& pose = preset.poses[i];
    synth::Frame frame;
    ASSERT_TRUE(synth::RenderFrame(preset.scene, preset.camera, pose, &frame).ok());
    RecoverDepthResult seen, turned;
    ASSERT_TRUE(as_seen->Recover(frame.bgr, preset.camera, &seen).ok());
    ASSERT_TRUE(level->Recover(frame.bgr, preset.camera, &turned).ok());
    const double seen_error = AbsRelBelow5m(seen.depth, frame.depth);
    const double level_error = AbsRelBelow5m(turned.depth, frame.depth);
    std::printf("frame %d: roll %.2f deg, found %.2f deg; AbsRel < 5 m %.4f as seen, %.4f level\n",
                i, pose.roll * 180 / M_PI, turned.roll * 180 / M_PI, seen_error, level_error);
    EXPECT_EQ(seen.roll, 0);
    EXPECT_NEAR(turned.roll, pose.roll, 0.2 * M_PI / 180) << i;
    EXPECT_NE(turned.fallback.find("recovered level"), std::string::npos) << turned.fallback;
    EXPECT_EQ(turned.depth.size(), frame.bgr.size());
    EXPECT_LT(level_error, 0.7 * seen_error) << i;
  }
}

TEST(RollLevelingTest, ALevelFrameLessSureThanTheFrameAsSeenIsNotTaken) {
  // Head scene 8, frame 4: turned level, the frame's width comes out 8.8% off with a confidence
  // of 0.9; as seen, 0.4% off with a confidence of 1.
  const synth::ScenePreset preset = HeadScene(8, 5);
  ASSERT_EQ(preset.poses.size(), 5u);
  synth::Frame frame;
  ASSERT_TRUE(synth::RenderFrame(preset.scene, preset.camera, preset.poses[4], &frame).ok());
  RecoverDepthOptions options;
  ASSERT_TRUE(options.level_roll);
  RecoverDepthResult result;
  ASSERT_TRUE(RecoverDepth(frame.bgr, preset.camera, options, &result).ok());
  const double width = preset.scene.width;
  std::printf("width %.3f m, true %.3f m; %s\n", result.geometry.width, width,
              result.fallback.c_str());
  EXPECT_LT(std::abs(result.geometry.width - width) / width, 0.03);
  EXPECT_EQ(result.roll, 0);
  EXPECT_NE(result.fallback.find("recovered as seen"), std::string::npos) << result.fallback;
}

TEST(RollLevelingTest, AFrameRefusedAsSeenIsRecoveredLevel) {
  // The mix class's scene 3 (head-mounted), frame 16: as seen, refused for its confidence; turned
  // level, recovered within 3% of the true width.
  const testing_util::PresetFrame f = testing_util::RenderPreset("mix", 3, 16);
  ASSERT_FALSE(f.frame.bgr.empty());
  RecoverDepthOptions options;
  options.level_roll = false;
  RecoverDepthResult seen;
  EXPECT_EQ(RecoverDepth(f.frame.bgr, f.camera, options, &seen).code(), StatusCode::kLowConfidence)
      << seen.status.ToString();
  options.level_roll = true;
  RecoverDepthResult turned;
  ASSERT_TRUE(RecoverDepth(f.frame.bgr, f.camera, options, &turned).ok())
      << turned.status.ToString();
  EXPECT_LT(std::abs(turned.geometry.width - f.true_width) / f.true_width, 0.03);
  EXPECT_NE(turned.roll, 0);
  EXPECT_GE(turned.confidence, options.min_confidence);
  EXPECT_NE(turned.fallback.find("recovered level"), std::string::npos) << turned.fallback;
  EXPECT_FALSE(turned.depth.empty());
}

}  // namespace
}  // namespace corridor
