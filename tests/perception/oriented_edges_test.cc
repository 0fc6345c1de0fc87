#include "perception/oriented_edges.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

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
  // Line directions in pixels (OrientedLineHits): larger integers, sampled.
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
  EXPECT_EQ(OrientationBin(-5, 0), 7);      // 180 degrees: the last bin.
  EXPECT_EQ(OrientationBin(0, -3), 4);      // -90 degrees is 90.
  EXPECT_EQ(OrientationBin(-100, -41), 0);  // -157.6 degrees is 22.4.
}

// A band cut from edges computed once over the whole image holds exactly those edges, and each
// edge's orientation bit (from the shared gradient) within 1 px.
TEST(OrientedEdgesTest, BandFromSharedImageEdges) {
  cv::Mat image(120, 160, CV_8UC3, cv::Scalar(90, 100, 110));
  cv::rectangle(image, cv::Rect(40, 30, 60, 50), cv::Scalar(200, 180, 40), cv::FILLED);
  cv::line(image, cv::Point(0, 110), cv::Point(159, 60), cv::Scalar(20, 20, 200), 3);
  ImageEdges shared;
  ASSERT_TRUE(ComputeImageEdges(image, &shared));
  ASSERT_TRUE(shared.Fits(image));
  EXPECT_GT(cv::countNonZero(shared.edges), 200);
  const OrientedEdges band = ComputeOrientedEdges(image, 25, 90, &shared);
  ASSERT_EQ(band.top, 25);
  ASSERT_EQ(band.edges.rows, 65);
  EXPECT_EQ(cv::norm(band.edges, shared.edges.rowRange(25, 90), cv::NORM_INF), 0.0);
  int checked = 0;
  for (int v = 1; v + 1 < band.edges.rows; ++v) {
    for (int u = 1; u + 1 < band.edges.cols; ++u) {
      if (band.edges.at<uchar>(v, u) == 0) continue;
      const int bin = OrientationBin(shared.dx.at<short>(v + 25, u), shared.dy.at<short>(v + 25, u));
      for (int dv = -1; dv <= 1; ++dv) {
        for (int du = -1; du <= 1; ++du) {
          ASSERT_NE(band.near.at<uchar>(v + dv, u + du) & (1 << bin), 0) << u << ", " << v;
        }
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
  // And nothing else: each pixel's bits are exactly those of the edges around it in the band.
  int mismatches = 0;
  for (int v = 0; v < band.edges.rows; ++v) {
    for (int u = 0; u < band.edges.cols; ++u) {
      int expected = 0;
      for (int dv = -1; dv <= 1; ++dv) {
        for (int du = -1; du <= 1; ++du) {
          const int vv = v + dv, uu = u + du;
          if (vv < 0 || vv >= band.edges.rows || uu < 0 || uu >= band.edges.cols) continue;
          if (band.edges.at<uchar>(vv, uu) == 0) continue;
          expected |= 1 << OrientationBin(shared.dx.at<short>(vv + 25, uu),
                                          shared.dy.at<short>(vv + 25, uu));
        }
      }
      if (band.near.at<uchar>(v, u) != expected) ++mismatches;
    }
  }
  EXPECT_EQ(mismatches, 0);
  // As a cache: edges of another image size are replaced by the image's rows from the top down
  // to a little below the band; a later band inside them reuses them, one below them refills.
  ImageEdges cache;
  ASSERT_TRUE(ComputeImageEdges(image.colRange(0, 80), &cache));
  EXPECT_FALSE(cache.Fits(image));
  const OrientedEdges first = ComputeOrientedEdges(image, 25, 60, &cache);
  ASSERT_EQ(cache.edges.cols, image.cols);
  EXPECT_GE(cache.edges.rows, 60 + 8);
  EXPECT_LT(cache.edges.rows, image.rows);
  EXPECT_TRUE(cache.Covers(image, 60));
  EXPECT_FALSE(cache.Fits(image));
  EXPECT_EQ(cv::norm(first.edges, shared.edges.rowRange(25, 60), cv::NORM_INF), 0.0);
  const uchar* kept = cache.edges.data;
  const OrientedEdges inside = ComputeOrientedEdges(image, 10, 62, &cache);
  EXPECT_EQ(cache.edges.data, kept);
  EXPECT_EQ(cv::norm(inside.edges, shared.edges.rowRange(10, 62), cv::NORM_INF), 0.0);
  ComputeOrientedEdges(image, 25, 110, &cache);
  EXPECT_TRUE(cache.Fits(image));
  ImageEdges other;
  EXPECT_FALSE(ComputeImageEdges(cv::Mat(), &other));
  EXPECT_FALSE(ComputeImageEdges(cv::Mat(10, 10, CV_32FC3, cv::Scalar(0, 0, 0)), &other));
}

// A cache extended down to a lower band holds what a cache filled for that band at once holds:
// the same blurred rows, gradients and edges (the rows it had are not blurred again, nor their
// gradients taken again, but Canny runs over all rows). Views cut from it before stay as they
// were. A textured image, so that hysteresis chains cross the rows where the two fills meet.
TEST(OrientedEdgesTest, ExtendedCacheIsTheCacheFilledAtOnce) {
  cv::Mat image(240, 200, CV_8UC3);
  cv::RNG(5).fill(image, cv::RNG::UNIFORM, 60, 190);
  cv::GaussianBlur(image, image, cv::Size(0, 0), 2.0);
  for (int k = 0; k < 12; ++k) {
    cv::line(image, cv::Point(7 * k, 0), cv::Point(199 - 5 * k, 239),
             cv::Scalar(20 * k, 240 - 15 * k, 90), 2);
  }
  int compared = 0;
  for (const int first_bottom : {40, 90, 150}) {
    for (const int second_bottom : {first_bottom + 3, first_bottom + 40, 239}) {
      ImageEdges extended;
      const OrientedEdges before = ComputeOrientedEdges(image, 5, first_bottom, &extended);
      const cv::Mat kept = before.edges.clone();
      const int had = extended.edges.rows;
      ComputeOrientedEdges(image, 5, second_bottom, &extended);
      ImageEdges at_once;
      ComputeOrientedEdges(image, 5, second_bottom, &at_once);
      const std::string where =
          std::to_string(first_bottom) + " then " + std::to_string(second_bottom);
      if (extended.edges.rows == had) continue;  // Covered already.
      ASSERT_EQ(extended.edges.size(), at_once.edges.size()) << where;
      EXPECT_EQ(cv::norm(extended.smooth, at_once.smooth, cv::NORM_INF), 0.0) << where;
      EXPECT_EQ(cv::norm(extended.dx, at_once.dx, cv::NORM_INF), 0.0) << where;
      EXPECT_EQ(cv::norm(extended.dy, at_once.dy, cv::NORM_INF), 0.0) << where;
      EXPECT_EQ(cv::norm(extended.edges, at_once.edges, cv::NORM_INF), 0.0) << where;
      EXPECT_EQ(extended.image_rows, image.rows);
      EXPECT_EQ(cv::norm(before.edges, kept, cv::NORM_INF), 0.0) << where;
      EXPECT_GT(cv::countNonZero(at_once.edges), 500) << where;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 6);
}

// A horizontal edge (a dark lower half): samples along it hit, those beside it or across it
// (a vertical line through it) do not; Fraction divides by at least `at_least`, and gives 0
// below 8 visible samples. Counts by hand.
TEST(OrientedEdgesTest, LineHitsCountTheSamplesOnEdgesAlongTheLine) {
  cv::Mat image(60, 100, CV_8UC3, cv::Scalar(200, 200, 200));
  image.rowRange(30, 60).setTo(cv::Scalar(40, 40, 40));
  const OrientedEdges edges = ComputeOrientedEdges(image, 10, 50);
  std::vector<cv::Point> along, beside, across;
  for (int i = 0; i < 40; ++i) {
    along.emplace_back(10 + 2 * i, 30);
    beside.emplace_back(10 + 2 * i, 20);
    across.emplace_back(50, 11 + i);
  }
  along[5] = cv::Point(-1, -1);  // Not visible.
  const LineHits on = OrientedLineHits(along.data(), 40, edges);
  EXPECT_EQ(on.visible, 39);
  EXPECT_EQ(on.hits, 39);
  EXPECT_DOUBLE_EQ(on.Fraction(20), 1.0);
  EXPECT_DOUBLE_EQ(on.Fraction(78), 0.5);
  EXPECT_EQ(OrientedLineHits(beside.data(), 40, edges).hits, 0);
  // The vertical line crosses the edge: at most its samples within 1 px of row 30, which run
  // across the edge, not along it.
  EXPECT_EQ(OrientedLineHits(across.data(), 40, edges).hits, 0);
  const LineHits few = OrientedLineHits(along.data(), 7, edges);
  EXPECT_EQ(few.visible, 6);
  EXPECT_EQ(few.Fraction(1), 0.0);
}

}  // namespace
}  // namespace corridor
