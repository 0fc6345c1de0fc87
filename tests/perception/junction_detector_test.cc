#include "perception/junction_detector.h"

#include <cmath>

#include <gtest/gtest.h>

#include "tests/perception/drawn_corridor.h"

namespace corridor {
namespace {

using testing::ColumnAt;
using testing::DrawCorridor;

// Horizontal distance, at row v, between a detected line and the drawn one (through vp and p).
double ColumnError(const JunctionLine& line, const Eigen::Vector2d& vp, const Eigen::Vector2d& p,
                   double v) {
  const double u_detected = -(line.line.y() * v + line.line.z()) / line.line.x();
  return std::abs(u_detected - ColumnAt(vp, p, v));
}

double AngleErrorDeg(const JunctionLine& line, const Eigen::Vector2d& vp, const Eigen::Vector2d& p) {
  const Eigen::Vector2d truth = (p - vp).normalized();
  const Eigen::Vector2d direction(line.line.y(), -line.line.x());
  return std::acos(std::min(1.0, std::abs(truth.dot(direction)))) * 180.0 / M_PI;
}

class DrawnCorridorTest : public ::testing::TestWithParam<bool> {};

TEST_P(DrawnCorridorTest, FindsTheDrawnJunctions) {
  const auto corridor = DrawCorridor(GetParam());
  JunctionPair pair;
  ASSERT_TRUE(DetectJunctions(corridor.bgr, JunctionDetectorOptions(), &pair).ok());
  ASSERT_TRUE(pair.status.ok()) << pair.status.ToString();
  EXPECT_LT(AngleErrorDeg(pair.left, corridor.vp, corridor.left_point), 1.0);
  EXPECT_LT(AngleErrorDeg(pair.right, corridor.vp, corridor.right_point), 1.0);
  for (double v : {300.0, 450.0}) {
    EXPECT_LT(ColumnError(pair.left, corridor.vp, corridor.left_point, v), 2.0) << v;
    EXPECT_LT(ColumnError(pair.right, corridor.vp, corridor.right_point, v), 2.0) << v;
  }
  EXPECT_NEAR(pair.vanishing_point.x(), corridor.vp.x(), 4.0);
  EXPECT_NEAR(pair.vanishing_point.y(), corridor.vp.y(), 4.0);
  EXPECT_GT(pair.left.support.size(), 50u);
  EXPECT_GT(pair.left.confidence, 0.3);
  EXPECT_GT(pair.left.near_end.y(), pair.left.far_end.y());
}

INSTANTIATE_TEST_SUITE_P(WithAndWithoutDistractors, DrawnCorridorTest, ::testing::Bool());

TEST(JunctionDetectorTest, DegenerateImagesFindNoCorridor) {
  cv::Mat noise(240, 320, CV_8UC3);
  cv::RNG(5).fill(noise, cv::RNG::UNIFORM, 0, 256);
  const cv::Mat images[] = {cv::Mat(1, 1, CV_8UC3, cv::Scalar::all(100)),
                            cv::Mat(4, 4, CV_8UC3, cv::Scalar::all(100)),
                            cv::Mat(10, 20000, CV_8UC3, cv::Scalar::all(100)),
                            cv::Mat(240, 320, CV_8UC3, cv::Scalar::all(0)),
                            cv::Mat(240, 320, CV_8UC3, cv::Scalar::all(255)),
                            noise};
  for (const auto& image : images) {
    JunctionPair pair;
    ASSERT_TRUE(DetectJunctions(image, JunctionDetectorOptions(), &pair).ok());
    EXPECT_EQ(pair.status.code(), StatusCode::kNoCorridorFound)
        << image.cols << "x" << image.rows << ": " << pair.status.ToString();
  }
}

// A blank image has no line at all: the refusal names both sides, not only the left one.
TEST(JunctionDetectorTest, ABlankImageNamesBothMissingSides) {
  JunctionPair pair;
  ASSERT_TRUE(
      DetectJunctions(cv::Mat(240, 320, CV_8UC3, cv::Scalar::all(0)), JunctionDetectorOptions(),
                      &pair)
          .ok());
  EXPECT_NE(pair.status.message().find("no left or right junction candidate"), std::string::npos)
      << pair.status.ToString();
}

TEST(JunctionDetectorTest, EmptyOrWrongDepthImageIsInvalid) {
  JunctionPair pair;
  EXPECT_EQ(DetectJunctions(cv::Mat(), JunctionDetectorOptions(), &pair).code(),
            StatusCode::kInvalidArgument);
  EXPECT_EQ(DetectJunctions(cv::Mat(50, 50, CV_16UC3), JunctionDetectorOptions(), &pair).code(),
            StatusCode::kInvalidArgument);
}

TEST(JunctionDetectorTest, GreyAndAlphaImagesWork) {
  const auto corridor = DrawCorridor(false);
  cv::Mat gray, bgra;
  cv::cvtColor(corridor.bgr, gray, cv::COLOR_BGR2GRAY);
  cv::cvtColor(corridor.bgr, bgra, cv::COLOR_BGR2BGRA);
  for (const auto& image : {gray, bgra}) {
    JunctionPair pair;
    ASSERT_TRUE(DetectJunctions(image, JunctionDetectorOptions(), &pair).ok());
    EXPECT_TRUE(pair.status.ok()) << pair.status.ToString();
  }
}

TEST(JunctionDetectorTest, OptionsCheckRejectsBadValues) {
  std::string why;
  EXPECT_TRUE(JunctionDetectorOptions().Check(&why)) << why;
  JunctionDetectorOptions o;
  o.roi_top_fraction = 1.2;
  EXPECT_FALSE(o.Check(&why));
  o = JunctionDetectorOptions();
  o.canny_low_ratio = 1.5;
  EXPECT_FALSE(o.Check(&why));
  EXPECT_NE(why.find("Canny"), std::string::npos) << why;
  o = JunctionDetectorOptions();
  o.hough_threshold = 0;
  EXPECT_FALSE(o.Check(&why));
  o = JunctionDetectorOptions();
  o.relaxed_hough_threshold = -1;
  EXPECT_FALSE(o.Check(&why));
  EXPECT_NE(why.find("relaxed_hough_threshold"), std::string::npos) << why;
  o.relaxed_hough_threshold = 0;  // No second look.
  EXPECT_TRUE(o.Check(&why)) << why;
  o.relaxed_hough_min_length_fraction = 0;
  EXPECT_FALSE(o.Check(&why));
}

TEST(JunctionDetectorTest, SampleAlongLineIsEvenlySpacedByHand) {
  JunctionLine line;
  line.near_end = {10, 100};
  line.far_end = {40, 40};
  const auto points = SampleAlongLine(line, 4);
  ASSERT_EQ(points.size(), 4u);
  // Steps of (30, -60) / 3 = (10, -20).
  EXPECT_NEAR(points[1].x(), 20, 1e-12);
  EXPECT_NEAR(points[1].y(), 80, 1e-12);
  EXPECT_NEAR(points[3].x(), 40, 1e-12);
  EXPECT_NEAR(points[3].y(), 40, 1e-12);
  EXPECT_TRUE(SampleAlongLine(line, 0).empty());
}

}  // namespace
}  // namespace corridor
