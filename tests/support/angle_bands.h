#pragma once

// Images of bands seen from a vanishing point: every pixel below it, on one half, takes the colour
// of its angle below the horizontal. The band tests of the baseboard's foot and of a polished
// floor's reflection draw their walls, baseboards and floors with them.

#include <cmath>
#include <random>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace corridor {
namespace testing_util {

inline constexpr double kBandDeg = M_PI / 180.0;
inline const Eigen::Vector2d kBandVp(320, 180);  // The vanishing point of the drawn images.

// The direction from kBandVp of a left (right) line `angle_deg` below the horizontal.
inline Eigen::Vector2d BandDown(double angle_deg, bool left) {
  return Eigen::Vector2d((left ? -1 : 1) * std::cos(angle_deg * kBandDeg),
                         std::sin(angle_deg * kBandDeg));
}

// A 640x480 image whose pixels below kBandVp on the `left` (or right) half are
// `colour(angle_deg, rng)`, the rest light grey; `rng` is seeded alike for every image.
template <typename Colour>
cv::Mat DrawByAngle(bool left, Colour colour) {
  cv::Mat image(480, 640, CV_8UC3, cv::Scalar(200, 200, 200));
  std::mt19937 rng(7);
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      const double dx = (u - kBandVp.x()) * (left ? -1 : 1), dy = v - kBandVp.y();
      if (dy <= 0 || dx <= 0) continue;
      image.at<cv::Vec3b>(v, u) = colour(std::atan2(dy, dx) / kBandDeg, rng);
    }
  }
  return image;
}

}  // namespace testing_util
}  // namespace corridor
