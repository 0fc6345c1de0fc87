#include "depth/paper_rasterizer.h"

#include <gtest/gtest.h>

#include "box_truth.h"

namespace corridor {
namespace {

using testing::BoxDepth;
using testing::TestCamera;
using testing::TestGeometry;

// The test camera at width x height, focal length f, principal point at the centre.
Camera CentredCamera(int width, int height, double f) {
  Camera camera = TestCamera();
  camera.image_width = width;
  camera.image_height = height;
  camera.fx = camera.fy = f;
  camera.cx = 0.5 * (width - 1);
  camera.cy = 0.5 * (height - 1);
  return camera;
}

// The paper's planes interpolate linearly between cross-sections, so they approximate the box:
// compare with the hand depth on floor and walls below the maximum height.
TEST(PaperRasterizerTest, ApproximatesTheBoxOnFloorAndWalls) {
  const Camera camera = CentredCamera(320, 240, 200);
  RasterizerOptions options;
  options.max_range = 30.0;
  options.max_height = 1.8;
  const PaperRasterizer rasterizer(options);
  for (const auto& g : {TestGeometry(0.0, 0.02, 0.0, 2.0), TestGeometry(0.15, 0.08, 0.3, 2.6),
                        TestGeometry(-0.2, -0.02, -0.2, 1.8)}) {
    cv::Mat depth;
    ASSERT_TRUE(rasterizer.Render(g, camera, &depth).ok());
    double sum_rel = 0;
    int compared = 0, missing = 0;
    for (int v = 0; v < camera.image_height; ++v) {
      for (int u = 0; u < camera.image_width; ++u) {
        int surface;
        const double z = BoxDepth(camera, g, u, v, &surface);
        const float got = depth.at<float>(v, u);
        if (!std::isfinite(z) || z > 25.0) continue;
        const Eigen::Matrix3d r = (Eigen::AngleAxisd(g.pitch, Eigen::Vector3d::UnitX()) *
                                   Eigen::AngleAxisd(g.yaw, Eigen::Vector3d::UnitY()))
                                      .toRotationMatrix();
        const Eigen::Vector3d p =
            r.transpose() * (z * camera.K().inverse() * Eigen::Vector3d(u, v, 1));
        const double height_above_floor = g.camera_height - p.y();
        if (height_above_floor > 1.75) {
          if (height_above_floor > 1.85) {
            EXPECT_EQ(got, 0.0f) << u << "," << v;
          }
          continue;
        }
        if (got == 0) {
          ++missing;
          continue;
        }
        sum_rel += std::abs(got - z) / z;
        ++compared;
      }
    }
    ASSERT_GT(compared, 1000);
    EXPECT_LT(sum_rel / compared, 0.01);              // Mean relative error below 1%.
    EXPECT_LT(missing, 0.01 * (compared + missing));  // Almost every modelled pixel is filled.
  }
}

// A fuzzer finding: with an absurd max_range (1e300) the farthest planes project to infinity and
// NaN, and their rows were converted to int (undefined). Depth must stay finite, and the floor
// near the camera must still be the box's (BoxDepth: the hand ray-box intersection).
TEST(PaperRasterizerTest, AnAbsurdMaxRangeGivesFiniteDepthAndTheNearFloor) {
  const Camera camera = CentredCamera(64, 48, 51.2);
  RasterizerOptions options;
  options.max_range = 1e300;
  const PaperRasterizer rasterizer(options);
  const CorridorGeometry g = TestGeometry(0.0098, -0.038, 0.0004, 2.78);
  cv::Mat depth;
  ASSERT_TRUE(rasterizer.Render(g, camera, &depth).ok());
  for (int v = 0; v < depth.rows; ++v) {
    for (int u = 0; u < depth.cols; ++u) {
      const float z = depth.at<float>(v, u);
      ASSERT_TRUE(std::isfinite(z) && z >= 0) << u << "," << v << ": " << z;
    }
  }
  int surface;
  const double floor = BoxDepth(camera, g, 32, 46, &surface);
  ASSERT_TRUE(std::isfinite(floor));
  EXPECT_NEAR(depth.at<float>(46, 32), floor, 0.05 * floor);
}

}  // namespace
}  // namespace corridor
