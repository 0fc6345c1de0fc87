// The ceiling search on generated corridors, given their true walls (from truth), against the
// true ceiling height; and no ceiling where the image shows none.
#include "perception/ceiling_detector.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "synth/corridor_renderer.h"
#include "synth/presets.h"

namespace corridor {
namespace {

TEST(CeilingDetectorTest, FindsTheCeilingHeightOfGeneratedCorridors) {
  int checked = 0;
  for (const auto& preset : synth::PaperPreset()) {
    if (preset.name.find("_E") == std::string::npos) continue;
    const synth::CorridorScene scene = synth::BuildScene(preset.scene);
    synth::Frame frame;
    ASSERT_TRUE(synth::RenderFrame(scene, preset.camera, preset.poses[4], &frame).ok());
    CeilingEstimate estimate;
    ASSERT_TRUE(
        DetectCeiling(frame.bgr, preset.camera, frame.truth, CeilingDetectorOptions(), &estimate)
            .ok());
    ASSERT_TRUE(estimate.found) << preset.name << ": " << estimate.reason;
    EXPECT_NEAR(estimate.height, preset.scene.ceiling_height, 0.03 * preset.scene.ceiling_height)
        << preset.name;
    EXPECT_GT(estimate.points, 20);
    ++checked;
  }
  EXPECT_EQ(checked, 6);
}

TEST(CeilingDetectorTest, NoCeilingInAFeaturelessUpperImage) {
  const Camera camera = synth::PaperCamera(0.66);
  cv::Mat image(camera.image_height, camera.image_width, CV_8UC3, cv::Scalar(180, 180, 180));
  cv::rectangle(image, cv::Rect(0, 200, camera.image_width, 160), cv::Scalar(60, 80, 120),
                cv::FILLED);
  CorridorGeometry g;
  g.width = 2.2;
  g.camera_height = 0.66;
  g.pitch = 0.05;
  CeilingEstimate estimate;
  ASSERT_TRUE(DetectCeiling(image, camera, g, CeilingDetectorOptions(), &estimate).ok());
  EXPECT_FALSE(estimate.found);
  EXPECT_FALSE(estimate.reason.empty());
}

TEST(CeilingDetectorTest, RejectsBadOptionsAndImages) {
  CeilingDetectorOptions o;
  o.max_height = 1.0;
  std::string why;
  EXPECT_FALSE(o.Check(&why));
  CeilingEstimate estimate;
  CorridorGeometry g;
  EXPECT_EQ(DetectCeiling(cv::Mat(), synth::PaperCamera(0.66), g, CeilingDetectorOptions(), &estimate)
                .code(),
            StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace corridor
