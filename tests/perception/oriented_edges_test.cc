#include "perception/oriented_edges.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace corridor {
namespace {

// The definition: atan2's angle taken into [0, pi] (an edge and its reverse are one edge), in
// eighths of pi, the last bin closed.
int BinByAtan2(double gx, double gy) {
  double angle = std::atan2(gy, gx);
  if (angle < 0) angle += M_PI;
  return std::min(kOrientationBins - 1, static_cast<int>(angle / M_PI * kOrientationBins));
}

// Every gradient a colour Sobel of 8-bit pixels can give (|g| <= 4 * 255), and beyond.
TEST(OrientedEdgesTest, OrientationBinIsAtan2sBinForEverySobelGradient) {
  long mismatches = 0;
  for (int gx = -1100; gx <= 1100; ++gx) {
    for (int gy = -1100; gy <= 1100; ++gy) {
      mismatches += OrientationBin(gx, gy) != BinByAtan2(gx, gy);
    }
  }
  EXPECT_EQ(mismatches, 0);
  // Line directions in pixels (OrientedLineSupport): larger integers, sampled.
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coordinate(-20000, 20000);
  for (int i = 0; i < 200000; ++i) {
    const int gx = coordinate(rng), gy = coordinate(rng);
    ASSERT_EQ(OrientationBin(gx, gy), BinByAtan2(gx, gy)) << gx << ", " << gy;
  }
}

// The bin edges by hand: 0, 45, 90, 135 and 180 degrees, and just either side of 22.5 degrees
// (tan 22.5 deg = 0.41421...: 41 / 100 below it, 42 / 100 above).
TEST(OrientedEdgesTest, OrientationBinEdges) {
  EXPECT_EQ(OrientationBin(0, 0), 0);
  EXPECT_EQ(OrientationBin(5, 0), 0);
  EXPECT_EQ(OrientationBin(100, 41), 0);
  EXPECT_EQ(OrientationBin(100, 42), 1);
  EXPECT_EQ(OrientationBin(7, 7), 2);
  EXPECT_EQ(OrientationBin(0, 3), 4);
  EXPECT_EQ(OrientationBin(-7, 7), 6);
  EXPECT_EQ(OrientationBin(-5, 0), 7);  // 180 degrees: the last bin.
  EXPECT_EQ(OrientationBin(0, -3), 4);  // -90 degrees is 90.
  EXPECT_EQ(OrientationBin(-100, -41), 0);  // -157.6 degrees is 22.4.
}

}  // namespace
}  // namespace corridor
