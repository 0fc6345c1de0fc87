// BinomialBlur against a direct 2-D convolution written here: the outer product of the binomial
// kernel, reflected borders by cv::borderInterpolate, the exact integer sum rounded half up.
#include "kernels/binomial_blur.h"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace corridor {
namespace {

cv::Mat Reference(const cv::Mat& image, int from, int to, int taps) {
  const int k3[3] = {1, 2, 1}, k5[5] = {1, 4, 6, 4, 1};
  const int* k = taps == 3 ? k3 : k5;
  const int r = taps / 2, total = taps == 3 ? 16 : 256, channels = image.channels();
  cv::Mat out(to - from, image.cols, image.type());
  for (int y = from; y < to; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      for (int c = 0; c < channels; ++c) {
        int sum = 0;
        for (int dy = -r; dy <= r; ++dy) {
          const int yy = cv::borderInterpolate(y + dy, image.rows, cv::BORDER_REFLECT_101);
          for (int dx = -r; dx <= r; ++dx) {
            const int xx = cv::borderInterpolate(x + dx, image.cols, cv::BORDER_REFLECT_101);
            sum += k[dy + r] * k[dx + r] * image.ptr<uchar>(yy)[xx * channels + c];
          }
        }
        out.ptr<uchar>(y - from)[x * channels + c] = static_cast<uchar>((sum + total / 2) / total);
      }
    }
  }
  return out;
}

TEST(BinomialBlurTest, EqualsTheDirectConvolution) {
  cv::RNG rng(7);
  int compared = 0;
  for (int channels = 1; channels <= 4; ++channels) {
    for (const cv::Size size : {cv::Size(53, 37), cv::Size(1, 9), cv::Size(9, 1), cv::Size(2, 2),
                                cv::Size(3, 4), cv::Size(40, 3)}) {
      cv::Mat image(size, CV_8UC(channels));
      rng.fill(image, cv::RNG::UNIFORM, 0, 256);
      for (int taps : {3, 5}) {
        // The whole image, and a band inside it that reads the rows around it.
        for (const auto& [from, to] :
             {std::pair<int, int>{0, size.height},
              std::pair<int, int>{size.height / 3, std::max(size.height / 3 + 1, size.height - 1)}}) {
          cv::Mat blurred;
          ASSERT_TRUE(BinomialBlur(image, from, to, taps, &blurred).ok());
          const cv::Mat expected = Reference(image, from, to, taps);
          ASSERT_EQ(blurred.size(), expected.size());
          ASSERT_EQ(blurred.type(), image.type());
          EXPECT_EQ(cv::norm(blurred, expected, cv::NORM_INF), 0.0)
              << channels << " channels, " << size << ", " << taps << " taps, rows " << from
              << "-" << to;
          ++compared;
        }
      }
    }
  }
  EXPECT_EQ(compared, 4 * 6 * 2 * 2);
}

TEST(BinomialBlurTest, AnImageBlurredIntoItselfIsBlurredFromTheOriginal) {
  cv::Mat image(20, 30, CV_8UC3);
  cv::RNG(8).fill(image, cv::RNG::UNIFORM, 0, 256);
  const cv::Mat expected = Reference(image, 0, image.rows, 5);
  ASSERT_TRUE(BinomialBlur(image, 0, image.rows, 5, &image).ok());
  EXPECT_EQ(cv::norm(image, expected, cv::NORM_INF), 0.0);
}

// Into a view of the same pixels (another header on them): still blurred from the original.
TEST(BinomialBlurTest, AViewOfTheImagesPixelsIsBlurredFromTheOriginal) {
  cv::Mat image(20, 30, CV_8UC1);
  cv::RNG(9).fill(image, cv::RNG::UNIFORM, 0, 256);
  const cv::Mat expected = Reference(image, 5, 15, 3);
  cv::Mat view = image.rowRange(5, 15);
  ASSERT_TRUE(BinomialBlur(image, 5, 15, 3, &view).ok());
  EXPECT_EQ(cv::norm(view, expected, cv::NORM_INF), 0.0);
}

TEST(BinomialBlurTest, RejectsBadImagesTapsAndRows) {
  cv::Mat out;
  const cv::Mat image(10, 10, CV_8UC3, cv::Scalar::all(9));
  EXPECT_FALSE(BinomialBlur(cv::Mat(), 0, 1, 3, &out).ok());
  EXPECT_FALSE(BinomialBlur(cv::Mat(10, 10, CV_16UC1), 0, 10, 3, &out).ok());
  EXPECT_FALSE(BinomialBlur(cv::Mat(10, 10, CV_8UC(5)), 0, 10, 3, &out).ok());
  EXPECT_FALSE(BinomialBlur(image, 0, 10, 4, &out).ok());
  EXPECT_FALSE(BinomialBlur(image, 0, 10, 7, &out).ok());
  EXPECT_FALSE(BinomialBlur(image, -1, 10, 3, &out).ok());
  EXPECT_FALSE(BinomialBlur(image, 0, 11, 3, &out).ok());
  EXPECT_FALSE(BinomialBlur(image, 5, 5, 3, &out).ok());
  const Status status = BinomialBlur(image, 0, 10, 4, &out);
  EXPECT_NE(status.message().find("taps"), std::string::npos) << status.ToString();
}

// GaussianBlurView against cv::GaussianBlur itself, the independent path it must equal bit for
// bit. OpenCV blurs a whole 8-bit image in fixed point, and a band of rows as those rows of the
// whole image blurred; column crops and wider kernels are OpenCV's own call on the view. Every
// channel count, and sigmas on both sides of the five-tap limit.
TEST(GaussianBlurViewTest, EqualsOpenCvsGaussianBlurBitForBit) {
  cv::RNG rng(11);
  int compared = 0, fast = 0;
  for (int channels = 1; channels <= 4; ++channels) {
    for (const cv::Size size : {cv::Size(67, 41), cv::Size(1, 7), cv::Size(7, 1), cv::Size(2, 3),
                                cv::Size(640, 12)}) {
      cv::Mat image(size, CV_8UC(channels));
      rng.fill(image, cv::RNG::UNIFORM, 0, 256);
      for (const double sigma : {0.3, 0.5, 0.7, 0.8, 0.9, 1.2, 2.0}) {
        cv::Mat whole;
        cv::GaussianBlur(image, whole, cv::Size(0, 0), sigma);
        const bool five_taps = sigma < 1;  // sigma 1 has a weight three pixels out.
        const int band = std::max(1, size.height / 3);
        for (const cv::Range rows : {cv::Range::all(), cv::Range(band, size.height),
                                     cv::Range(0, band), cv::Range(band / 2, band)}) {
          if (rows.start >= rows.end && rows != cv::Range::all()) continue;
          const cv::Mat view = image.rowRange(rows);
          cv::Mat expected = whole.rowRange(rows), blurred;
          if (!five_taps) cv::GaussianBlur(view, expected, cv::Size(0, 0), sigma);
          GaussianBlurView(view, sigma, &blurred);
          ASSERT_EQ(blurred.size(), expected.size());
          ASSERT_EQ(blurred.type(), expected.type());
          EXPECT_EQ(cv::norm(blurred, expected, cv::NORM_INF), 0.0)
              << channels << " channels, " << size << ", sigma " << sigma << ", rows "
              << rows.start << "-" << rows.end;
          ++compared;
          fast += five_taps;
        }
        // A column crop: OpenCV's call on the view.
        const cv::Mat crop = image.colRange(0, std::max(1, size.width / 2));
        cv::Mat expected, blurred;
        cv::GaussianBlur(crop, expected, cv::Size(0, 0), sigma);
        GaussianBlurView(crop, sigma, &blurred);
        EXPECT_EQ(cv::norm(blurred, expected, cv::NORM_INF), 0.0)
            << channels << " channels, " << size << ", sigma " << sigma << ", column crop";
      }
    }
  }
  EXPECT_GT(compared, 4 * 5 * 7 * 2);
  EXPECT_GT(fast, compared / 2);
}

// The junction search's sigma, 0.8, has OpenCV's kernel [6 58 128 58 6] / 256 (read here off an
// impulse OpenCV blurs). A band blurred into its own pixels is blurred from the original.
TEST(GaussianBlurViewTest, BlursABandIntoItsOwnPixelsFromTheOriginal) {
  cv::Mat impulse = cv::Mat::zeros(1, 9, CV_8U), spread;
  impulse.at<uchar>(0, 4) = 255;
  cv::GaussianBlur(impulse, spread, cv::Size(0, 0), 0.8);
  EXPECT_EQ(spread.at<uchar>(0, 2), 6);
  EXPECT_EQ(spread.at<uchar>(0, 3), 58);
  EXPECT_EQ(spread.at<uchar>(0, 1), 0);
  cv::Mat image(30, 50, CV_8UC3);
  cv::RNG(12).fill(image, cv::RNG::UNIFORM, 0, 256);
  cv::Mat whole;
  cv::GaussianBlur(image, whole, cv::Size(0, 0), 0.8);
  cv::Mat view = image.rowRange(10, 30);
  GaussianBlurView(view, 0.8, &view);
  EXPECT_EQ(cv::norm(view, whole.rowRange(10, 30), cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace corridor
