// The floor-texture check: MeasureFloorTexture against a per-pixel count written out here, and
// DetectJunctions on outdoor scenes whose blob outlines meet like junctions.

#include "perception/floor_texture.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include <Eigen/Geometry>

#include "perception/junction_detector.h"
#include "tests/support/outdoor_scene.h"

namespace corridor {
namespace {

// The line through two image points, normal pointing down (b > 0), unit normal.
Eigen::Vector3d DownLine(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  Eigen::Vector3d line = a.homogeneous().cross(b.homogeneous());
  line /= line.head<2>().norm();
  return line.y() < 0 ? Eigen::Vector3d(-line) : line;
}

// The same count pixel by pixel, straight from the definition.
FloorTexture CountEachPixel(const cv::Mat& dx, const cv::Mat& dy, const GradientGrid& grid,
                            const Eigen::Vector3d& left, const Eigen::Vector3d& right,
                            double vanishing_row, double margin, int strong) {
  FloorTexture out;
  long strong_pixels = 0;
  for (int j = 0; j < dx.rows; ++j) {
    for (int i = 0; i < dx.cols; ++i) {
      const Eigen::Vector3d p(grid.scale * i, grid.first_row + grid.scale * j, 1.0);
      if (!(p.y() > vanishing_row + margin && left.dot(p) > margin && right.dot(p) > margin)) {
        continue;
      }
      ++out.floor_pixels;
      strong_pixels += std::abs(dx.at<short>(j, i)) + std::abs(dy.at<short>(j, i)) >= strong;
    }
  }
  out.strong_fraction = out.floor_pixels > 0 ? double(strong_pixels) / out.floor_pixels : 0.0;
  return out;
}

TEST(FloorTextureTest, CountsTheStrongPixelsBetweenTheLinesAsEachPixelWould) {
  // Gradients of both signs and every magnitude, so that the threshold and the |.| matter.
  cv::Mat dx(120, 160, CV_16S), dy(120, 160, CV_16S);
  cv::RNG rng(3);
  rng.fill(dx, cv::RNG::UNIFORM, -300, 301);
  rng.fill(dy, cv::RNG::UNIFORM, -300, 301);
  const Eigen::Vector2d vp(170, 80);  // A corridor's vanishing point, right of centre.
  for (const GradientGrid grid : {GradientGrid{1, 120}, GradientGrid{2, 100}, GradientGrid{4, 3}}) {
    SCOPED_TRACE(grid.scale);
    const Eigen::Vector3d left = DownLine(vp, Eigen::Vector2d(0, 230));
    const Eigen::Vector3d right = DownLine(vp, Eigen::Vector2d(330, 260));
    const double margin = 3.0 * grid.scale;
    const FloorTexture expected = CountEachPixel(dx, dy, grid, left, right, vp.y(), margin, 240);
    const FloorTexture got = MeasureFloorTexture(dx, dy, grid, left, right, vp.y(), margin, 240);
    ASSERT_GT(expected.floor_pixels, 500);  // The premise: a real floor region.
    EXPECT_EQ(got.floor_pixels, expected.floor_pixels);
    EXPECT_DOUBLE_EQ(got.strong_fraction, expected.strong_fraction);
    // Uniform gradients in [-300, 300]: |x| + |y| < 240 is a diamond of area 2 * 240^2 in a
    // square of 600^2, so about 68 % are strong.
    EXPECT_GT(got.strong_fraction, 0.5);
    EXPECT_LT(got.strong_fraction, 0.8);
  }
}

TEST(FloorTextureTest, AFlatFloorWithOneStrongStripeCountsTheStripe) {
  // Two lines that meet at (80, 0); one column of strong gradients. By hand: the floor of row v
  // spans u in (80 - v, 80 + v); the stripe at u = 80 lies inside every row, so the fraction is
  // rows / floor pixels.
  cv::Mat dx(100, 160, CV_16S, cv::Scalar(20)), dy(100, 160, CV_16S, cv::Scalar(-30));
  dx.col(80).setTo(cv::Scalar(-250));
  const Eigen::Vector3d left = DownLine({80, 0}, {0, 80});     // u + v = 80, below: u + v > 80.
  const Eigen::Vector3d right = DownLine({80, 0}, {160, 80});  // v - u = -80, below: v > u - 80.
  // A margin of half a pixel keeps every pixel off the lines (no ties to round).
  const FloorTexture got = MeasureFloorTexture(dx, dy, GradientGrid{1, 0}, left, right,
                                               /*vanishing_row=*/0, /*margin=*/0.5, 240);
  // Row v (1..99): 80 - v < u < 80 + v (by at least 0.5 sqrt(2)), clipped to [0, 159]: u from
  // max(0, 81 - v) to min(159, 79 + v).
  long floor = 0;
  for (int v = 1; v < 100; ++v) floor += std::min(159, 79 + v) - std::max(0, 81 - v) + 1;
  EXPECT_EQ(got.floor_pixels, floor);
  EXPECT_DOUBLE_EQ(got.strong_fraction, 99.0 / floor);
}

TEST(FloorTextureTest, NothingIsCountedForWrongMaps) {
  const cv::Mat dx(10, 10, CV_32F, cv::Scalar(0)), dy(10, 10, CV_32F, cv::Scalar(0));
  const FloorTexture got = MeasureFloorTexture(dx, dy, GradientGrid{}, {0, 1, 0}, {0, 1, 0}, -1,
                                               0, 240);
  EXPECT_EQ(got.floor_pixels, 0);
  EXPECT_EQ(got.strong_fraction, 0.0);
}

// Outdoor scenes where two blob outlines meet like a corridor's junctions (found with the check
// off), and the check says why they are not one.
TEST(FloorTextureTest, AnOutdoorSceneWhoseBlobsMeetLikeJunctionsIsNoCorridor) {
  for (const uint64_t seed : {3, 85, 127}) {
    SCOPED_TRACE(seed);
    const cv::Mat image = testing_util::OutdoorScene(seed);
    JunctionDetectorOptions off;
    off.max_floor_texture = 0;
    JunctionPair pair;
    ASSERT_TRUE(DetectJunctions(image, off, &pair).ok());
    ASSERT_TRUE(pair.status.ok()) << "premise: without the check a pair is found";
    ASSERT_TRUE(DetectJunctions(image, JunctionDetectorOptions(), &pair).ok());
    EXPECT_EQ(pair.status.code(), StatusCode::kNoCorridorFound);
    EXPECT_GT(pair.floor_texture, JunctionDetectorOptions().max_floor_texture);
    EXPECT_NE(pair.status.message().find("floor between the junction lines is textured"),
              std::string::npos)
        << pair.status.ToString();
  }
}

TEST(FloorTextureTest, OptionsAreChecked) {
  JunctionDetectorOptions options;
  std::string why;
  EXPECT_TRUE(options.Check(&why)) << why;
  options.max_floor_texture = -0.1;
  EXPECT_FALSE(options.Check(&why));
  EXPECT_NE(why.find("max_floor_texture"), std::string::npos);
  options.max_floor_texture = 0.04;
  options.strong_edge_gradient = 0;
  EXPECT_FALSE(options.Check(&why));
}

}  // namespace
}  // namespace corridor
