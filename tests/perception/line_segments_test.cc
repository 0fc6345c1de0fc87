#include "perception/line_segments.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace corridor {
namespace {

TEST(LineSegmentsTest, MergesCollinearPiecesOfABrokenLine) {
  // Three pieces of v = 400 - 0.5 u, broken like a junction behind doors, plus an unrelated one.
  const auto piece = [](double u0, double u1) {
    return cv::Vec4f(static_cast<float>(u0), static_cast<float>(400 - 0.5 * u0),
                     static_cast<float>(u1), static_cast<float>(400 - 0.5 * u1));
  };
  const std::vector<cv::Vec4f> segments = {piece(0, 60), piece(100, 180), piece(220, 260),
                                           cv::Vec4f(300, 100, 300, 300)};
  const auto lines = MergeSegments(segments, 2.0, 3.0);
  ASSERT_EQ(lines.size(), 2u);
  const MergedLine& m = std::abs(lines[0].slope + 0.5) < 0.01 ? lines[0] : lines[1];
  EXPECT_NEAR(m.slope, -0.5, 1e-6);
  EXPECT_NEAR(m.start.x(), 0, 1e-6);
  EXPECT_NEAR(m.end.x(), 260, 1e-6);
  // Extent 260 * sqrt(1.25); covered (60 + 80 + 40) * sqrt(1.25).
  EXPECT_NEAR(m.length, 260 * std::sqrt(1.25), 1e-6);
  EXPECT_NEAR(m.covered, 180 * std::sqrt(1.25), 1e-6);
  EXPECT_NEAR(m.inclination_deg, std::atan(0.5) * 180 / M_PI, 1e-6);
  EXPECT_GT(m.line.y(), 0);  // Normal points down.
}

TEST(LineSegmentsTest, KeepsParallelButDistantLinesApart) {
  const std::vector<cv::Vec4f> segments = {cv::Vec4f(0, 400, 200, 300), cv::Vec4f(0, 410, 200, 310)};
  EXPECT_EQ(MergeSegments(segments, 2.0, 3.0).size(), 2u);
}

TEST(LineSegmentsTest, HoughFindsADrawnLineInTheRoi) {
  cv::Mat gray(200, 300, CV_8U, cv::Scalar(40));
  std::vector<cv::Point> floor{{0, 199}, {0, 150}, {299, 60}, {299, 199}};
  cv::fillPoly(gray, std::vector<std::vector<cv::Point>>{floor}, cv::Scalar(200));
  const EdgeSegments found = DetectSegments(gray, 100, {1.0, 90, 0.4, 90, 40, 20, 15, 5, 0.0});
  ASSERT_FALSE(found.segments.empty());
  // Every segment lies on the drawn edge v = 150 - 0.3 u, in full-image rows.
  for (const auto& s : found.segments) {
    EXPECT_NEAR(s[1], 150 - 0.3 * s[0], 2.0);
    EXPECT_GE(s[1], 100);
  }
}

}  // namespace
}  // namespace corridor
