#pragma once

// Test helpers of the rasteriser tests: random cameras and corridors, and the comparison of a
// depth image with its no-estimate pixels marked NaN against the plain one.

#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "box_truth.h"

namespace corridor {
namespace testing {

// The largest random view drawn: image size, focal length, yaw and pitch.
struct RandomViewLimits {
  int max_width = 400, max_height = 300;
  double max_focal = 800;
  double max_yaw = 0.6, max_pitch = 0.6;  // Pitch from -0.4 up to max_pitch.
};

// A camera of random size (from 8 px), focal length (from 50 px) and principal point, and a
// corridor of random yaw, pitch, width (1-4 m) and offset (within 0.4 of the width) with a
// random ceiling (1-4 m) when `ceiling`.
inline void RandomView(cv::RNG* rng, const RandomViewLimits& limits, bool ceiling, Camera* camera,
                       CorridorGeometry* g) {
  *camera = TestCamera();
  camera->image_width = rng->uniform(8, limits.max_width);
  camera->image_height = rng->uniform(8, limits.max_height);
  camera->fx = camera->fy = rng->uniform(50.0, limits.max_focal);
  camera->cx = rng->uniform(0.0, 1.0) * camera->image_width;
  camera->cy = rng->uniform(0.0, 1.0) * camera->image_height;
  const double width = rng->uniform(1.0, 4.0);
  *g = TestGeometry(rng->uniform(-limits.max_yaw, limits.max_yaw),
                    rng->uniform(-0.4, limits.max_pitch), rng->uniform(-0.4, 0.4) * width, width,
                    ceiling ? rng->uniform(1.0, 4.0) : 0.0);
}

// `marked` is `plain` with NaN wherever `plain` is not positive, bit for bit (a failure names the
// first pixel that differs); the number of NaNs.
inline int ExpectNaNWhereNotPositive(const cv::Mat& plain, const cv::Mat& marked) {
  EXPECT_EQ(marked.size(), plain.size());
  if (marked.size() != plain.size()) return 0;
  int nans = 0;
  for (int v = 0; v < plain.rows; ++v) {
    for (int u = 0; u < plain.cols; ++u) {
      const float z = plain.at<float>(v, u), got = marked.at<float>(v, u);
      const bool same = z > 0 ? got == z : std::isnan(got);
      if (!same) {
        ADD_FAILURE() << "at " << u << "," << v << ": " << got << " for " << z;
        return nans;
      }
      nans += z > 0 ? 0 : 1;
    }
  }
  return nans;
}

}  // namespace testing
}  // namespace corridor
