// FastAtan2 against cv::fastAtan2 itself: every gradient a 3x3 Sobel of 8-bit pixels can give
// (|gx|, |gy| <= 1020, both signs), and random floats of any size.
#include "kernels/fast_atan2.h"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

namespace corridor {
namespace {

TEST(FastAtan2Test, EqualsOpenCvsForEverySobelGradient) {
  long mismatches = 0;
  for (int gy = -1020; gy <= 1020; ++gy) {
    for (int gx = -1020; gx <= 1020; ++gx) {
      const float y = static_cast<float>(gy), x = static_cast<float>(gx);
      mismatches += FastAtan2(y, x) != cv::fastAtan2(y, x);
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(FastAtan2Test, EqualsOpenCvsForRandomFloats) {
  cv::RNG rng(9);
  for (int k = 0; k < 100000; ++k) {
    const float y = static_cast<float>(rng.uniform(-1e4, 1e4));
    const float x = static_cast<float>(rng.uniform(-1e4, 1e4));
    ASSERT_EQ(FastAtan2(y, x), cv::fastAtan2(y, x)) << x << ", " << y;
  }
}

}  // namespace
}  // namespace corridor
