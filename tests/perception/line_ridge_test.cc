// RidgeFraction on drawn bands: an oblique line across a 200x160 image with given greys above the
// line, on it (a band `width` px thick) and below it. Hand-computed expectations: a joint darker
// or lighter than equal sides is a ridge everywhere; a step, a step with the joint's grey between
// its sides, and a joint fainter than the sides differ are not.
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "perception/line_ridge.h"

namespace corridor {
namespace {

// The line v = 40 + 0.5 u, as a MergedLine over u in [10, 190].
MergedLine DrawnLine() {
  MergedLine m;
  const Eigen::Vector2d normal = Eigen::Vector2d(-0.5, 1.0).normalized();  // Points down.
  m.line = Eigen::Vector3d(normal.x(), normal.y(), -40.0 * normal.y());
  m.start = Eigen::Vector2d(10, 45);
  m.end = Eigen::Vector2d(190, 135);
  m.length = (m.end - m.start).norm();
  m.covered = m.length;
  m.slope = 0.5;
  return m;
}

// Each pixel's grey from its signed distance to the line (positive below): `above`, `joint`
// within width / 2 of the line, `below`. Drawn in grey, as BGR.
cv::Mat Band(int above, int joint, int below, double width) {
  const MergedLine m = DrawnLine();
  cv::Mat image(160, 200, CV_8UC3);
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      const double d = m.line.dot(Eigen::Vector3d(u, v, 1));
      const int grey = std::abs(d) <= 0.5 * width ? joint : (d < 0 ? above : below);
      image.at<cv::Vec3b>(v, u) = cv::Vec3b(grey, grey, grey);
    }
  }
  return image;
}

TEST(LineRidgeTest, AJointDarkerOrLighterThanEqualSidesIsARidge) {
  EXPECT_DOUBLE_EQ(RidgeFraction(Band(90, 70, 90, 3), DrawnLine(), 0), 1.0);
  EXPECT_DOUBLE_EQ(RidgeFraction(Band(90, 115, 90, 3), DrawnLine(), 0), 1.0);
  // A one-pixel joint still darkens one of the three rows looked at.
  EXPECT_DOUBLE_EQ(RidgeFraction(Band(90, 70, 88, 1), DrawnLine(), 0), 1.0);
}

TEST(LineRidgeTest, AStepOrAFaintJointIsNot) {
  EXPECT_DOUBLE_EQ(RidgeFraction(Band(120, 90, 60, 3), DrawnLine(), 0), 0.0);  // Joint between.
  EXPECT_DOUBLE_EQ(RidgeFraction(Band(120, 60, 60, 0), DrawnLine(), 0), 0.0);  // A plain step.
  // Darker than both sides by 10, but the sides differ by 30: a shadow at a junction.
  EXPECT_DOUBLE_EQ(RidgeFraction(Band(110, 70, 80, 3), DrawnLine(), 0), 0.0);
  // Darker by less than the 6 grey levels asked.
  EXPECT_DOUBLE_EQ(RidgeFraction(Band(90, 86, 90, 3), DrawnLine(), 0), 0.0);
}

TEST(LineRidgeTest, CountsOnlyThePartThatIsAJoint) {
  // The joint drawn over the line's left half only: half of the points along it are ridges.
  cv::Mat image = Band(90, 90, 90, 0);
  const cv::Mat joint = Band(90, 60, 90, 3);
  joint.colRange(0, 100).copyTo(image.colRange(0, 100));
  EXPECT_NEAR(RidgeFraction(image, DrawnLine(), 0), 0.5, 1.0 / 24 + 1e-9);
}

TEST(LineRidgeTest, WorksOnTheRowsOfARegionOfInterest) {
  const cv::Mat image = Band(90, 70, 90, 3);
  const int roi_top = 30;
  EXPECT_DOUBLE_EQ(RidgeFraction(image.rowRange(roi_top, image.rows), DrawnLine(), roi_top), 1.0);
}

TEST(LineRidgeTest, ALineOutsideTheImageHasNoAnswer) {
  MergedLine m = DrawnLine();
  m.start += Eigen::Vector2d(500, 0);
  m.end += Eigen::Vector2d(500, 0);
  EXPECT_EQ(RidgeFraction(Band(90, 70, 90, 3), m, 0), -1.0);
}

}  // namespace
}  // namespace corridor
