#pragma once

#include <cstdint>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace corridor {
namespace testing_util {

// An outdoor scene, not a corridor: a 320x240 sky (blue, lighter toward a horizon at row 100)
// over green ground, with 25 filled ellipses of random colours (bushes, stones, cars) on and
// near the ground. Blob outlines give straight-ish Hough segments in every direction, and two of
// them can meet like a corridor's junctions.
inline cv::Mat OutdoorScene(uint64_t seed) {
  constexpr int kWidth = 320, kHeight = 240, kHorizon = 100;
  cv::Mat image(kHeight, kWidth, CV_8UC3);
  for (int v = 0; v < kHorizon; ++v) {
    image.row(v).setTo(cv::Scalar(255, 160 + v / 2, 120 + v));
  }
  image.rowRange(kHorizon, kHeight).setTo(cv::Scalar(50, 140, 60));
  cv::RNG rng(seed);
  for (int k = 0; k < 25; ++k) {
    const cv::Point centre(rng.uniform(0, kWidth + 1), rng.uniform(60, kHeight + 1));
    const cv::Size axes(rng.uniform(5, 41), rng.uniform(5, 31));
    const cv::Scalar colour(rng.uniform(0, 256), rng.uniform(0, 256), rng.uniform(0, 256));
    cv::ellipse(image, centre, axes, 0, 0, 360, colour, cv::FILLED);
  }
  return image;
}

}  // namespace testing_util
}  // namespace corridor
