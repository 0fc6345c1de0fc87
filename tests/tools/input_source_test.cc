// Uncalibrated mode of ResolveInput: pinholes from --hfov or --fx/--fy/--cx/--cy, sized by the
// first image, with the focal length computed by hand.
#include "tools/input_source.h"

#include <filesystem>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

namespace corridor {
namespace {

std::string FolderWithOneImage(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/input_source_test_" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  EXPECT_TRUE(cv::imwrite(dir + "/frame.png", cv::Mat(240, 400, CV_8UC3, cv::Scalar::all(90))));
  return dir;
}

TEST(InputSourceTest, HorizontalFieldOfViewGivesTheFocalLength) {
  CameraOverrides overrides;
  overrides.hfov_deg = 90;
  overrides.camera_height = 1.0;
  std::vector<InputScene> scenes;
  ASSERT_TRUE(ResolveInput(FolderWithOneImage("hfov"), overrides, &scenes).ok());
  ASSERT_EQ(scenes.size(), 1u);
  // 90 degrees over 400 px: f = 200 / tan(45 deg) = 200 px; centre (199.5, 119.5).
  EXPECT_NEAR(scenes[0].camera.fx, 200.0, 1e-9);
  EXPECT_NEAR(scenes[0].camera.fy, 200.0, 1e-9);
  EXPECT_NEAR(scenes[0].camera.cx, 199.5, 1e-12);
  EXPECT_NEAR(scenes[0].camera.cy, 119.5, 1e-12);
  EXPECT_EQ(scenes[0].camera.image_width, 400);
  EXPECT_EQ(scenes[0].camera_source, "--hfov");
}

TEST(InputSourceTest, PinholeFromFlags) {
  CameraOverrides overrides;
  overrides.fx = 300;
  overrides.cy = 100;
  overrides.camera_height = 0.7;
  std::vector<InputScene> scenes;
  ASSERT_TRUE(ResolveInput(FolderWithOneImage("fx"), overrides, &scenes).ok());
  EXPECT_EQ(scenes[0].camera.fx, 300);
  EXPECT_EQ(scenes[0].camera.fy, 300);  // --fy defaults to --fx.
  EXPECT_EQ(scenes[0].camera.cx, 199.5);
  EXPECT_EQ(scenes[0].camera.cy, 100);
  EXPECT_EQ(scenes[0].camera.mount_height, 0.7);
}

TEST(InputSourceTest, WithoutAnyCalibrationTheMessageListsTheWays) {
  CameraOverrides overrides;
  overrides.camera_height = 1.0;
  std::vector<InputScene> scenes;
  const Status status = ResolveInput(FolderWithOneImage("none"), overrides, &scenes);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(status.message().find("--hfov"), std::string::npos) << status.message();
  overrides.hfov_deg = 60;
  overrides.camera_height = 0;
  EXPECT_NE(ResolveInput(FolderWithOneImage("noheight"), overrides, &scenes).message().find("--camera_height"),
            std::string::npos);
}

}  // namespace
}  // namespace corridor
