#include "corridor_depth/evaluation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "tests/evaluation/eval_test_dataset.h"

namespace corridor {
namespace {

using testing_util::EvalTempDir;

std::unique_ptr<DepthRecoverer> MakeRecoverer() {
  RecoverDepthOptions options;
  options.solver = "grid";
  options.rasterizer = "paper";
  std::unique_ptr<DepthRecoverer> recoverer;
  EXPECT_TRUE(DepthRecoverer::Create(options, &recoverer).ok());
  return recoverer;
}

// One scene "Cord_E01" with a real corridor frame 000 at the given pose.
EvalScene MakeScene(const EvalTempDir& dir) {
  testing_util::WriteEvalTestScene(dir.Path("data"), "Cord_E01",
                                   {testing_util::ReliabilityGeometry(0.05, 0.08, 0.1, 2.1)});
  EvalScene scene;
  scene.name = "Cord_E01";
  scene.camera = testing_util::ReliabilityCamera();
  DatasetFrame frame;
  frame.name = "000";
  frame.rgb_path = dir.Path("data/Cord_E01/rgb/000.png");
  frame.depth_path = dir.Path("data/Cord_E01/depth/000.png");
  frame.has_truth = true;
  frame.truth.geometry = testing_util::ReliabilityGeometry(0.05, 0.08, 0.1, 2.1);
  scene.frames.push_back(frame);
  return scene;
}

TEST(AccumulateDepthBins, HandComputed) {
  const cv::Mat gt = (cv::Mat_<float>(1, 5) << 0.5f, 1.5f, 1.8f, 0.0f, 2.5f);
  const cv::Mat pred = (cv::Mat_<float>(1, 5) << 0.6f, 1.5f, 0.0f, 2.0f, 2.0f);
  std::vector<DepthBin> bins;
  AccumulateDepthBins(pred, gt, 2.0, &bins);  // 2.5 is beyond the largest cap.
  ASSERT_EQ(bins.size(), 2u);
  EXPECT_NEAR(bins[0].abs_rel_sum, 0.1f / 0.5f, 1e-6);
  EXPECT_EQ(bins[0].pixels, 1);
  EXPECT_NEAR(bins[1].abs_rel_sum, 0.0, 1e-6);  // 1.8 has no prediction.
  EXPECT_EQ(bins[1].pixels, 1);
}

TEST(FrameEvaluator, GoodFrameIsEvaluatedAndWritten) {
  EvalTempDir dir("frame");
  const EvalScene scene = MakeScene(dir);
  FrameEvalOptions options;
  options.output_dir = dir.Path("out");
  FrameRecord record;
  ASSERT_TRUE(EvaluateFrame(scene, 0, *MakeRecoverer(), options, &record).ok());
  ASSERT_TRUE(record.status.ok()) << record.status.ToString();
  EXPECT_TRUE(record.ran && record.has_estimate && record.has_truth && record.has_depth_truth);
  EXPECT_NEAR(record.estimate.width, 2.1, 0.2);
  ASSERT_EQ(record.metrics.size(), 2u);
  EXPECT_LT(record.metrics[0].abs_rel, 0.15);
  EXPECT_GT(record.metrics[0].coverage, 0.3);
  EXPECT_GE(record.metrics[1].num_gt, record.metrics[0].num_gt);
  EXPECT_EQ(record.depth_bins.size(), 40u);
  EXPECT_GT(record.times.total, 0);
  EXPECT_TRUE(std::filesystem::exists(dir.Path("out/depth/Cord_E01/000.png")));
  const cv::Mat vis = cv::imread(dir.Path("out/vis/Cord_E01/000.png"));
  ASSERT_FALSE(vis.empty());
  EXPECT_GT(vis.cols, 4 * 320);  // Four panels and two colour bars.
}

TEST(FrameEvaluator, UnreadableImageFailsWithCoverageZero) {
  EvalTempDir dir("frame");
  EvalScene scene = MakeScene(dir);
  std::ofstream(scene.frames[0].rgb_path, std::ios::trunc) << "not a png";
  FrameRecord record;
  ASSERT_TRUE(EvaluateFrame(scene, 0, *MakeRecoverer(), FrameEvalOptions(), &record).ok());
  EXPECT_FALSE(record.status.ok());
  EXPECT_NE(record.status.message().find("000.png"), std::string::npos);
  EXPECT_FALSE(record.ran);
  EXPECT_FALSE(record.has_estimate);
  for (const DepthMetrics& m : record.metrics) {
    EXPECT_EQ(m.coverage, 0.0);
    EXPECT_GT(m.num_gt, 0);
    EXPECT_TRUE(std::isnan(m.abs_rel));
  }
}

TEST(FrameEvaluator, DepthSizeMismatchFails) {
  EvalTempDir dir("frame");
  EvalScene scene = MakeScene(dir);
  ASSERT_TRUE(cv::imwrite(scene.frames[0].depth_path, cv::Mat(10, 20, CV_16U, cv::Scalar(2000))));
  FrameRecord record;
  ASSERT_TRUE(EvaluateFrame(scene, 0, *MakeRecoverer(), FrameEvalOptions(), &record).ok());
  EXPECT_FALSE(record.status.ok());
  EXPECT_NE(record.status.message().find("colour image"), std::string::npos)
      << record.status.message();
  EXPECT_EQ(record.metrics[0].coverage, 0.0);
  EXPECT_EQ(record.metrics[0].num_gt, 200);
}

TEST(FrameEvaluator, NoCorridorFailsAndCountsAgainstCoverage) {
  EvalTempDir dir("frame");
  EvalScene scene = MakeScene(dir);
  ASSERT_TRUE(
      cv::imwrite(scene.frames[0].rgb_path, cv::Mat(240, 320, CV_8UC3, cv::Scalar(128, 128, 128))));
  FrameRecord record;
  FrameEvalOptions options;
  options.output_dir = dir.Path("out");
  ASSERT_TRUE(EvaluateFrame(scene, 0, *MakeRecoverer(), options, &record).ok());
  EXPECT_FALSE(record.status.ok());
  EXPECT_TRUE(record.ran);
  EXPECT_EQ(record.metrics[1].coverage, 0.0);
  EXPECT_FALSE(std::filesystem::exists(dir.Path("out/depth/Cord_E01/000.png")));
  EXPECT_TRUE(std::filesystem::exists(dir.Path("out/vis/Cord_E01/000.png")));  // Still shown.
}

TEST(FrameEvaluator, WithoutGroundTruthMetricsAreUnknown) {
  EvalTempDir dir("frame");
  EvalScene scene = MakeScene(dir);
  scene.frames[0].depth_path.clear();
  FrameRecord record;
  ASSERT_TRUE(EvaluateFrame(scene, 0, *MakeRecoverer(), FrameEvalOptions(), &record).ok());
  EXPECT_TRUE(record.status.ok());
  EXPECT_FALSE(record.has_depth_truth);
  EXPECT_TRUE(std::isnan(record.metrics[0].coverage));
  EXPECT_TRUE(std::isnan(record.metrics[0].abs_rel));
}

// With a per-image field of view, each frame gets a pinhole of its own size: the scene's camera
// (another size, as when it came from a different first image) serves only for the mount height.
TEST(FrameEvaluator, PerImageFieldOfViewGivesTheImageItsOwnCamera) {
  EvalTempDir dir("frame");
  EvalScene scene = MakeScene(dir);
  // The render camera: 320 px wide with fx = 250, so tan(hfov / 2) = 160 / 250.
  const double hfov_deg = 2 * std::atan(160.0 / 250.0) * 180 / M_PI;
  scene.camera = Camera::FromHorizontalFov(640, 480, 1.0, 1.2);
  FrameRecord wrong;
  ASSERT_TRUE(EvaluateFrame(scene, 0, *MakeRecoverer(), FrameEvalOptions(), &wrong).ok());
  EXPECT_FALSE(wrong.status.ok());  // A 640x480 camera for a 320x240 image.

  scene.per_image_hfov_deg = hfov_deg;
  FrameRecord record;
  ASSERT_TRUE(EvaluateFrame(scene, 0, *MakeRecoverer(), FrameEvalOptions(), &record).ok());
  ASSERT_TRUE(record.status.ok()) << record.status.ToString();
  EXPECT_NEAR(record.estimate.width, 2.1, 0.2);
  EXPECT_LT(record.metrics[0].abs_rel, 0.15);

  const Camera camera = FrameCamera(scene, cv::Size(320, 240));
  EXPECT_EQ(camera.image_width, 320);
  EXPECT_EQ(camera.image_height, 240);
  EXPECT_NEAR(camera.fx, 250.0, 1e-9);
  EXPECT_NEAR(camera.fy, 250.0, 1e-9);
  EXPECT_NEAR(camera.cx, 159.5, 1e-12);
  EXPECT_NEAR(camera.cy, 119.5, 1e-12);
  EXPECT_EQ(camera.mount_height, 1.2);
  scene.per_image_hfov_deg = 0;
  EXPECT_EQ(FrameCamera(scene, cv::Size(320, 240)).image_width, 640);  // The scene's own.
}

}  // namespace
}  // namespace corridor
