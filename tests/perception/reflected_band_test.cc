// FindReflectedJunction on drawn bands below a line through a vanishing point, coloured by their
// angle below the horizontal: a baseboard and its reflection on a polished floor (the junction at
// the band's middle in slope, computed by hand), with a stripe inside the reflection, nearly the
// baseboard's colour, a baseboard above a true junction on a matte floor, a band whose lower part
// is no blend of the baseboard and the floor, and bad input. JunctionAtReflectedBandsMiddle on the
// same bands; FindJunctionBelowBandTop on them from the baseboard's top.
#include <cmath>

#include <gtest/gtest.h>

#include "perception/reflected_band.h"
#include "tests/support/angle_bands.h"

namespace corridor {
namespace {

constexpr double kDeg = testing_util::kBandDeg;
const Eigen::Vector2d& kVp = testing_util::kBandVp;
using testing_util::BandDown;

JunctionLine LineAt(double angle_deg, bool left) {
  JunctionLine line;
  line.far_end = kVp + 20 * BandDown(angle_deg, left);
  line.near_end = kVp + 330 * BandDown(angle_deg, left);
  const Eigen::Vector3d l = line.far_end.homogeneous().cross(line.near_end.homogeneous());
  line.line = l / l.head<2>().norm();
  return line;
}

// An image coloured by angle below the vanishing point (tests/support/angle_bands.h), from a
// colour of the angle alone.
template <typename Colour>
cv::Mat DrawByAngle(bool left, Colour colour) {
  return testing_util::DrawByAngle(left, [&](double angle, std::mt19937&) { return colour(angle); });
}

cv::Vec3b Blend(const cv::Vec3d& a, const cv::Vec3d& b, double g) {
  const cv::Vec3d c = (1 - g) * a + g * b;
  return cv::Vec3b(cv::saturate_cast<uchar>(c[0]), cv::saturate_cast<uchar>(c[1]),
                   cv::saturate_cast<uchar>(c[2]));
}

// Wall above 30 degrees, the baseboard down to the junction, its reflection down to 38 degrees;
// the junction's slope is the mean of 30's and 38's (the mirror about the floor), about 34.1.
const double kTop = 30, kBottom = 38;
const double kJunction = std::atan(0.5 * (std::tan(kTop * kDeg) + std::tan(kBottom * kDeg))) / kDeg;
const cv::Vec3d kWall(200, 205, 215), kBoard(60, 60, 70), kMatte(110, 120, 150);

// Wall down to `top`, the baseboard down to `junction`, its reflection on a floor of colour
// `floor` and gloss `gloss` down to `bottom`, then the floor mirroring the wall.
cv::Mat PolishedBand(bool left, double top, double junction, double bottom,
                     const cv::Vec3d& floor = kMatte, double gloss = 0.4) {
  return DrawByAngle(left, [&](double angle) {
    if (angle < top) return Blend(kWall, kWall, 0);
    if (angle < junction) return Blend(kBoard, kBoard, 0);
    if (angle < bottom) return Blend(floor, kBoard, gloss);
    return Blend(floor, kWall, gloss);
  });
}

TEST(ReflectedBandTest, APolishedFloorsReflectionPutsTheJunctionAtTheBandsMiddle) {
  for (const bool left : {true, false}) {
    // The floor mirrors the baseboard, then the wall, blended with its own colour.
    const cv::Mat image = PolishedBand(left, kTop, kJunction, kBottom);
    double turn = 0;
    ASSERT_TRUE(
        FindReflectedJunction(image, LineAt(kBottom, left), kVp, left, 12.0, &turn))
        << left;
    EXPECT_NEAR(turn, kJunction - kBottom, 0.15) << left;
    // Taken at the baseboard's top instead, the junction lies below it at the same middle.
    ASSERT_TRUE(FindJunctionBelowBandTop(image, LineAt(kTop, left), kVp, left, 12.0, &turn))
        << left;
    EXPECT_NEAR(turn, kJunction - kTop, 0.15) << left;
  }
}

TEST(ReflectedBandTest, AStripeInsideTheReflectionLeavesTheMiddleFound) {
  // A dark stripe mirrored inside the lower part (a door's threshold, a joint): it changes the
  // band more than the step at the middle does, and the junction is still the middle.
  const double gloss = 0.4;
  const double stripe_from = kJunction + 0.5 * (kBottom - kJunction);
  const cv::Mat image = DrawByAngle(true, [&](double angle) {
    if (angle < kTop) return Blend(kWall, kWall, 0);
    if (angle < kJunction) return Blend(kBoard, kBoard, 0);
    if (angle >= stripe_from && angle < stripe_from + 0.3) return cv::Vec3b(10, 10, 10);
    if (angle < kBottom) return Blend(kMatte, kBoard, gloss);
    return Blend(kMatte, kWall, gloss);
  });
  double turn = 0;
  ASSERT_TRUE(FindReflectedJunction(image, LineAt(kBottom, true), kVp, true, 12.0, &turn));
  EXPECT_NEAR(turn, kJunction - kBottom, 0.15);
}

TEST(ReflectedBandTest, AReflectionNearlyTheBaseboardsColourIsFound) {
  // A floor whose own colour is near the baseboard's: the reflection differs from the baseboard
  // by (1 - gloss) |floor - baseboard| = 0.5 * 56 = 28 levels, 6.5% of the wall-to-baseboard
  // step (430 levels).
  const cv::Vec3d floor(80, 80, 86);
  const cv::Mat image = PolishedBand(false, kTop, kJunction, kBottom, floor, 0.5);
  double turn = 0;
  ASSERT_TRUE(FindReflectedJunction(image, LineAt(kBottom, false), kVp, false, 12.0, &turn));
  EXPECT_NEAR(turn, kJunction - kBottom, 0.15);
}

TEST(ReflectedBandTest, AJunctionAlreadyAtTheBandsMiddleIsTold) {
  // The same polished floor, the junction found where the baseboard meets its reflection: the band
  // lies about it. At the reflection's lower edge, or on a matte floor, it does not.
  const cv::Mat polished = PolishedBand(true, kTop, kJunction, kBottom);
  const cv::Mat matte = DrawByAngle(true, [&](double angle) {
    if (angle < kTop) return Blend(kWall, kWall, 0);
    if (angle < kJunction) return Blend(kBoard, kBoard, 0);
    return Blend(kMatte, kMatte, 0);
  });
  EXPECT_TRUE(JunctionAtReflectedBandsMiddle(polished, LineAt(kJunction, true), kVp, true, 12.0));
  EXPECT_FALSE(JunctionAtReflectedBandsMiddle(polished, LineAt(kBottom, true), kVp, true, 12.0));
  EXPECT_FALSE(JunctionAtReflectedBandsMiddle(matte, LineAt(kJunction, true), kVp, true, 12.0));
}

TEST(ReflectedBandTest, FromATopABandUnder4PercentOfTheCamerasHeightIsNoBaseboard) {
  // The same 1.8-degree band of baseboard and reflection below a line 30 degrees below the
  // horizontal is a baseboard 3.6% of the camera's height (1 - tan 30 / tan 30.9, by hand); below
  // a line 10 degrees below it, 8.5% (1 - tan 10 / tan 10.9).
  for (const double top : {30.0, 10.0}) {
    const double bottom = top + 1.8;
    const double junction =
        std::atan(0.5 * (std::tan(top * kDeg) + std::tan(bottom * kDeg))) / kDeg;
    const cv::Mat image = PolishedBand(true, top, junction, bottom);
    double turn = 0;
    const bool found = FindJunctionBelowBandTop(image, LineAt(top, true), kVp, true, 12.0, &turn);
    if (top == 30.0) {
      EXPECT_FALSE(found);
    } else {
      ASSERT_TRUE(found);
      EXPECT_NEAR(turn, junction - top, 0.15);
    }
  }
}

TEST(ReflectedBandTest, ABaseboardAboveATrueJunctionIsLeftAlone) {
  // The same band on a matte floor is a baseboard from 30 to 38 degrees, all one colour.
  const cv::Mat image = DrawByAngle(true, [&](double angle) {
    if (angle < kTop) return Blend(kWall, kWall, 0);
    if (angle < kBottom) return Blend(kBoard, kBoard, 0);
    return Blend(kMatte, kMatte, 0);
  });
  double turn = 0;
  EXPECT_FALSE(FindReflectedJunction(image, LineAt(kBottom, true), kVp, true, 12.0, &turn));
  // Nor, from its top, a baseboard over a reflection.
  EXPECT_FALSE(FindJunctionBelowBandTop(image, LineAt(kTop, true), kVp, true, 12.0, &turn));
}

TEST(ReflectedBandTest, ALowerPartThatIsNoBlendIsNoReflection) {
  // A band split at the middle, its lower part green: no blend of the baseboard and the floor.
  const cv::Mat image = DrawByAngle(false, [&](double angle) {
    if (angle < kTop) return Blend(kWall, kWall, 0);
    if (angle < kJunction) return Blend(kBoard, kBoard, 0);
    if (angle < kBottom) return cv::Vec3b(40, 160, 40);
    return Blend(kMatte, kWall, 0.4);
  });
  double turn = 0;
  EXPECT_FALSE(FindReflectedJunction(image, LineAt(kBottom, false), kVp, false, 12.0, &turn));
  EXPECT_FALSE(FindJunctionBelowBandTop(image, LineAt(kTop, false), kVp, false, 12.0, &turn));
}

TEST(ReflectedBandTest, RefusesWhatItCannotLookAt) {
  const cv::Mat image(480, 640, CV_8UC3, cv::Scalar(0, 0, 0));
  const JunctionLine line = LineAt(kBottom, true);
  double turn = 0;
  EXPECT_FALSE(FindReflectedJunction(cv::Mat(), line, kVp, true, 12.0, &turn));
  EXPECT_FALSE(FindJunctionBelowBandTop(cv::Mat(), line, kVp, true, 12.0, &turn));
  EXPECT_FALSE(FindReflectedJunction(cv::Mat(480, 640, CV_8UC1), line, kVp, true, 12.0, &turn));
  EXPECT_FALSE(FindReflectedJunction(image, line, Eigen::Vector2d(NAN, 0), true, 12.0, &turn));
  EXPECT_FALSE(FindReflectedJunction(image, line, kVp, true, 0.0, &turn));
  EXPECT_FALSE(FindReflectedJunction(image, line, kVp, true, 12.0, &turn));  // No band at all.
}

}  // namespace
}  // namespace corridor
