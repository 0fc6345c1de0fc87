#include "kernels/color_gradient.h"

#include <random>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace corridor {
namespace {

// The reference: cv::Sobel on each channel taken on its own, and the first channel with the
// largest |dx| + |dy| chosen pixel by pixel.
void ReferenceGradient(const cv::Mat& image, cv::Mat* dx, cv::Mat* dy) {
  std::vector<cv::Mat> channels;
  cv::split(image, channels);
  *dx = cv::Mat(image.size(), CV_16S);
  *dy = cv::Mat(image.size(), CV_16S);
  std::vector<cv::Mat> gx(channels.size()), gy(channels.size());
  for (size_t c = 0; c < channels.size(); ++c) {
    cv::Sobel(channels[c], gx[c], CV_16S, 1, 0, 3);
    cv::Sobel(channels[c], gy[c], CV_16S, 0, 1, 3);
  }
  for (int r = 0; r < image.rows; ++r) {
    for (int u = 0; u < image.cols; ++u) {
      int best = -1;
      for (size_t c = 0; c < channels.size(); ++c) {
        const int m = std::abs(gx[c].at<short>(r, u)) + std::abs(gy[c].at<short>(r, u));
        if (m > best) {
          best = m;
          dx->at<short>(r, u) = gx[c].at<short>(r, u);
          dy->at<short>(r, u) = gy[c].at<short>(r, u);
        }
      }
    }
  }
}

cv::Mat RandomImage(int rows, int cols, int type, uint32_t seed) {
  cv::Mat image(rows, cols, type);
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::UNIFORM, 0, 256);
  return image;
}

void ExpectSameGradient(const cv::Mat& image) {
  cv::Mat dx, dy, ref_dx, ref_dy;
  std::vector<int> histogram;
  ColorGradient(image, &dx, &dy, &histogram);
  ReferenceGradient(image, &ref_dx, &ref_dy);
  ASSERT_EQ(dx.type(), CV_16S);
  EXPECT_EQ(cv::countNonZero(dx != ref_dx), 0) << image.cols << "x" << image.rows;
  EXPECT_EQ(cv::countNonZero(dy != ref_dy), 0) << image.cols << "x" << image.rows;
  std::vector<int> ref_histogram(kGradientBins, 0);
  for (int r = 0; r < image.rows; ++r) {
    for (int u = 0; u < image.cols; ++u) {
      ++ref_histogram[std::abs(ref_dx.at<short>(r, u)) + std::abs(ref_dy.at<short>(r, u))];
    }
  }
  EXPECT_EQ(histogram, ref_histogram);
}

TEST(ColorGradientTest, MatchesSobelPerChannelOnNoiseAndEveryBorder) {
  ExpectSameGradient(RandomImage(37, 53, CV_8UC3, 1));
  ExpectSameGradient(RandomImage(2, 5, CV_8UC3, 2));    // Two rows: both borders reflect.
  ExpectSameGradient(RandomImage(1, 1, CV_8UC3, 3));    // One pixel.
  ExpectSameGradient(RandomImage(9, 1, CV_8UC3, 4));    // One column.
  ExpectSameGradient(RandomImage(16, 16, CV_8UC4, 5));  // Four channels.
  ExpectSameGradient(RandomImage(20, 30, CV_8UC1, 6));  // Grey.
  // The rows are split into planes three at a time: three rows, two channels, and rows wide
  // enough for the vector loops and their tails.
  ExpectSameGradient(RandomImage(3, 70, CV_8UC3, 9));
  ExpectSameGradient(RandomImage(11, 67, CV_8UC2, 10));
  ExpectSameGradient(RandomImage(5, 130, CV_8UC4, 11));
}

// Three grey levels: channels of equal |dx| + |dy| but different derivatives at many pixels,
// where the first channel must be the one chosen.
TEST(ColorGradientTest, TiesGoToTheFirstChannel) {
  for (const int type : {CV_8UC2, CV_8UC3, CV_8UC4}) {
    cv::Mat image(9, 77, type);
    cv::RNG(21).fill(image, cv::RNG::UNIFORM, 0, 3);
    ExpectSameGradient(image);
  }
}

TEST(ColorGradientTest, AViewIsTakenOnItsOwnLikeACopy) {
  const cv::Mat image = RandomImage(60, 40, CV_8UC3, 7);
  const cv::Mat view = image.rowRange(20, 60);
  cv::Mat dx, dy, copy_dx, copy_dy;
  ColorGradient(view, &dx, &dy, nullptr);
  ColorGradient(view.clone(), &copy_dx, &copy_dy, nullptr);
  EXPECT_EQ(cv::countNonZero(dx != copy_dx), 0);
  EXPECT_EQ(cv::countNonZero(dy != copy_dy), 0);
}

TEST(ColorGradientTest, ChoosesTheChannelWithTheStrongerEdge) {
  // Blue steps weakly, red strongly at the same column: red's derivative wins.
  cv::Mat image(10, 10, CV_8UC3, cv::Scalar(100, 100, 100));
  image.colRange(5, 10).setTo(cv::Scalar(110, 100, 200));
  cv::Mat dx, dy;
  ColorGradient(image, &dx, &dy, nullptr);
  EXPECT_EQ(dx.at<short>(5, 5), 4 * 100);  // Sobel of a 100-level step: 1 + 2 + 1 times 100.
  EXPECT_EQ(dy.at<short>(5, 5), 0);
}

TEST(ColorGradientTest, FloatImagesTakeTheOpenCvPath) {
  cv::Mat image;
  RandomImage(12, 14, CV_8UC3, 8).convertTo(image, CV_32FC3);
  cv::Mat dx, dy, ref_dx, ref_dy;
  std::vector<int> histogram;
  ColorGradient(image, &dx, &dy, &histogram);
  ReferenceGradient(image, &ref_dx, &ref_dy);
  EXPECT_EQ(cv::countNonZero(dx != ref_dx), 0);
  EXPECT_EQ(cv::countNonZero(dy != ref_dy), 0);
  EXPECT_EQ(histogram.size(), static_cast<size_t>(kGradientBins));
}

// With a floor F the bins from F on are the reference's (from cv::Sobel per channel), bin F - 1
// holds every smaller value, the ones below it nothing; so every percentile at least F is the
// reference's and the smaller ones come out as F - 1. Widths with and without vector tails.
TEST(ColorGradientTest, HistogramWithAFloor) {
  for (const int cols : {7, 8, 37, 70}) {
    const cv::Mat image = RandomImage(13, cols, CV_8UC3, 20 + cols);
    cv::Mat ref_dx, ref_dy;
    ReferenceGradient(image, &ref_dx, &ref_dy);
    std::vector<int> reference(kGradientBins, 0);
    for (int r = 0; r < image.rows; ++r) {
      for (int u = 0; u < image.cols; ++u) {
        ++reference[std::abs(ref_dx.at<short>(r, u)) + std::abs(ref_dy.at<short>(r, u))];
      }
    }
    for (const int floor : {1, 40, 400, 900}) {
      cv::Mat dx, dy;
      std::vector<int> histogram;
      ColorGradient(image, &dx, &dy, &histogram, floor);
      ASSERT_EQ(histogram.size(), static_cast<size_t>(kGradientBins));
      int below = 0;
      for (int m = 0; m < floor; ++m) below += reference[m];
      for (int m = 0; m + 1 < floor; ++m) EXPECT_EQ(histogram[m], 0) << cols << " " << floor;
      EXPECT_EQ(histogram[floor - 1], below) << cols << " " << floor;
      for (int m = floor; m < kGradientBins; ++m) {
        EXPECT_EQ(histogram[m], reference[m]) << cols << " " << floor << " " << m;
      }
      const double total = static_cast<double>(image.total());
      for (const double p : {10.0, 50.0, 90.0, 99.0}) {
        const double exact = HistogramPercentile(reference, total, p);
        EXPECT_EQ(HistogramPercentile(histogram, total, p), exact >= floor ? exact : floor - 1);
      }
    }
  }
}

TEST(ColorGradientTest, HistogramPercentile) {
  std::vector<int> histogram(kGradientBins, 0);
  histogram[10] = 50;
  histogram[20] = 40;
  histogram[30] = 10;
  EXPECT_EQ(HistogramPercentile(histogram, 100, 50), 10);
  EXPECT_EQ(HistogramPercentile(histogram, 100, 51), 20);
  EXPECT_EQ(HistogramPercentile(histogram, 100, 90), 20);
  EXPECT_EQ(HistogramPercentile(histogram, 100, 95), 30);
}

}  // namespace
}  // namespace corridor
