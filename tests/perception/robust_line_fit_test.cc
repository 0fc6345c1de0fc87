// FitLineLeastDistance against lines known by construction and against cv::fitLine(DIST_L1), an
// independent fit of the least sum of distances.
#include "perception/robust_line_fit.h"

#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace corridor {
namespace {

double SumOfDistances(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector3d& l) {
  double sum = 0;
  for (const auto& p : points) sum += std::abs(l.dot(p.homogeneous())) / l.head<2>().norm();
  return sum;
}

// Points along the line through (x0, y0) at `angle`, every `step` px, with every `outlier_every`th
// moved `outlier` px across it (0: none).
std::vector<Eigen::Vector2d> PointsAlong(double x0, double y0, double angle, int count,
                                         double step, int outlier_every, double outlier) {
  const Eigen::Vector2d direction(std::cos(angle), std::sin(angle)), normal(-direction.y(),
                                                                            direction.x());
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < count; ++i) {
    Eigen::Vector2d p = Eigen::Vector2d(x0, y0) + i * step * direction;
    if (outlier_every > 0 && i % outlier_every == 3) p += outlier * normal;
    points.push_back(p);
  }
  return points;
}

TEST(RobustLineFitTest, RecoversAnExactLineDespiteOutliers) {
  // Every angle class, and counts that are and are not multiples of the four lanes.
  for (const double angle_deg : {-80.0, -35.0, 0.0, 12.5, 47.0, 89.0}) {
    for (const int count : {8, 9, 63, 301}) {
      const double angle = angle_deg * M_PI / 180;
      const auto points = PointsAlong(320, 410, angle, count, 1.3, 9, 6.0);
      Eigen::Vector3d line;
      ASSERT_TRUE(FitLineLeastDistance(points, &line)) << angle_deg << " " << count;
      EXPECT_NEAR(line.head<2>().norm(), 1.0, 1e-12);
      EXPECT_GE(line.y(), 0.0);
      // The inliers lie on the fitted line to within the L1 weights' floor (0.05 px), where a
      // least-squares fit would be pulled about 0.7 px towards the outliers.
      const Eigen::Vector2d normal(-std::sin(angle), std::cos(angle));
      EXPECT_NEAR(std::abs(line.head<2>().dot(normal)), 1.0, 1e-5) << angle_deg << " " << count;
      for (int i = 0; i < count; ++i) {
        if (i % 9 == 3) continue;
        EXPECT_NEAR(line.dot(points[i].homogeneous()), 0.0, 0.05) << angle_deg << " " << i;
      }
    }
  }
}

TEST(RobustLineFitTest, SumOfDistancesAsSmallAsOpenCvsL1Fit) {
  cv::RNG rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const double angle = rng.uniform(-1.5, 1.5);
    auto points = PointsAlong(rng.uniform(0.0, 600.0), rng.uniform(200.0, 400.0), angle,
                              40 + trial * 17, 1.0, 7, rng.uniform(-20.0, 20.0));
    std::vector<cv::Point2f> cv_points;
    for (auto& p : points) {
      p += Eigen::Vector2d(rng.gaussian(0.7), rng.gaussian(0.7));
      cv_points.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
    }
    Eigen::Vector3d line;
    ASSERT_TRUE(FitLineLeastDistance(points, &line));
    cv::Vec4f fitted;
    cv::fitLine(cv_points, fitted, cv::DIST_L1, 0, 0.01, 0.01);
    const Eigen::Vector3d opencv(-fitted[1], fitted[0],
                                 fitted[1] * fitted[2] - fitted[0] * fitted[3]);
    EXPECT_LE(SumOfDistances(points, line), 1.005 * SumOfDistances(points, opencv)) << trial;
  }
}

TEST(RobustLineFitTest, TooFewPointsLeaveTheLineAlone) {
  const auto points = PointsAlong(0, 0, 0.3, 7, 1.0, 0, 0);
  Eigen::Vector3d line(1, 2, 3);
  EXPECT_FALSE(FitLineLeastDistance(points, &line));
  EXPECT_EQ(line, Eigen::Vector3d(1, 2, 3));
  EXPECT_FALSE(FitLineLeastDistance({}, &line));
}

}  // namespace
}  // namespace corridor
