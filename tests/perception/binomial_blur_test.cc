// BinomialBlur against a direct 2-D convolution written here: the outer product of the binomial
// kernel, reflected borders by cv::borderInterpolate, the exact integer sum rounded half up.
#include "perception/binomial_blur.h"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

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

}  // namespace
}  // namespace corridor
