// ForEachEdgePixel against cv::findNonZero (row-major, the same order) on sparse and dense maps
// of any non-zero values, widths that are and are not multiples of eight; NonZeroBytes by hand.
#include "kernels/edge_scan.h"

#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

namespace corridor {
namespace {

TEST(EdgeScanTest, VisitsWhatFindNonZeroFinds) {
  cv::RNG rng(23);
  int visited_total = 0;
  for (const cv::Size size : {cv::Size(64, 9), cv::Size(61, 7), cv::Size(5, 3), cv::Size(8, 1),
                              cv::Size(1, 4)}) {
    for (const double density : {0.0, 0.03, 0.5, 1.0}) {
      cv::Mat edges(size, CV_8U, cv::Scalar(0));
      for (int v = 0; v < size.height; ++v) {
        for (int u = 0; u < size.width; ++u) {
          if (rng.uniform(0.0, 1.0) < density) edges.at<uchar>(v, u) = rng.uniform(1, 256);
        }
      }
      std::vector<cv::Point> expected, visited;
      if (cv::countNonZero(edges) > 0) cv::findNonZero(edges, expected);
      ForEachEdgePixel(edges, [&](int u, int v) { visited.emplace_back(u, v); });
      EXPECT_EQ(visited, expected) << size << " density " << density;
      visited_total += static_cast<int>(visited.size());
    }
  }
  EXPECT_GT(visited_total, 500);
}

TEST(EdgeScanTest, NonZeroBytesMarksEachNonZeroByteInItsLowestBit) {
  EXPECT_EQ(NonZeroBytes(0), 0u);
  EXPECT_EQ(NonZeroBytes(0xff00000000000080ULL), 0x0100000000000001ULL);
  EXPECT_EQ(NonZeroBytes(0x0001020408102040ULL), 0x0001010101010101ULL);
  EXPECT_EQ(NonZeroBytes(~0ULL), 0x0101010101010101ULL);
}

}  // namespace
}  // namespace corridor
