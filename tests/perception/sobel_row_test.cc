#include "kernels/sobel_row.h"

#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace corridor {
namespace {

// cv::Sobel (dx = 1, 3x3) of a three-row plane is the reference on its middle row's interior.
TEST(SobelXRowTest, MatchesCvSobelAndItsThresholdOnRandomRows) {
  cv::RNG rng(11);
  for (int cols = 3; cols <= 70; ++cols) {
    cv::Mat plane(3, cols, CV_8UC1);
    // Uniform bytes, and only 0 and 255 (the largest gradients, +-1020).
    rng.fill(plane, cv::RNG::UNIFORM, 0, 256);
    if (cols % 2 == 0) plane = (plane > 127);
    cv::Mat sobel;
    cv::Sobel(plane, sobel, CV_16S, 1, 0, 3);
    const int begin = 1 + cols % 3 % (cols - 2), end = cols - 1 - (cols % 5 == 0 ? 1 : 0);
    for (int threshold : {-5, 0, 1, 100, 1020, 1021, 5000}) {
      std::vector<int16_t> g(cols, 7);
      std::vector<uint8_t> strong(cols, 7);
      SobelXRow(plane.ptr<uint8_t>(0), plane.ptr<uint8_t>(1), plane.ptr<uint8_t>(2), begin, end,
                threshold, g.data(), strong.data());
      for (int x = 0; x < cols; ++x) {
        if (x < begin || x >= end) {  // Outside the range: not written.
          EXPECT_EQ(g[x], 7);
          EXPECT_EQ(strong[x], 7);
          continue;
        }
        const int expected = sobel.at<int16_t>(1, x);
        ASSERT_EQ(g[x], expected) << cols << " columns, x " << x;
        ASSERT_EQ(strong[x] != 0, std::abs(expected) >= threshold)
            << cols << " columns, x " << x << ", threshold " << threshold;
      }
    }
  }
}

}  // namespace
}  // namespace corridor
