// The floor-texture check: MeasureFloorTexture against a per-pixel count written out here, and
// DetectJunctions on outdoor scenes whose blob outlines meet like junctions.

#include "perception/floor_texture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "perception/junction_detector.h"
#include "tests/support/image_line.h"
#include "tests/support/outdoor_scene.h"

namespace corridor {
namespace {

using testing_util::DownLine;

// Angle between two directions given in degrees, as undirected lines: in [0, 90].
double LineAngleDeg(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 180.0);
  return std::min(d, 180.0 - d);
}

// The same count pixel by pixel, straight from the definition, with angles: an edge runs at
// 90 degrees to its gradient; it is a corridor line within the tolerance of 0 (horizontal),
// 90 (vertical) or the direction to the vanishing point.
FloorTexture CountEachPixel(const cv::Mat& dx, const cv::Mat& dy, const GradientGrid& grid,
                            const Eigen::Vector3d& left, const Eigen::Vector3d& right,
                            const Eigen::Vector2d& vp, const FloorTextureOptions& options) {
  FloorTexture out;
  long strong_pixels = 0, odd_pixels = 0;
  const double margin = options.margin;
  for (int j = 0; j < dx.rows; ++j) {
    for (int i = 0; i < dx.cols; ++i) {
      const Eigen::Vector3d p(grid.scale * i, grid.first_row + grid.scale * j, 1.0);
      if (!(p.y() > vp.y() + margin && left.dot(p) > margin && right.dot(p) > margin)) continue;
      ++out.floor_pixels;
      const double gx = dx.at<short>(j, i), gy = dy.at<short>(j, i);
      if (std::abs(gx) + std::abs(gy) < options.strong) continue;
      ++strong_pixels;
      const double edge = std::atan2(gy, gx) * 180 / M_PI + 90;
      const double to_vp = std::atan2(vp.y() - p.y(), vp.x() - p.x()) * 180 / M_PI;
      const double t = options.line_tolerance_deg;
      if (LineAngleDeg(edge, 0) > t && LineAngleDeg(edge, 90) > t && LineAngleDeg(edge, to_vp) > t) {
        ++odd_pixels;
      }
    }
  }
  if (out.floor_pixels > 0) {
    out.strong_fraction = static_cast<double>(strong_pixels) / out.floor_pixels;
    out.odd_fraction = static_cast<double>(odd_pixels) / out.floor_pixels;
  }
  return out;
}

TEST(FloorTextureTest, CountsTheStrayStrongPixelsBetweenTheLinesAsEachPixelWould) {
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
    FloorTextureOptions options;
    options.margin = 3.0 * grid.scale;
    const FloorTexture expected = CountEachPixel(dx, dy, grid, left, right, vp, options);
    const FloorTexture got = MeasureFloorTexture(dx, dy, grid, left, right, vp, options);
    ASSERT_GT(expected.floor_pixels, 500);  // The premise: a real floor region.
    EXPECT_EQ(got.floor_pixels, expected.floor_pixels);
    EXPECT_DOUBLE_EQ(got.strong_fraction, expected.strong_fraction);
    // Random directions: three 30 degree bands of 180 are corridor lines, so about half of the
    // strong pixels are stray (ties at the bands' edges could differ by one pixel; none did).
    EXPECT_NEAR(got.odd_fraction, expected.odd_fraction, 1.0 / expected.floor_pixels);
    // Uniform gradients in [-300, 300]: |x| + |y| < 240 is a diamond of area 2 * 240^2 in a
    // square of 600^2, so about 68 % are strong.
    EXPECT_GT(got.strong_fraction, 0.5);
    EXPECT_LT(got.strong_fraction, 0.8);
    EXPECT_GT(got.odd_fraction, 0.25 * got.strong_fraction);
    EXPECT_LT(got.odd_fraction, 0.75 * got.strong_fraction);
  }
}

TEST(FloorTextureTest, AFlatFloorWithOneStrongStripeCountsTheStripe) {
  // Two lines that meet at (80, 0); one column of strong gradients at 45 degrees (an edge along
  // no corridor line: the vanishing point is straight up from it). By hand: the floor of row v
  // spans u in (80 - v, 80 + v); the stripe at u = 80 lies inside every row, so both fractions
  // are rows / floor pixels.
  cv::Mat dx(100, 160, CV_16S, cv::Scalar(20)), dy(100, 160, CV_16S, cv::Scalar(-30));
  dx.col(80).setTo(cv::Scalar(-200));
  dy.col(80).setTo(cv::Scalar(-200));
  const Eigen::Vector3d left = DownLine({80, 0}, {0, 80});     // u + v = 80, below: u + v > 80.
  const Eigen::Vector3d right = DownLine({80, 0}, {160, 80});  // v - u = -80, below: v > u - 80.
  // A margin of half a pixel keeps every pixel off the lines (no ties to round).
  FloorTextureOptions options;
  options.margin = 0.5;
  const Eigen::Vector2d vp(80, 0);
  FloorTexture got = MeasureFloorTexture(dx, dy, GradientGrid{1, 0}, left, right, vp, options);
  // Row v (1..99): 80 - v < u < 80 + v (by at least 0.5 sqrt(2)), clipped to [0, 159]: u from
  // max(0, 81 - v) to min(159, 79 + v).
  long floor = 0;
  for (int v = 1; v < 100; ++v) floor += std::min(159, 79 + v) - std::max(0, 81 - v) + 1;
  EXPECT_EQ(got.floor_pixels, floor);
  EXPECT_DOUBLE_EQ(got.strong_fraction, 99.0 / floor);
  EXPECT_DOUBLE_EQ(got.odd_fraction, 99.0 / floor);
  // The same stripe as an edge toward the vanishing point (a joint along the corridor; its
  // gradient is horizontal): strong, but a corridor line.
  dx.col(80).setTo(cv::Scalar(-250));
  dy.col(80).setTo(cv::Scalar(0));
  got = MeasureFloorTexture(dx, dy, GradientGrid{1, 0}, left, right, vp, options);
  EXPECT_DOUBLE_EQ(got.strong_fraction, 99.0 / floor);
  EXPECT_EQ(got.odd_fraction, 0.0);
}

// A checkered floor: dark joints along the corridor (toward the vanishing point) and across it
// (horizontal), drawn into a grey image and differentiated. Many strong edges, few stray: only
// where two joints cross is the gradient diagonal. (This dense, high-contrast pattern still
// exceeds the default threshold: docs/reliability.md, known gaps.)
TEST(FloorTextureTest, ACheckeredFloorIsStrongEdgesAlongCorridorLinesOnly) {
  cv::Mat grey(240, 320, CV_8U, cv::Scalar(190));
  const cv::Point vp(160, 60);
  for (int u = -400; u <= 720; u += 60) cv::line(grey, vp, {u, 239}, cv::Scalar(40), 2);
  for (int v = 80; v < 240; v = v + 8 + (v - 60) / 4) {
    cv::line(grey, {0, v}, {319, v}, cv::Scalar(40), 2);
  }
  cv::Mat dx, dy;
  cv::Sobel(grey, dx, CV_16S, 1, 0, 3);
  cv::Sobel(grey, dy, CV_16S, 0, 1, 3);
  const Eigen::Vector3d left = DownLine({160, 60}, {0, 200});
  const Eigen::Vector3d right = DownLine({160, 60}, {319, 200});
  FloorTextureOptions options;
  const FloorTexture got =
      MeasureFloorTexture(dx, dy, GradientGrid{}, left, right, Eigen::Vector2d(160, 60), options);
  ASSERT_GT(got.floor_pixels, 5000);
  EXPECT_GT(got.strong_fraction, 0.1);  // The premise: far more than any threshold.
  EXPECT_LT(got.odd_fraction, 0.2 * got.strong_fraction);
}

TEST(FloorTextureTest, NothingIsCountedForWrongMaps) {
  const cv::Mat dx(10, 10, CV_32F, cv::Scalar(0)), dy(10, 10, CV_32F, cv::Scalar(0));
  const FloorTexture got = MeasureFloorTexture(dx, dy, GradientGrid{}, {0, 1, 0}, {0, 1, 0},
                                               Eigen::Vector2d(0, -1), FloorTextureOptions());
  EXPECT_EQ(got.floor_pixels, 0);
  EXPECT_EQ(got.strong_fraction, 0.0);
}

// Outdoor scenes where two blob outlines meet like a corridor's junctions (found with the check
// off), and the check says why they are not one. Every such scene among the first 120 seeds (which
// ones they are depends on the Hough's draws; at least three of them must be).
TEST(FloorTextureTest, AnOutdoorSceneWhoseBlobsMeetLikeJunctionsIsNoCorridor) {
  int pairs = 0;
  for (uint64_t seed = 0; seed < 120; ++seed) {
    SCOPED_TRACE(seed);
    const cv::Mat image = testing_util::OutdoorScene(seed);
    JunctionDetectorOptions off;
    off.max_floor_texture = 0;
    JunctionPair pair;
    ASSERT_TRUE(DetectJunctions(image, off, &pair).ok());
    if (!pair.status.ok()) continue;  // No pair even without the check.
    ++pairs;
    ASSERT_TRUE(DetectJunctions(image, JunctionDetectorOptions(), &pair).ok());
    EXPECT_EQ(pair.status.code(), StatusCode::kNoCorridorFound);
    EXPECT_GT(pair.floor_texture, JunctionDetectorOptions().max_floor_texture);
    EXPECT_NE(pair.status.message().find("floor between the junction lines is textured"),
              std::string::npos)
        << pair.status.ToString();
  }
  EXPECT_GE(pairs, 3) << "premise: without the check, blobs meet like junctions in some scenes";
}

// The junction search's second, relaxed Hough look (for a faint junction broken into pieces)
// pairs lines in outdoor scenes too: blob outlines' short straight pieces line up by chance.
// Without its length and partner rules (a new line at least 0.2 of the height, its first-look
// partner with a BoundaryScore of at least 0.1) 2 of these 120 scenes got past the floor texture
// check and were taken for corridors (measured; 5 when both lines could be new). With them, none.
TEST(FloorTextureTest, TheSecondHoughLookTakesNoOutdoorSceneForACorridor) {
  JunctionDetectorOptions loose;
  loose.relaxed_min_line_fraction = 0;
  loose.relaxed_min_partner_boundary = 0;
  int corridors = 0, loose_corridors = 0;
  for (uint64_t seed = 0; seed < 120; ++seed) {
    const cv::Mat image = testing_util::OutdoorScene(seed);
    JunctionPair pair;
    ASSERT_TRUE(DetectJunctions(image, JunctionDetectorOptions(), &pair).ok());
    corridors += pair.status.ok();
    ASSERT_TRUE(DetectJunctions(image, loose, &pair).ok());
    loose_corridors += pair.status.ok();
  }
  EXPECT_EQ(corridors, 0);
  EXPECT_GE(loose_corridors, 1) << "premise: without its rules the second look takes some";
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
  options.strong_edge_gradient = 240;
  options.floor_line_tolerance_deg = 50;
  EXPECT_FALSE(options.Check(&why));
  EXPECT_NE(why.find("floor_line_tolerance_deg"), std::string::npos);
}

}  // namespace
}  // namespace corridor
