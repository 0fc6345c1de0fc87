// The confidence mask against the generator's ground truth: pixels where the true depth departs
// from the pure box model (boxes, door recesses) should be untrusted, the others trusted.
#include "pipeline/confidence_mask.h"

#include <gtest/gtest.h>

#include "depth/exact_rasterizer.h"
#include "synth/corridor_renderer.h"
#include "synth/presets.h"

namespace corridor {
namespace {

TEST(ConfidenceMaskTest, FlagsWhatTheBoxModelDoesNotExplain) {
  auto presets = synth::PaperPreset();
  const auto& preset = presets[6];  // Cord_H01: boxes and doors.
  const synth::CorridorScene scene = synth::BuildScene(preset.scene);
  int64_t violating = 0, violating_flagged = 0, consistent = 0, consistent_trusted = 0;
  for (size_t f : {size_t{2}, size_t{9}}) {
    synth::Frame frame;
    ASSERT_TRUE(synth::RenderFrame(scene, preset.camera, preset.poses[f], &frame).ok());
    RasterizerOptions options;
    options.max_range = 40;
    cv::Mat model;
    ASSERT_TRUE(ExactRasterizer(options).Render(frame.truth, preset.camera, &model).ok());
    const cv::Mat mask = ComputeConfidenceMask(frame.bgr, model, preset.camera, frame.truth);
    ASSERT_EQ(mask.type(), CV_8U);
    for (int v = 0; v < mask.rows; ++v) {
      for (int u = 0; u < mask.cols; ++u) {
        const float gt = frame.depth.at<float>(v, u), m = model.at<float>(v, u);
        if (gt <= 0 || m <= 0 || gt > 15) continue;
        const bool departs = std::abs(gt - m) > 0.1 * gt;
        const bool trusted = mask.at<uchar>(v, u) == 255;
        if (departs) {
          ++violating;
          violating_flagged += !trusted;
        } else {
          ++consistent;
          consistent_trusted += trusted;
        }
      }
    }
  }
  ASSERT_GT(violating, 500);
  const double recall = static_cast<double>(violating_flagged) / violating;
  const double kept = static_cast<double>(consistent_trusted) / consistent;
  std::printf("untrusted among model-violating pixels %.3f, trusted among consistent %.3f\n",
              recall, kept);
  // Objects on the floor are found; doors and furniture against the walls mostly are not yet,
  // hence the low bar on recall.
  EXPECT_GT(recall, 0.12);
  EXPECT_GT(kept, 0.95);
}

TEST(ConfidenceMaskTest, NoEstimateIsNotTrusted) {
  const Camera camera = synth::PaperCamera(0.66);
  const cv::Mat bgr(camera.image_height, camera.image_width, CV_8UC3, cv::Scalar(120, 120, 120));
  const cv::Mat depth = cv::Mat::zeros(camera.image_height, camera.image_width, CV_32F);
  CorridorGeometry g;
  g.width = 2;
  g.camera_height = 0.66;
  EXPECT_EQ(cv::countNonZero(ComputeConfidenceMask(bgr, depth, camera, g)), 0);
}

}  // namespace
}  // namespace corridor
