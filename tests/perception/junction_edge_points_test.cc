// MeasureJunctionEdgePoints on edges drawn by hand: a blurred slanted step whose position is known
// analytically (the grey level is the step convolved with a Gaussian, sampled at pixel centres),
// found from integer support pixels on both sides of it and a fitted line off by a fraction of a
// pixel; weights that follow the gradient's strength; rows without support; bad input.
#include "perception/junction_edge_points.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

namespace corridor {
namespace {

// The edge u = u0 + slope v, a step from `dark` to `bright` (left to right) blurred by a Gaussian
// of sigma_px across it; `contrast(v)` scales the step row by row.
template <typename Contrast>
cv::Mat BlurredEdge(int width, int height, double u0, double slope, double sigma_px,
                    Contrast contrast) {
  cv::Mat bgr(height, width, CV_8UC3);
  const double across = 1.0 / std::hypot(1.0, slope);  // Perpendicular px per px along a row.
  for (int v = 0; v < height; ++v) {
    const double edge = u0 + slope * v;
    const double step = contrast(v);
    for (int u = 0; u < width; ++u) {
      const double d = (u - edge) * across;
      const double level = 60 + step * 0.5 * std::erfc(-d / (std::sqrt(2.0) * sigma_px));
      const int g = static_cast<int>(std::lround(std::clamp(level, 0.0, 255.0)));
      bgr.at<cv::Vec3b>(v, u) = cv::Vec3b(g, g, g);
    }
  }
  return bgr;
}

Eigen::Vector3d LineOf(double u0, double slope) {
  Eigen::Vector3d line(1.0, -slope, -u0);
  return line / line.head<2>().norm();
}

// A junction as the detector leaves it: its fitted line (off the true edge by `shift` px along the
// rows and slightly turned), and integer support pixels on both sides of the edge on rows
// [v0, v1].
JunctionLine DetectedJunction(double u0, double slope, double shift, int v0, int v1) {
  JunctionLine junction;
  junction.line = LineOf(u0 + shift, slope * 1.01);
  for (int v = v0; v <= v1; ++v) {
    const double edge = u0 + slope * v;
    junction.support.emplace_back(std::floor(edge), v);
    junction.support.emplace_back(std::floor(edge) + 1, v);
  }
  return junction;
}

TEST(JunctionEdgePointsTest, PointsLieOnTheDrawnEdgeToATenthOfAPixel) {
  const double u0 = 120.37, slope = -0.62;  // A left junction's lean.
  const cv::Mat bgr = BlurredEdge(240, 200, u0, slope, 1.0, [](int) { return 120.0; });
  JunctionLine junction = DetectedJunction(u0, slope, 0.6, 20, 179);
  MeasureJunctionEdgePoints(bgr, JunctionEdgePointOptions(), &junction);
  // One point per supported row (their neighbours 19 and 180 too), on the true edge.
  ASSERT_GE(junction.edge_points.size(), 160u);
  ASSERT_LE(junction.edge_points.size(), 162u);
  ASSERT_EQ(junction.edge_weights.size(), junction.edge_points.size());
  const Eigen::Vector3d truth = LineOf(u0, slope);
  double worst = 0, mean = 0;
  for (const Eigen::Vector2d& p : junction.edge_points) {
    const double distance = truth.dot(p.homogeneous());
    worst = std::max(worst, std::abs(distance));
    mean += distance / junction.edge_points.size();
  }
  EXPECT_LT(worst, 0.1);
  EXPECT_LT(std::abs(mean), 0.05);
  // The integer support pixels were up to a pixel off along the row.
  double support_worst = 0;
  for (const Eigen::Vector2d& p : junction.support) {
    support_worst = std::max(support_worst, std::abs(truth.dot(p.homogeneous())));
  }
  EXPECT_GT(support_worst, 0.5);
  // An even edge: every weight near 1 (the peak's sampled strength varies with the edge's phase
  // on the row).
  for (double w : junction.edge_weights) EXPECT_NEAR(w, 1.0, 0.15);
}

TEST(JunctionEdgePointsTest, WeightsFollowTheSquaredContrastUpToTheCap) {
  const double u0 = 90.6, slope = 0.45;
  // Rows 10-69 have contrast 60, rows 70-139 120 (the median row's), rows 140-189 180.
  const auto contrast = [](int v) { return v >= 140 ? 180.0 : v >= 70 ? 120.0
                                                                      : 60.0; };
  const cv::Mat bgr = BlurredEdge(240, 200, u0, slope, 1.2, contrast);
  JunctionLine junction = DetectedJunction(u0, slope, -0.4, 10, 189);
  JunctionEdgePointOptions options;
  options.threshold = 10;
  options.max_weight = 4;
  MeasureJunctionEdgePoints(bgr, options, &junction);
  ASSERT_GE(junction.edge_points.size(), 170u);
  // Relative weights, before the scaling to mean 1: the median row has contrast 120 (ratio 1);
  // contrast 60 gives 1/4, contrast 180 gives 9/4.
  std::vector<double> low, mid, high;
  for (size_t i = 0; i < junction.edge_points.size(); ++i) {
    const double v = junction.edge_points[i].y();
    if (v < 68) low.push_back(junction.edge_weights[i]);
    if (v > 72 && v < 138) mid.push_back(junction.edge_weights[i]);
    if (v > 142) high.push_back(junction.edge_weights[i]);
  }
  ASSERT_FALSE(low.empty());
  ASSERT_FALSE(mid.empty());
  ASSERT_FALSE(high.empty());
  const auto average = [](const std::vector<double>& x) {
    double s = 0;
    for (double y : x) s += y;
    return s / x.size();
  };
  EXPECT_NEAR(average(low) / average(mid), 0.25, 0.03);
  EXPECT_NEAR(average(high) / average(mid), 2.25, 0.15);
  double sum = 0;
  for (double w : junction.edge_weights) sum += w;
  EXPECT_NEAR(sum / junction.edge_weights.size(), 1.0, 1e-9);
  // With a cap of 2, the strong rows weigh twice the median's.
  options.max_weight = 2;
  MeasureJunctionEdgePoints(bgr, options, &junction);
  high.clear();
  mid.clear();
  for (size_t i = 0; i < junction.edge_points.size(); ++i) {
    const double v = junction.edge_points[i].y();
    if (v > 72 && v < 138) mid.push_back(junction.edge_weights[i]);
    if (v > 142) high.push_back(junction.edge_weights[i]);
  }
  EXPECT_NEAR(average(high) / average(mid), 2.0, 0.1);
}

TEST(JunctionEdgePointsTest, RowsWithoutSupportGiveNoPoints) {
  const double u0 = 100.2, slope = 0.3;
  const cv::Mat bgr = BlurredEdge(240, 200, u0, slope, 1.0, [](int) { return 120.0; });
  JunctionLine junction = DetectedJunction(u0, slope, 0.0, 20, 59);
  const JunctionLine far = DetectedJunction(u0, slope, 0.0, 140, 179);
  junction.support.insert(junction.support.end(), far.support.begin(), far.support.end());
  MeasureJunctionEdgePoints(bgr, JunctionEdgePointOptions(), &junction);
  ASSERT_GE(junction.edge_points.size(), 80u);
  for (const Eigen::Vector2d& p : junction.edge_points) {
    EXPECT_TRUE((p.y() >= 19 && p.y() <= 60) || (p.y() >= 139 && p.y() <= 180)) << p.y();
  }
}

TEST(JunctionEdgePointsTest, AnEdgeBeyondReachOrNoImageGivesNothing) {
  const double u0 = 100.2, slope = 0.3;
  const cv::Mat bgr = BlurredEdge(240, 200, u0, slope, 1.0, [](int) { return 120.0; });
  // The fitted line 6 px off the edge: nothing within max_distance_px.
  JunctionLine junction = DetectedJunction(u0, slope, 6.0, 20, 179);
  junction.edge_points = {Eigen::Vector2d(1, 2)};  // Replaced, not appended to.
  MeasureJunctionEdgePoints(bgr, JunctionEdgePointOptions(), &junction);
  EXPECT_TRUE(junction.edge_points.empty());
  EXPECT_TRUE(junction.edge_weights.empty());
  junction = DetectedJunction(u0, slope, 0.0, 20, 179);
  MeasureJunctionEdgePoints(cv::Mat(), JunctionEdgePointOptions(), &junction);
  EXPECT_TRUE(junction.edge_points.empty());
  JunctionEdgePointOptions bad;
  bad.reach_px = 0.5;
  EXPECT_FALSE(bad.Check(nullptr));
  bad = JunctionEdgePointOptions();
  bad.max_weight = 0.5;
  EXPECT_FALSE(bad.Check(nullptr));
  EXPECT_TRUE(JunctionEdgePointOptions().Check(nullptr));
}

}  // namespace
}  // namespace corridor
