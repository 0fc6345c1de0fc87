#include "corridor_depth/corridor_frame.h"

#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace corridor {
namespace {

// The rotation built by hand from docs/geometry.md, compared with Eigen's angle-axis composition.
TEST(CorridorFrameTest, MatchesEigenComposition) {
  const double pitch = 0.13, yaw = -0.21;
  const CorridorRotation<double> r(pitch, yaw);
  const Eigen::Matrix3d expected =
      (Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitX()) *
       Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()))
          .toRotationMatrix();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(r.m[i][j], expected(i, j), 1e-12);
  }
}

TEST(CorridorFrameTest, SignConventions) {
  // Pitched down: the corridor axis points up in the image (negative y).
  EXPECT_LT(CorridorRotation<double>(0.1, 0.0).Axis().y, 0.0);
  // Positive yaw: the axis appears right of the principal point.
  EXPECT_GT(CorridorRotation<double>(0.0, 0.1).Axis().x, 0.0);
}

TEST(CorridorFrameTest, ToCorridorInvertsToCamera) {
  const CorridorRotation<double> r(0.2, 0.3);
  const Vec3<double> p{1.0, -2.0, 3.0};
  const Vec3<double> back = r.ToCorridor(r.ToCamera(p));
  EXPECT_NEAR(back.x, 1.0, 1e-12);
  EXPECT_NEAR(back.y, -2.0, 1e-12);
  EXPECT_NEAR(back.z, 3.0, 1e-12);
}

}  // namespace
}  // namespace corridor
