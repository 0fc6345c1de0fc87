#include "synth/presets.h"

#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "corridor_depth/dataset.h"
#include "corridor_depth/image_io.h"
#include "tests/support/camera_expect.h"

namespace corridor {
namespace synth {
namespace {

TEST(PresetsTest, PaperPresetMirrorsThePaperDataset) {
  const auto presets = PaperPreset();
  ASSERT_EQ(presets.size(), 9u);
  int easy = 0, hard = 0;
  for (const auto& p : presets) {
    EXPECT_EQ(p.poses.size(), 15u);
    EXPECT_GE(p.scene.width, 1.8);
    EXPECT_LE(p.scene.width, 3.1);
    EXPECT_TRUE(p.camera.mount_height == 0.62 || p.camera.mount_height == 0.66);
    EXPECT_EQ(p.camera.image_width, 420);
    EXPECT_EQ(p.camera.image_height, 360);
    easy += p.name.rfind("Cord_E", 0) == 0;
    hard += p.name.rfind("Cord_H", 0) == 0;
    std::string why;
    EXPECT_TRUE(p.scene.Check(&why)) << why;
  }
  EXPECT_EQ(easy, 6);
  EXPECT_EQ(hard, 3);
}

// The scaled preset is the same views at finer pixels: the same field of view and principal ray,
// the same scenes and poses.
TEST(PresetsTest, ScaledPaperPresetKeepsTheViews) {
  const auto plain = PaperPreset();
  const auto scaled = PaperPreset(1.5);
  ASSERT_EQ(scaled.size(), plain.size());
  for (size_t i = 0; i < plain.size(); ++i) {
    const Camera& c = scaled[i].camera;
    // (630 - 1) / 2: the image centre, as 209.5 is at 420.
    testing_util::ExpectPinhole(c, 630, 540, 375.0, 375.0, 314.5, 269.5);
    // Half the horizontal field of view, atan(210 / 250), unchanged.
    EXPECT_NEAR(std::atan2(c.image_width / 2.0, c.fx), std::atan2(210.0, 250.0), 1e-12);
    EXPECT_EQ(c.mount_height, plain[i].camera.mount_height);
    EXPECT_EQ(scaled[i].name, plain[i].name);
    EXPECT_EQ(scaled[i].scene.width, plain[i].scene.width);
    ASSERT_EQ(scaled[i].poses.size(), plain[i].poses.size());
    EXPECT_EQ(scaled[i].poses[7].yaw, plain[i].poses[7].yaw);
  }
  testing_util::ExpectPinhole(PaperCamera(0.66), 420, 360, 250.0, 250.0, 209.5, 179.5);
}

TEST(PresetsTest, WriteSceneProducesTheDatasetLayout) {
  const std::string root = ::testing::TempDir() + "/synth_presets_test";
  std::filesystem::remove_all(root);
  ScenePreset preset = PaperPreset()[0];
  preset.poses.resize(2);
  int calls = 0;
  ASSERT_TRUE(WriteScene(root, preset, [&](int, int) { ++calls; }).ok());
  EXPECT_EQ(calls, 2);
  std::vector<DatasetScene> scenes;
  const Status status = LoadDataset(root, &scenes);
  ASSERT_TRUE(status.ok()) << status.ToString();
  ASSERT_EQ(scenes.size(), 1u);
  EXPECT_EQ(scenes[0].name, "Cord_E01");
  EXPECT_DOUBLE_EQ(scenes[0].camera.mount_height, preset.camera.mount_height);
  ASSERT_EQ(scenes[0].frames.size(), 2u);
  for (const auto& frame : scenes[0].frames) {
    EXPECT_TRUE(frame.has_truth);
    EXPECT_DOUBLE_EQ(frame.truth.geometry.width, preset.scene.width);
    cv::Mat depth;
    ASSERT_TRUE(ReadDepthPng(frame.depth_path, &depth).ok());
    EXPECT_EQ(depth.cols, 420);
    EXPECT_GT(cv::countNonZero(depth > 0), depth.total() * 0.95);
  }
}

}  // namespace
}  // namespace synth
}  // namespace corridor
