// FindLowerEdge on drawn bands below a line through a vanishing point: a baseboard on a carpet
// (its foot at a known turn), a stripe beside the wall with floor on both sides, a plain floor;
// and TurnTowardFloor against hand-computed directions.
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "perception/lower_edge.h"
#include "tests/support/angle_bands.h"

namespace corridor {
namespace {

constexpr double kDeg = testing_util::kBandDeg;
const Eigen::Vector2d& kVp = testing_util::kBandVp;
using testing_util::BandDown;
using testing_util::DrawByAngle;

// A MergedLine from the vanishing point along `direction`, from `r0` to `r1` px.
MergedLine LineAlong(const Eigen::Vector2d& direction, double r0, double r1) {
  return LineThrough(kVp + r0 * direction, kVp + r1 * direction);
}

// A carpet: each pixel its own shade of red-brown, as textured as a real one.
cv::Vec3b Carpet(std::mt19937& rng) {
  std::uniform_int_distribution<int> jitter(-30, 30);
  const int j = jitter(rng);
  return cv::Vec3b(cv::saturate_cast<uchar>(70 + j), cv::saturate_cast<uchar>(60 + j),
                   cv::saturate_cast<uchar>(120 + j));
}

TEST(LowerEdgeTest, FindsABaseboardsFootOnACarpet) {
  for (const bool left : {true, false}) {
    // Wall above 30 degrees, a grey baseboard down to 33, carpet below.
    const cv::Mat image = DrawByAngle(left, [](double angle, std::mt19937& rng) {
      if (angle < 30) return cv::Vec3b(180, 180, 190);
      if (angle < 33) return cv::Vec3b(80, 80, 80);
      return Carpet(rng);
    });
    const MergedLine top = LineAlong(BandDown(30, left), 20, 340);
    MergedLine foot;
    double turn = 0;
    ASSERT_TRUE(FindLowerEdge(image, 0, top, kVp, left, 6.0, &foot, &turn)) << left;
    EXPECT_NEAR(turn, 3.0, 0.15) << left;
    // The foot passes through the vanishing point, along 33 degrees.
    EXPECT_NEAR(foot.line.dot(kVp.homogeneous()), 0, 0.5);
    EXPECT_NEAR(foot.line.dot((kVp + 300 * BandDown(33, left)).homogeneous()), 0, 1.0);
    // The same image with the ROI's top rows cut off gives the same foot.
    MergedLine cut;
    double cut_turn = 0;
    ASSERT_TRUE(FindLowerEdge(image.rowRange(150, 480), 150, top, kVp, left, 6.0, &cut, &cut_turn));
    EXPECT_NEAR(cut_turn, turn, 1e-9);
  }
}

TEST(LowerEdgeTest, AThinJointBeyondTheFootIsNotTheBandAgain) {
  for (const bool left : {true, false}) {
    // A dark baseboard from 30 to 33 degrees on a slightly lighter tiled floor, with a thin
    // joint along the wall beyond the search (37.6 degrees) darker than the baseboard: on its way
    // down and up the profile passes through the baseboard's colour, but only for a step or two.
    const cv::Mat image = DrawByAngle(left, [](double angle, std::mt19937&) {
      if (angle < 30) return cv::Vec3b(90, 90, 170);
      if (angle < 33) return cv::Vec3b(70, 76, 70);
      // The joint, blurred as a camera sees it: 25 levels darker at its middle.
      const double d = (angle - 37.6) / 0.4;
      const int dip = static_cast<int>(std::lround(25 * std::exp(-d * d)));
      return cv::Vec3b(84 - dip, 92 - dip, 84 - dip);
    });
    const MergedLine top = LineAlong(BandDown(30, left), 20, 340);
    MergedLine foot;
    double turn = 0;
    ASSERT_TRUE(FindLowerEdge(image, 0, top, kVp, left, 6.0, &foot, &turn)) << left;
    EXPECT_NEAR(turn, 3.0, 0.15) << left;
  }
}

TEST(LowerEdgeTest, AStripeBesideTheWallIsNoBand) {
  // Floor from the junction at 30 degrees, a dark stripe from 33 to 35, floor again beyond: the
  // floor's colour comes back beyond the stripe.
  const cv::Mat image = DrawByAngle(true, [](double angle, std::mt19937&) {
    if (angle < 30) return cv::Vec3b(180, 180, 190);
    if (angle >= 33 && angle < 35) return cv::Vec3b(20, 20, 20);
    return cv::Vec3b(90, 110, 140);
  });
  const MergedLine junction = LineAlong(BandDown(30, true), 20, 340);
  MergedLine foot;
  double turn = 0;
  EXPECT_FALSE(FindLowerEdge(image, 0, junction, kVp, true, 6.0, &foot, &turn));
}

TEST(LowerEdgeTest, AReflectionFadingIntoTheFloorIsNoBand) {
  for (const bool left : {true, false}) {
    // The junction at 30 degrees below a dark baseboard; on a polished floor the baseboard's
    // reflection fades evenly from dark to the floor's grey over 4 degrees, and a faint ripple in
    // the fade steps up most near 32.8 degrees. Nothing on the floor side is flat: it is one
    // edge's tail, not a band with a foot.
    const cv::Mat image = DrawByAngle(left, [](double angle, std::mt19937&) {
      if (angle < 30) return cv::Vec3b(40, 40, 45);
      const double fade = 40 * std::min(1.0, (angle - 30) / 4.0);
      const double ripple = 2 * std::exp(-std::pow((angle - 33) / 0.3, 2));
      const int v = static_cast<int>(std::lround(70 + fade + ripple));
      return cv::Vec3b(v, v, v);
    });
    MergedLine foot;
    double turn = 0;
    EXPECT_FALSE(FindLowerEdge(image, 0, LineAlong(BandDown(30, left), 20, 340), kVp, left, 6.0,
                               &foot, &turn))
        << left << " turn " << turn;
  }
}

TEST(LowerEdgeTest, APlainFloorHasNoEdge) {
  const cv::Mat image = DrawByAngle(false, [](double angle, std::mt19937&) {
    return angle < 30 ? cv::Vec3b(180, 180, 190) : cv::Vec3b(90, 110, 140);
  });
  MergedLine foot;
  double turn = 0;
  EXPECT_FALSE(FindLowerEdge(image, 0, LineAlong(BandDown(30, false), 20, 340), kVp, false, 6.0,
                             &foot, &turn));
}

TEST(LowerEdgeTest, RefusesWhatItCannotLookAt) {
  const cv::Mat image(480, 640, CV_8UC3, cv::Scalar(0, 0, 0));
  const MergedLine top = LineAlong(BandDown(30, true), 20, 340);
  MergedLine foot;
  double turn = 0;
  EXPECT_FALSE(FindLowerEdge(cv::Mat(), 0, top, kVp, true, 6.0, &foot, &turn));
  EXPECT_FALSE(FindLowerEdge(cv::Mat(480, 640, CV_8UC1), 0, top, kVp, true, 6.0, &foot, &turn));
  EXPECT_FALSE(FindLowerEdge(image, 0, top, kVp, true, 0.0, &foot, &turn));
  EXPECT_FALSE(FindLowerEdge(image, 0, top, Eigen::Vector2d(NAN, 0), true, 6.0, &foot, &turn));
  // A line 3 px long near the vanishing point: its band would be under 4 px everywhere.
  EXPECT_FALSE(FindLowerEdge(image, 0, LineAlong(BandDown(30, true), 1, 4), kVp, true, 6.0, &foot,
                             &turn));
}

TEST(LowerEdgeTest, TurnsTowardTheFloor) {
  for (const bool left : {true, false}) {
    const MergedLine line = LineAlong(BandDown(30, left), 20, 340);
    const Eigen::Vector3d turned =
        TurnTowardFloor(line.line, kVp + 300 * BandDown(30, left), kVp, left, 10.0);
    EXPECT_NEAR(std::hypot(turned.x(), turned.y()), 1.0, 1e-12);
    EXPECT_GE(turned.y(), 0);
    EXPECT_NEAR(turned.dot(kVp.homogeneous()), 0, 1e-9);
    // 40 degrees below the horizontal: toward straight down.
    EXPECT_NEAR(turned.dot((kVp + 100 * BandDown(40, left)).homogeneous()), 0, 1e-9) << left;
  }
}

}  // namespace
}  // namespace corridor
