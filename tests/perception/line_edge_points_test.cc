// EdgePeaksAlong on images drawn by hand: a slanted step edge whose position on every row is known
// (the edge pixel's grey level is its covered fraction), two parallel edges, flat lines searched
// column by column, the threshold, the step and bad input.
#include "perception/line_edge_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Geometry>

namespace corridor {
namespace {

// u = u0 + slope * v: a step from dark (40) to bright (200) at that u on every row, area-sampled
// (the pixel [u, u + 1) holds the step at u + 0.5 in its centre's frame).
cv::Mat SlantedEdge(int width, int height, double u0, double slope, int dark = 40,
                    int bright = 200) {
  cv::Mat bgr(height, width, CV_8UC3);
  for (int v = 0; v < height; ++v) {
    const double edge = u0 + slope * v;  // In pixel-centre coordinates.
    for (int u = 0; u < width; ++u) {
      const double covered = std::clamp(u + 0.5 - edge, 0.0, 1.0);  // Bright part of the pixel.
      const int g = static_cast<int>(std::lround(dark + covered * (bright - dark)));
      bgr.at<cv::Vec3b>(v, u) = cv::Vec3b(g, g, g);
    }
  }
  return bgr;
}

// The line u - u0 - slope v = 0, normalised.
Eigen::Vector3d LineOf(double u0, double slope) {
  Eigen::Vector3d line(1.0, -slope, -u0);
  return line / line.head<2>().norm();
}

// The positions along `line` (PositionAlong) of its points at rows v0 and v1.
void RowsToPositions(const Eigen::Vector3d& line, double u0, double slope, double v0, double v1,
                     double* t0, double* t1) {
  *t0 = PositionAlong(line, Eigen::Vector2d(u0 + slope * v0, v0));
  *t1 = PositionAlong(line, Eigen::Vector2d(u0 + slope * v1, v1));
  if (*t0 > *t1) std::swap(*t0, *t1);
}

TEST(EdgePeaksAlongTest, PeaksLieOnTheDrawnEdgeOnEveryRow) {
  const double u0 = 80.3, slope = 0.35;
  const cv::Mat bgr = SlantedEdge(200, 160, u0, slope);
  // The searched line: 2 px beside the edge, as a previous frame's line would be.
  const Eigen::Vector3d line = LineOf(u0 + 2.0, slope);
  ASSERT_TRUE(CrossedByRows(line));
  double t0, t1;
  RowsToPositions(line, u0 + 2.0, slope, 10, 149, &t0, &t1);
  EdgePeakSearch search;
  search.reach_px = 5;
  search.threshold = 40;
  std::vector<EdgePeak> peaks;
  const int searched = EdgePeaksAlong(bgr, line, t0, t1, search, &peaks);
  EXPECT_GE(searched, 138);
  ASSERT_EQ(static_cast<int>(peaks.size()), searched);
  for (const EdgePeak& peak : peaks) {
    const double truth = u0 + slope * peak.major;  // The edge's u on this row.
    EXPECT_NEAR(peak.point.x(), truth, 0.3) << "row " << peak.major;
    EXPECT_EQ(peak.point.y(), peak.major);
    EXPECT_NEAR(peak.offset, peak.point.x() - (u0 + 2.0 + slope * peak.major), 1e-9);
    // A 160-level step seen by the Sobel (1 2 1 across, the step's neighbours) along the normal.
    EXPECT_GT(peak.strength, 200);
  }
  // Every second row with step_px 2.
  std::vector<EdgePeak> every_second;
  search.step_px = 2;
  const int searched_half = EdgePeaksAlong(bgr, line, t0, t1, search, &every_second);
  EXPECT_NEAR(searched_half, searched / 2.0, 1.0);
  ASSERT_GE(every_second.size(), 2u);
  EXPECT_EQ(every_second[1].major - every_second[0].major, 2);
  // A threshold above the step's gradient: no peaks, the rows still searched.
  std::vector<EdgePeak> none;
  search.threshold = 5000;
  EXPECT_EQ(EdgePeaksAlong(bgr, line, t0, t1, search, &none), searched_half);
  EXPECT_TRUE(none.empty());
}

TEST(EdgePeaksAlongTest, AllPeaksOrTheNearestOne) {
  // Two edges 6 px apart: dark, a bright stripe, dark again.
  const double u0 = 60.2;
  cv::Mat bgr = SlantedEdge(160, 120, u0, 0.0);
  const cv::Mat back = SlantedEdge(160, 120, u0 + 6.0, 0.0, 200, 40);
  for (int v = 0; v < bgr.rows; ++v) {
    for (int u = static_cast<int>(u0) + 4; u < bgr.cols; ++u) {
      bgr.at<cv::Vec3b>(v, u) = back.at<cv::Vec3b>(v, u);
    }
  }
  const Eigen::Vector3d line = LineOf(u0 + 1.0, 0.0);
  double t0, t1;
  RowsToPositions(line, u0 + 1.0, 0.0, 20, 99, &t0, &t1);
  EdgePeakSearch search;
  search.reach_px = 8;
  search.threshold = 40;
  search.nearest_only = false;
  std::vector<EdgePeak> all;
  const int searched = EdgePeaksAlong(bgr, line, t0, t1, search, &all);
  ASSERT_EQ(static_cast<int>(all.size()), 2 * searched);
  for (size_t k = 0; k + 1 < all.size(); k += 2) {
    EXPECT_NEAR(all[k].point.x(), u0, 0.3);
    EXPECT_NEAR(all[k + 1].point.x(), u0 + 6.0, 0.3);
  }
  search.nearest_only = true;
  std::vector<EdgePeak> nearest;
  EXPECT_EQ(EdgePeaksAlong(bgr, line, t0, t1, search, &nearest), searched);
  ASSERT_EQ(static_cast<int>(nearest.size()), searched);
  for (const EdgePeak& peak : nearest) EXPECT_NEAR(peak.point.x(), u0, 0.3);  // 1 px, not 5.
}

TEST(EdgePeaksAlongTest, FlatLinesAreSearchedColumnByColumn) {
  // The transposed slanted edge: v = v0 + slope * u.
  const double v0 = 50.4, slope = 0.2;
  const cv::Mat bgr = SlantedEdge(120, 200, v0, slope).t();
  const Eigen::Vector3d line(-slope / std::hypot(1.0, slope), 1.0 / std::hypot(1.0, slope),
                             -v0 / std::hypot(1.0, slope));
  ASSERT_FALSE(CrossedByRows(line));
  const double t0 = PositionAlong(line, Eigen::Vector2d(10, v0 + 10 * slope));
  const double t1 = PositionAlong(line, Eigen::Vector2d(189, v0 + 189 * slope));
  EdgePeakSearch search;
  search.threshold = 40;
  std::vector<EdgePeak> peaks;
  const int searched = EdgePeaksAlong(bgr, line, std::min(t0, t1), std::max(t0, t1), search,
                                      &peaks);
  EXPECT_GE(searched, 178);
  ASSERT_EQ(static_cast<int>(peaks.size()), searched);
  for (const EdgePeak& peak : peaks) {
    EXPECT_EQ(peak.point.x(), peak.major);
    EXPECT_NEAR(peak.point.y(), v0 + slope * peak.major, 0.3) << "column " << peak.major;
  }
}

TEST(EdgePeaksAlongTest, BadInputFindsNothing) {
  const Eigen::Vector3d line = LineOf(50, 0.0);
  std::vector<EdgePeak> peaks;
  EXPECT_EQ(EdgePeaksAlong(cv::Mat(), line, 0, 100, EdgePeakSearch(), &peaks), 0);
  EXPECT_EQ(EdgePeaksAlong(cv::Mat(100, 100, CV_8UC1, cv::Scalar(0)), line, 0, 100,
                           EdgePeakSearch(), &peaks),
            0);
  // A line outside the image: every row's run leaves it.
  const cv::Mat bgr = SlantedEdge(100, 100, 50, 0.0);
  EXPECT_EQ(EdgePeaksAlong(bgr, LineOf(500, 0.0), 0, 100, EdgePeakSearch(), &peaks), 0);
  EXPECT_TRUE(peaks.empty());
}

}  // namespace
}  // namespace corridor
