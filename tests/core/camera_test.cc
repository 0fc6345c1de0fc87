#include "corridor_depth/camera.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace corridor {
namespace {

Camera ValidCamera() {
  Camera c;
  c.image_width = 420;
  c.image_height = 360;
  c.fx = c.fy = 230;
  c.cx = 209.5;
  c.cy = 179.5;
  c.mount_height = 0.66;
  return c;
}

TEST(CameraTest, ValidCameraPassesCheck) {
  std::string why;
  EXPECT_TRUE(ValidCamera().Check(&why)) << why;
}

TEST(CameraTest, RejectsBadFocalLengths) {
  for (double f : {-1.0, 0.0, std::numeric_limits<double>::quiet_NaN()}) {
    Camera c = ValidCamera();
    c.fx = f;
    std::string why;
    EXPECT_FALSE(c.Check(&why));
    EXPECT_NE(why.find("focal"), std::string::npos) << why;
  }
}

TEST(CameraTest, RejectsPrincipalPointOutsideImage) {
  Camera c = ValidCamera();
  c.cx = 500;
  std::string why;
  EXPECT_FALSE(c.Check(&why));
  EXPECT_NE(why.find("principal point"), std::string::npos) << why;
}

TEST(CameraTest, RejectsAbsurdMountHeights) {
  for (double h : {0.0, -0.5, 11.0, std::numeric_limits<double>::infinity()}) {
    Camera c = ValidCamera();
    c.mount_height = h;
    std::string why;
    EXPECT_FALSE(c.Check(&why)) << h;
    EXPECT_NE(why.find("camera height"), std::string::npos) << why;
  }
}

TEST(CameraTest, RejectsNonFiniteDistortion) {
  Camera c = ValidCamera();
  c.distortion[1] = std::numeric_limits<double>::quiet_NaN();
  std::string why;
  EXPECT_FALSE(c.Check(&why));
}

TEST(CameraTest, FovCameraHasExpectedFocalLength) {
  // 90 degrees over 400 px: f = 200 px by hand.
  const Camera c = Camera::FromHorizontalFov(400, 300, M_PI / 2, 1.0);
  EXPECT_NEAR(c.fx, 200.0, 1e-9);
  EXPECT_NEAR(c.cx, 199.5, 1e-12);
}

TEST(CameraTest, UndistortInvertsDistort) {
  Camera c = ValidCamera();
  c.distortion = {-0.2, 0.05, 0.001, -0.002, 0.0};
  for (double u : {10.0, 100.0, 300.0}) {
    for (double v : {20.0, 180.0, 350.0}) {
      const Eigen::Vector2d raw = c.Distort({u, v});
      const Eigen::Vector2d back = c.Undistort(raw);
      EXPECT_NEAR(back.x(), u, 1e-6);
      EXPECT_NEAR(back.y(), v, 1e-6);
    }
  }
}

TEST(CameraTest, DistortMatchesHandComputedRadialTerm) {
  Camera c = ValidCamera();
  c.distortion = {0.1, 0, 0, 0, 0};
  // Normalised x = 1 (u = cx + fx), y = 0: r^2 = 1, radial factor 1.1.
  const Eigen::Vector2d raw = c.Distort({c.cx + c.fx, c.cy});
  EXPECT_NEAR(raw.x(), c.cx + 1.1 * c.fx, 1e-9);
  EXPECT_NEAR(raw.y(), c.cy, 1e-9);
}

}  // namespace
}  // namespace corridor
