// FloorMirrorsLights on drawn corridors: walls and a floor between two junction lines through a
// vanishing point, with bright patches (mirrored lights) on the floor or on the walls.
#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "perception/floor_lights.h"

namespace corridor {
namespace {

const Eigen::Vector2d kVp(320, 200);

Eigen::Vector3d Through(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.homogeneous().cross(b.homogeneous());
}

// Walls of grey 140 (every third column 170, their brightest), a floor of grey 90 between
// the lines from the vanishing point to the bottom corners.
cv::Mat Corridor() {
  cv::Mat image(480, 640, CV_8UC3, cv::Scalar(140, 140, 140));
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; u += 3) image.at<cv::Vec3b>(v, u) = cv::Vec3b(170, 170, 170);
  }
  const cv::Point floor[3] = {cv::Point(320, 200), cv::Point(639, 479), cv::Point(0, 479)};
  cv::fillConvexPoly(image, floor, 3, cv::Scalar(90, 90, 90));
  return image;
}

const Eigen::Vector3d kLeft = Through(kVp, Eigen::Vector2d(0, 479));
const Eigen::Vector3d kRight = Through(kVp, Eigen::Vector2d(639, 479));

TEST(FloorLightsTest, AFloorShowingTheLightsMirrorsThem) {
  cv::Mat image = Corridor();
  // Three mirrored lights down the floor's middle: 3 * 40 * 20 px of about 50000 floor px.
  for (const int v : {300, 360, 420}) {
    cv::rectangle(image, cv::Rect(300, v, 40, 20), cv::Scalar(200, 200, 200), cv::FILLED);
  }
  EXPECT_TRUE(FloorMirrorsLights(image, kLeft, kRight, kVp, 0.005));
  // Asked for more of the floor than the lights cover, it says no.
  EXPECT_FALSE(FloorMirrorsLights(image, kLeft, kRight, kVp, 0.1));
}

TEST(FloorLightsTest, ADiffuseFloorOrBrightWallsMirrorNothing) {
  cv::Mat image = Corridor();
  EXPECT_FALSE(FloorMirrorsLights(image, kLeft, kRight, kVp, 0.005));
  // A lit door on the wall, brighter than any floor pixel, is the walls' own.
  cv::rectangle(image, cv::Rect(20, 220, 60, 150), cv::Scalar(230, 230, 230), cv::FILLED);
  EXPECT_FALSE(FloorMirrorsLights(image, kLeft, kRight, kVp, 0.005));
  // Patches on the floor no brighter than the walls' brightest are no lights.
  for (const int v : {300, 360, 420}) {
    cv::rectangle(image, cv::Rect(300, v, 40, 20), cv::Scalar(160, 160, 160), cv::FILLED);
  }
  EXPECT_FALSE(FloorMirrorsLights(image, kLeft, kRight, kVp, 0.005));
}

TEST(FloorLightsTest, RefusesWhatItCannotLookAt) {
  EXPECT_FALSE(FloorMirrorsLights(cv::Mat(), kLeft, kRight, kVp, 0.005));
  EXPECT_FALSE(FloorMirrorsLights(cv::Mat(480, 640, CV_8UC1), kLeft, kRight, kVp, 0.005));
  EXPECT_FALSE(FloorMirrorsLights(Corridor(), kLeft, kRight, Eigen::Vector2d(NAN, 0), 0.005));
}

}  // namespace
}  // namespace corridor
