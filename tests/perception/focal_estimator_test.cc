// The focal estimator on frames of the generator (an independent ray caster) whose camera has a
// known focal length, on images that hold one usable vanishing point only, and on bad inputs.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "corridor_depth/camera.h"
#include "perception/focal_estimator.h"
#include "synth/corridor_renderer.h"
#include "tests/perception/drawn_corridor.h"

namespace corridor {
namespace {

constexpr double kDeg = M_PI / 180.0;

// The focal length of a horizontal field of view over `width` pixels, by hand.
double HfovFocal(int width, double hfov_deg) { return 0.5 * width / std::tan(0.5 * hfov_deg * kDeg); }

// A 640x480 corridor with doors on both walls, 0.6 m floor tiles (grout both ways) and ceiling
// lights, at the given field of view and pose; *fx receives the generator camera's focal.
cv::Mat RenderCorridor(double hfov_deg, double yaw_deg, double pitch_deg, uint32_t seed,
                       double* fx) {
  synth::SceneOptions scene;
  scene.door_density = 0.9;
  scene.tile_size = 0.6;
  scene.seed = seed;
  const Camera camera = Camera::FromHorizontalFov(640, 480, hfov_deg * kDeg, 0.66);
  synth::CameraPose pose;
  pose.yaw = yaw_deg * kDeg;
  pose.pitch = pitch_deg * kDeg;
  pose.offset = 0.15;
  pose.height = 0.66;
  synth::Frame frame;
  const Status status = synth::RenderFrame(scene, camera, pose, &frame);
  EXPECT_TRUE(status.ok()) << status.ToString();
  *fx = camera.fx;
  return frame.bgr;
}

struct Case {
  double hfov_deg, yaw_deg, pitch_deg;
};

class FocalFromGeneratedCorridor : public ::testing::TestWithParam<Case> {};

// A yaw or pitch of 4 degrees or more puts the across or the vertical vanishing point within
// 15 focal lengths of the centre (the default limit). Measured on two scenes, hfov 50/70/90,
// yaw 0/2/4/6/-8 and pitch 0/2/4/6/8/-5 degrees: all 156 such frames within 1.3% (median
// 0.1%); the 24 with both at most 2 degrees fall back. So 3% leaves a margin.
TEST_P(FocalFromGeneratedCorridor, RecoversTheFocalWithin3Percent) {
  const Case c = GetParam();
  double fx = 0;
  const cv::Mat image = RenderCorridor(c.hfov_deg, c.yaw_deg, c.pitch_deg, 11, &fx);
  ASSERT_NEAR(fx, HfovFocal(640, c.hfov_deg), 1e-9);  // The generator's camera, checked by hand.
  FocalEstimate estimate;
  const Status status = EstimateFocal(image, FocalEstimatorOptions(), 60, &estimate);
  ASSERT_TRUE(status.ok()) << status.ToString();
  std::printf("| %2.0f | %+3.0f | %+3.0f | %6.1f | %6.1f | %+5.2f%% | %d/%d/%d | %s |\n", c.hfov_deg,
              c.yaw_deg, c.pitch_deg, fx, estimate.focal_px, 100 * (estimate.focal_px / fx - 1),
              estimate.corridor_support, estimate.second_support, estimate.third_support,
              estimate.how.c_str());
  EXPECT_TRUE(estimate.from_vanishing_points) << estimate.how;
  EXPECT_NEAR(estimate.focal_px, fx, 0.03 * fx) << estimate.how;
  EXPECT_EQ(estimate.how.rfind("vanishing points (corridor + ", 0), 0u) << estimate.how;
  // The corridor's vanishing point, by hand: K (sin yaw, -sin pitch cos yaw, cos pitch cos yaw).
  const double yaw = c.yaw_deg * kDeg, pitch = c.pitch_deg * kDeg;
  const double u = 319.5 + fx * std::tan(yaw) / std::cos(pitch);
  const double v = 239.5 - fx * std::tan(pitch);
  EXPECT_NEAR(estimate.corridor_vp.x(), u, 1.5);
  EXPECT_NEAR(estimate.corridor_vp.y(), v, 1.5);
  EXPECT_GE(estimate.second_support, FocalEstimatorOptions().min_second_support);
}

INSTANTIATE_TEST_SUITE_P(
    HfovAndPose, FocalFromGeneratedCorridor,
    ::testing::Values(Case{50, 6, 4}, Case{50, -5, 6}, Case{50, 4, -5}, Case{70, 6, 4},
                      Case{70, -5, 6}, Case{70, 4, -5}, Case{90, 6, 4}, Case{90, -5, 6},
                      Case{90, 4, -5}, Case{60, 8, 0}, Case{60, 0, 8}));

// Straight ahead (zero yaw and pitch) the across and vertical lines are parallel in the image:
// their vanishing points are at infinity and say nothing about f.
TEST(FocalEstimatorTest, StraightAheadFallsBackToTheFieldOfView) {
  double fx = 0;
  const cv::Mat image = RenderCorridor(70, 0, 0, 11, &fx);
  FocalEstimate estimate;
  ASSERT_TRUE(EstimateFocal(image, FocalEstimatorOptions(), 60, &estimate).ok());
  EXPECT_FALSE(estimate.from_vanishing_points);
  EXPECT_NEAR(estimate.focal_px, HfovFocal(640, 60), 1e-9);
  EXPECT_NE(estimate.how.find("ill-conditioned"), std::string::npos) << estimate.how;
  EXPECT_NE(estimate.how.find("fell back to --hfov=60"), std::string::npos) << estimate.how;
  EXPECT_GT(estimate.corridor_support, 0);
}

// A drawn corridor: floor and walls whose edges all meet at one vanishing point.
TEST(FocalEstimatorTest, OneVanishingPointFallsBackToTheFieldOfView) {
  const testing::DrawnCorridor drawn = testing::DrawCorridor(false);
  FocalEstimate estimate;
  ASSERT_TRUE(EstimateFocal(drawn.bgr, FocalEstimatorOptions(), 75, &estimate).ok());
  EXPECT_FALSE(estimate.from_vanishing_points);
  EXPECT_NEAR(estimate.focal_px, HfovFocal(640, 75), 1e-9);
  EXPECT_NE(estimate.how.find("fell back to --hfov=75"), std::string::npos) << estimate.how;
  EXPECT_EQ(estimate.second_support, 0);
}

TEST(FocalEstimatorTest, BlankImageFallsBack) {
  FocalEstimate estimate;
  const cv::Mat grey(240, 320, CV_8UC1, cv::Scalar(128));
  ASSERT_TRUE(EstimateFocal(grey, FocalEstimatorOptions(), 60, &estimate).ok());
  EXPECT_FALSE(estimate.from_vanishing_points);
  EXPECT_NEAR(estimate.focal_px, HfovFocal(320, 60), 1e-9);
  EXPECT_NE(estimate.how.find("no vanishing point found"), std::string::npos) << estimate.how;
}

TEST(FocalEstimatorTest, BadInputsGiveInvalidArgument) {
  const cv::Mat good(120, 160, CV_8UC3, cv::Scalar(90, 100, 110));
  const FocalEstimatorOptions options;
  FocalEstimate estimate;
  const auto code = [&](const cv::Mat& image, double hfov) {
    return EstimateFocal(image, options, hfov, &estimate).code();
  };
  EXPECT_EQ(code(cv::Mat(), 60), StatusCode::kInvalidArgument);
  EXPECT_EQ(code(cv::Mat(120, 160, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5)), 60),
            StatusCode::kInvalidArgument);
  EXPECT_EQ(code(cv::Mat(10, 10, CV_8UC3, cv::Scalar(0, 0, 0)), 60), StatusCode::kInvalidArgument);
  EXPECT_EQ(code(cv::Mat(120, 160, CV_8UC2, cv::Scalar(0, 0)), 60), StatusCode::kInvalidArgument);
  for (double hfov : {0.0, -10.0, 180.0, 500.0, std::numeric_limits<double>::quiet_NaN(),
                      std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(code(good, hfov), StatusCode::kInvalidArgument) << hfov;
  }
  EXPECT_EQ(EstimateFocal(good, options, 60, nullptr).code(), StatusCode::kInvalidArgument);
  FocalEstimatorOptions bad;
  bad.min_hfov_deg = 100;
  bad.max_hfov_deg = 90;
  const Status status = EstimateFocal(good, bad, 60, &estimate);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(status.message().find("min_hfov_deg"), std::string::npos) << status.message();
  EXPECT_EQ(code(good, 60), StatusCode::kOk);  // The same image is fine with a good fallback.
}

TEST(FocalEstimatorTest, OptionsCheckNamesTheBadField) {
  std::string why;
  EXPECT_TRUE(FocalEstimatorOptions().Check(&why)) << why;
  FocalEstimatorOptions o;
  o.inlier_distance_px = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(o.Check(&why));
  EXPECT_NE(why.find("inlier_distance_px"), std::string::npos) << why;
  o = FocalEstimatorOptions();
  o.max_second_vp_distance = 0;
  EXPECT_FALSE(o.Check(&why));
  EXPECT_NE(why.find("max_second_vp_distance"), std::string::npos) << why;
  o = FocalEstimatorOptions();
  o.min_second_support = 1;
  EXPECT_FALSE(o.Check(nullptr));
}

}  // namespace
}  // namespace corridor
