// MarkNoEstimateNaN against a per-pixel rule written out here: positive depths stay, zero,
// negative and NaN become NaN; on widths that leave a tail after whole vector steps and on a
// region that is not continuous in memory.
#include "depth/no_estimate.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

namespace corridor {
namespace {

float Pattern(int v, int u) {
  switch ((7 * v + 3 * u) % 5) {
    case 0:
      return 0.0f;
    case 1:
      return -1.5f;
    case 2:
      return std::numeric_limits<float>::quiet_NaN();
    case 3:
      return 1e-30f;  // Tiny but positive: a depth.
    default:
      return 0.25f * static_cast<float>(u + 1);
  }
}

void ExpectMarked(const cv::Mat& depth) {
  for (int v = 0; v < depth.rows; ++v) {
    for (int u = 0; u < depth.cols; ++u) {
      const float before = Pattern(v, u), after = depth.at<float>(v, u);
      if (before > 0) {
        EXPECT_EQ(after, before) << v << "," << u;
      } else {
        EXPECT_TRUE(std::isnan(after)) << v << "," << u;
      }
    }
  }
}

cv::Mat Filled(int rows, int cols) {
  cv::Mat depth(rows, cols, CV_32F);
  for (int v = 0; v < rows; ++v) {
    for (int u = 0; u < cols; ++u) depth.at<float>(v, u) = Pattern(v, u);
  }
  return depth;
}

TEST(MarkNoEstimateNaN, EveryPixelByTheRule) {
  for (int cols : {1, 7, 8, 9, 17, 31}) {
    cv::Mat depth = Filled(5, cols);
    MarkNoEstimateNaN(&depth);
    ExpectMarked(depth);
  }
}

TEST(MarkNoEstimateNaN, RegionOfALargerImage) {
  cv::Mat whole(9, 40, CV_32F, cv::Scalar(-2.0f));
  cv::Mat region = whole(cv::Rect(3, 2, 19, 6));
  Filled(6, 19).copyTo(region);
  MarkNoEstimateNaN(&region);
  ExpectMarked(region);
  // Outside the region nothing changed.
  EXPECT_EQ(whole.at<float>(0, 0), -2.0f);
  EXPECT_EQ(whole.at<float>(2, 2), -2.0f);
  EXPECT_EQ(whole.at<float>(2, 22), -2.0f);
  EXPECT_EQ(whole.at<float>(8, 39), -2.0f);
}

}  // namespace
}  // namespace corridor
