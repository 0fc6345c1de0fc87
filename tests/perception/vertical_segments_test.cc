// FindVerticalSegments on drawn edges whose lines are known exactly: an edge drawn at eight
// times the resolution and averaged down (so that it is anti-aliased like a camera's) is found
// on its line to a small fraction of a pixel and of a degree; edges too far from the image's
// columns, and the columns skipped, give none.
#include "perception/vertical_segments.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace corridor {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr int kScale = 8;

// A 320x240 grey image, dark (40) left of the line x = x0 + (y - 120) tan(tilt), light (200)
// right of it, drawn at kScale times the size and averaged down.
cv::Mat EdgeImage(double x0, double tilt_deg) {
  cv::Mat big(240 * kScale, 320 * kScale, CV_8UC1, cv::Scalar(200));
  const double t = std::tan(tilt_deg * kDeg);
  // Pixel centres at integers: a pixel (u, v) covers [u - 0.5, u + 0.5] x [v - 0.5, v + 0.5].
  const auto big_x = [&](double y) { return (x0 + (y - 120) * t + 0.5) * kScale; };
  const double top = -0.5, bottom = 239.5;
  std::vector<cv::Point> dark = {{0, 0},
                                 {static_cast<int>(std::lround(big_x(top))), 0},
                                 {static_cast<int>(std::lround(big_x(bottom))), big.rows},
                                 {0, big.rows}};
  cv::fillConvexPoly(big, dark, cv::Scalar(40));
  cv::Mat small;
  cv::resize(big, small, cv::Size(320, 240), 0, 0, cv::INTER_AREA);
  return small;
}

// The segment longest in rows.
const cv::Vec4d* Longest(const std::vector<cv::Vec4d>& segments) {
  const cv::Vec4d* best = nullptr;
  for (const cv::Vec4d& s : segments) {
    if (best == nullptr || std::abs(s[3] - s[1]) > std::abs((*best)[3] - (*best)[1])) best = &s;
  }
  return best;
}

TEST(VerticalSegmentsTest, FindsATiltedEdgeOnItsLine) {
  for (const double tilt : {0.0, 0.8, -2.5, 12.0, -30.0}) {
    const double x0 = 150.3;
    const cv::Mat image = EdgeImage(x0, tilt);
    const std::vector<cv::Vec4d> segments = FindVerticalSegments(image, VerticalSegmentOptions());
    const cv::Vec4d* s = Longest(segments);
    ASSERT_NE(s, nullptr) << "tilt " << tilt;
    EXPECT_GT(std::abs((*s)[3] - (*s)[1]), 200) << "tilt " << tilt;
    const double found_tilt = std::atan2((*s)[2] - (*s)[0], (*s)[3] - (*s)[1]) / kDeg;
    EXPECT_NEAR(found_tilt, tilt, 0.05) << "tilt " << tilt;
    // The line's column at row 120: x0, and half a fine pixel more, since the fill takes in the
    // fine pixels its boundary passes through.
    const double at_120 = (*s)[0] + ((*s)[2] - (*s)[0]) * (120 - (*s)[1]) / ((*s)[3] - (*s)[1]);
    EXPECT_NEAR(at_120, x0 + 0.5 / kScale, 0.1) << "tilt " << tilt;
  }
}

TEST(VerticalSegmentsTest, FindsNoneBeyondTheLargestTilt) {
  const cv::Mat image = EdgeImage(150, 60.0);
  for (const cv::Vec4d& s : FindVerticalSegments(image, VerticalSegmentOptions())) {
    const double tilt = std::atan2(std::abs(s[2] - s[0]), std::abs(s[3] - s[1])) / kDeg;
    EXPECT_LE(tilt, VerticalSegmentOptions().max_tilt_deg) << s;
  }
  cv::Mat horizontal(240, 320, CV_8UC1, cv::Scalar(200));
  horizontal.rowRange(100, 240).setTo(40);
  EXPECT_TRUE(FindVerticalSegments(horizontal, VerticalSegmentOptions()).empty());
}

TEST(VerticalSegmentsTest, SkippedColumnsAreNotScanned) {
  const cv::Mat image = EdgeImage(150.3, 2.0);
  std::vector<cv::Vec2i> skip(image.rows, cv::Vec2i(130, 170));
  EXPECT_TRUE(FindVerticalSegments(image, VerticalSegmentOptions(), skip).empty());
  // A colour image's green channel carries the same edge.
  cv::Mat bgr;
  cv::merge(std::vector<cv::Mat>{cv::Mat(image.size(), CV_8UC1, cv::Scalar(90)), image,
                                 cv::Mat(image.size(), CV_8UC1, cv::Scalar(90))},
            bgr);
  EXPECT_NE(Longest(FindVerticalSegments(bgr, VerticalSegmentOptions())), nullptr);
}

// The green channel of a BGR or BGRA image is read as the grey image itself (the other channels
// hold a different edge); a skipped span at the image's edge or beyond it, or an empty one,
// leaves the edge in the middle to be found as without a span.
TEST(VerticalSegmentsTest, ChannelLayoutsAndSpansAtTheEdgeKeepTheSegments) {
  const cv::Mat image = EdgeImage(150.3, 2.0);
  const std::vector<cv::Vec4d> grey = FindVerticalSegments(image, VerticalSegmentOptions());
  const cv::Vec4d* expected = Longest(grey);
  ASSERT_NE(expected, nullptr);
  const cv::Mat other = EdgeImage(60.0, -10.0);
  cv::Mat bgr, bgra;
  cv::merge(std::vector<cv::Mat>{other, image, other}, bgr);
  cv::merge(std::vector<cv::Mat>{other, image, other, other}, bgra);
  const int cols = image.cols;
  const std::vector<std::vector<cv::Vec2i>> skips = {
      {},
      std::vector<cv::Vec2i>(image.rows, cv::Vec2i(0, 20)),
      std::vector<cv::Vec2i>(image.rows, cv::Vec2i(cols - 20, cols)),
      std::vector<cv::Vec2i>(image.rows, cv::Vec2i(cols + 5, cols + 40)),
      std::vector<cv::Vec2i>(image.rows, cv::Vec2i(40, 40))};
  for (const cv::Mat* input : std::vector<const cv::Mat*>{&image, &bgr, &bgra}) {
    for (size_t k = 0; k < skips.size(); ++k) {
      const std::vector<cv::Vec4d> found =
          FindVerticalSegments(*input, VerticalSegmentOptions(), skips[k]);
      const cv::Vec4d* s = Longest(found);
      ASSERT_NE(s, nullptr) << input->channels() << " channels, skip " << k;
      for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR((*s)[i], (*expected)[i], 1e-9) << input->channels() << " channels, skip " << k;
      }
    }
  }
}

// A 3x3 Sobel of 8-bit values reaches at most 4 x 255: a larger least gradient (even one beyond
// 16-bit range) finds nothing, and a least gradient of 1 still finds the edge.
TEST(VerticalSegmentsTest, GradientThresholdsAtTheExtremes) {
  const cv::Mat image = EdgeImage(150.3, 2.0);
  VerticalSegmentOptions options;
  for (const double min_gradient : {1021.0, 40000.0, 70000.0}) {
    options.min_gradient = min_gradient;
    EXPECT_TRUE(FindVerticalSegments(image, options).empty()) << min_gradient;
  }
  options.min_gradient = 1;
  EXPECT_NE(Longest(FindVerticalSegments(image, options)), nullptr);
}

TEST(VerticalSegmentsTest, BadOptionsAreRejected) {
  VerticalSegmentOptions options;
  std::string why;
  EXPECT_TRUE(options.Check(&why)) << why;
  options.max_tilt_deg = 50;
  EXPECT_FALSE(options.Check(&why));
  EXPECT_NE(why.find("max_tilt_deg"), std::string::npos) << why;
}

}  // namespace
}  // namespace corridor
