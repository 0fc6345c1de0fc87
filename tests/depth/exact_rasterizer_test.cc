#include "depth/exact_rasterizer.h"

#include <cmath>

#include <gtest/gtest.h>

#include "box_truth.h"
#include "random_views.h"

namespace corridor {
namespace {

using testing::BoxDepth;
using testing::ExpectNaNWhereNotPositive;
using testing::RandomView;
using testing::RandomViewLimits;
using testing::TestCamera;
using testing::TestGeometry;

TEST(ExactRasterizerTest, MatchesHandDepthWithCeiling) {
  const Camera camera = TestCamera();
  RasterizerOptions options;
  options.max_range = 1e6;
  const ExactRasterizer rasterizer(options);
  for (const auto& g : {TestGeometry(0.0, 0.0, 0.0, 2.0, 2.6), TestGeometry(0.2, 0.1, 0.3, 2.4, 2.8),
                        TestGeometry(-0.3, -0.05, -0.4, 3.0, 3.0)}) {
    cv::Mat depth;
    ASSERT_TRUE(rasterizer.Render(g, camera, &depth).ok());
    for (int v = 0; v < camera.image_height; v += 7) {
      for (int u = 0; u < camera.image_width; u += 5) {
        const double expected = BoxDepth(camera, g, u, v);
        const float got = depth.at<float>(v, u);
        if (!std::isfinite(expected)) {
          EXPECT_EQ(got, 0.0f);
        } else {
          EXPECT_NEAR(got, expected, 1e-5 * expected + 1e-6) << u << "," << v;
        }
      }
    }
  }
}

TEST(ExactRasterizerTest, NoCeilingCutsWallsAtMaxHeightAndRange) {
  const Camera camera = TestCamera();
  RasterizerOptions options;
  options.max_range = 8.0;
  options.max_height = 1.5;
  const ExactRasterizer rasterizer(options);
  const CorridorGeometry g = TestGeometry(0.05, 0.02, 0.1, 2.2);
  cv::Mat depth;
  ASSERT_TRUE(rasterizer.Render(g, camera, &depth).ok());
  int zeros = 0;
  for (int v = 0; v < camera.image_height; ++v) {
    for (int u = 0; u < camera.image_width; ++u) {
      int surface;
      const double z = BoxDepth(camera, g, u, v, &surface);
      const float got = depth.at<float>(v, u);
      bool expect_zero = !std::isfinite(z) || z > 8.0;
      if (surface == 1) {
        // Height of the wall point above the floor, by hand: h - Y_W.
        const Eigen::Matrix3d r = (Eigen::AngleAxisd(g.pitch, Eigen::Vector3d::UnitX()) *
                                   Eigen::AngleAxisd(g.yaw, Eigen::Vector3d::UnitY()))
                                      .toRotationMatrix();
        const Eigen::Vector3d p = r.transpose() * (z * camera.K().inverse() * Eigen::Vector3d(u, v, 1));
        expect_zero = expect_zero || g.camera_height - p.y() > 1.5;
      }
      if (expect_zero) {
        ++zeros;
        EXPECT_EQ(got, 0.0f) << u << "," << v;
      } else {
        EXPECT_NEAR(got, z, 1e-5 * z) << u << "," << v;
      }
    }
  }
  EXPECT_GT(zeros, 100);
}

// The four row kernels (end wall or not, ceiling or cut walls), AVX2 and baseline: the same
// depths to the bit, as they do the same IEEE operations.
TEST(ExactRasterizerTest, Avx2AndBaselineRowsGiveTheSameDepths) {
  const Camera camera = TestCamera();
  for (const double end_distance : {0.0, 6.0}) {
    for (const double ceiling : {0.0, 2.7}) {
      CorridorGeometry g = TestGeometry(0.1, 0.08, 0.2, 2.3, ceiling);
      g.end_distance = end_distance;
      RasterizerOptions options;
      options.max_range = 10.0;
      options.max_height = 1.8;
      cv::Mat fast, baseline;
      ASSERT_TRUE(ExactRasterizer(options).Render(g, camera, &fast).ok());
      options.use_avx2 = false;
      ASSERT_TRUE(ExactRasterizer(options).Render(g, camera, &baseline).ok());
      EXPECT_EQ(cv::norm(fast, baseline, cv::NORM_INF), 0.0) << end_distance << " " << ceiling;
      EXPECT_GT(cv::countNonZero(baseline), baseline.total() / 2) << end_distance << " " << ceiling;
    }
  }
}

// The rows' floor/ceiling spans, filled without divisions, against every pixel divided: bitwise
// the same over random poses (yaw up to 0.6 rad, where m.r barely changes along a row, or steeply
// pitched), widths, ceilings, ranges and image sizes, on both row kernels. (A span's fill one part
// in 10^4 off, or a span three pixels too long, fails it.)
TEST(ExactRasterizerTest, PlaneSpansGiveTheSameDepthsAsEveryPixelDivided) {
  cv::RNG rng(31);
  for (int trial = 0; trial < 200; ++trial) {
    Camera camera;
    CorridorGeometry g;
    RandomView(&rng, RandomViewLimits(), trial % 2 != 0, &camera, &g);
    RasterizerOptions options;
    options.max_range = rng.uniform(2.0, 60.0);
    options.max_height = rng.uniform(0.8, 3.0);
    options.use_avx2 = trial % 3 != 0;
    cv::Mat spans, divided;
    ASSERT_TRUE(ExactRasterizer(options).Render(g, camera, &spans).ok());
    options.plane_spans = false;
    ASSERT_TRUE(ExactRasterizer(options).Render(g, camera, &divided).ok());
    ASSERT_EQ(cv::norm(spans, divided, cv::NORM_INF), 0.0) << "trial " << trial;
  }
  // A level camera in a 2 m corridor: the lowest row's middle is floor (depth h / n.r).
  const Camera camera = TestCamera();
  cv::Mat depth;
  ASSERT_TRUE(ExactRasterizer(RasterizerOptions()).Render(TestGeometry(0, 0, 0, 2.0), camera, &depth).ok());
  const double y = (camera.image_height - 1 - camera.cy) / camera.fy;
  EXPECT_NEAR(depth.at<float>(camera.image_height - 1, camera.image_width / 2), 0.66 / y, 1e-5);
}

// RenderNoEstimateNaN, NaN written in the rows' own pass, against Render's depths with every
// pixel not positive made NaN: bitwise the same (NaN where Render has no estimate) over random
// poses, end walls, ceilings and ranges, with and without lens distortion, on both row kernels.
TEST(ExactRasterizerTest, NoEstimateNaNIsRenderWithItsZerosMarked) {
  cv::RNG rng(47);
  for (int trial = 0; trial < 60; ++trial) {
    RandomViewLimits limits;
    limits.max_width = 300, limits.max_height = 200, limits.max_focal = 600;
    limits.max_yaw = limits.max_pitch = 0.5;
    Camera camera;
    CorridorGeometry g;
    RandomView(&rng, limits, trial % 2 != 0, &camera, &g);
    if (trial % 4 == 3) camera.distortion = {-0.2, 0.05, 0.0, 0.0, 0.0};
    if (trial % 3 == 0) g.end_distance = rng.uniform(2.0, 30.0);
    RasterizerOptions options;
    options.max_range = rng.uniform(2.0, 60.0);
    options.max_height = rng.uniform(0.8, 3.0);
    options.use_avx2 = trial % 5 != 0;
    const ExactRasterizer rasterizer(options);
    cv::Mat plain, marked;
    ASSERT_TRUE(rasterizer.Render(g, camera, &plain).ok());
    ASSERT_TRUE(rasterizer.RenderNoEstimateNaN(g, camera, &marked).ok());
    const int nans = ExpectNaNWhereNotPositive(plain, marked);
    if (::testing::Test::HasFailure()) FAIL() << "trial " << trial;
    if (trial == 0) {
      EXPECT_GT(nans, 0);
    }
  }
}

TEST(ExactRasterizerTest, HonoursLensDistortionThroughRayTable) {
  Camera camera = TestCamera();
  camera.distortion = {-0.25, 0.06, 0.0, 0.0, 0.0};
  RasterizerOptions options;
  options.max_range = 1e6;
  const ExactRasterizer rasterizer(options);
  const CorridorGeometry g = TestGeometry(0.1, 0.05, 0.2, 2.4, 2.7);
  cv::Mat depth;
  ASSERT_TRUE(rasterizer.Render(g, camera, &depth).ok());
  Camera ideal = camera;
  ideal.distortion = {};
  for (int v = 3; v < camera.image_height; v += 13) {
    for (int u = 2; u < camera.image_width; u += 11) {
      // The raw pixel (u, v) sees the ideal pixel that distorts onto it.
      const Eigen::Vector2d p = camera.Undistort({u, v});
      ASSERT_NEAR(camera.Distort(p).x(), u, 1e-6);
      const double expected = BoxDepth(ideal, g, p.x(), p.y());
      EXPECT_NEAR(depth.at<float>(v, u), expected, 1e-4 * expected) << u << "," << v;
    }
  }
}

TEST(ExactRasterizerTest, RejectsCameraOutsideTheCorridor) {
  const ExactRasterizer rasterizer{RasterizerOptions()};
  cv::Mat depth;
  EXPECT_EQ(rasterizer.Render(TestGeometry(0, 0, 1.5, 2.0), TestCamera(), &depth).code(),
            StatusCode::kImplausibleGeometry);
}

}  // namespace
}  // namespace corridor
