#include "kernels/max_filter.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace corridor {
namespace {

// cv::dilate with a square of ones and its default border is the reference.
cv::Mat Dilated(const cv::Mat& image, int reach) {
  cv::Mat out;
  cv::dilate(image, out, cv::Mat::ones(2 * reach + 1, 2 * reach + 1, CV_8U));
  return out;
}

TEST(MaxFilterSquareTest, MatchesDilateOnRandomImagesOfEverySmallSize) {
  cv::RNG rng(5);
  for (int reach = 0; reach <= 3; ++reach) {
    for (int rows = 1; rows <= 12; ++rows) {
      for (int cols = 1; cols <= 40; cols += 3) {
        cv::Mat image(rows, cols, CV_8UC1);
        rng.fill(image, cv::RNG::UNIFORM, 0, 256);
        cv::Mat out;
        MaxFilterSquare(image, reach, &out);
        ASSERT_EQ(cv::norm(out, Dilated(image, reach), cv::NORM_INF), 0)
            << rows << "x" << cols << " reach " << reach;
      }
    }
  }
}

TEST(MaxFilterSquareTest, SparseEdgesOfAFrameAndAView) {
  cv::RNG rng(11);
  cv::Mat edges = cv::Mat::zeros(240, 320, CV_8UC1);
  for (int i = 0; i < 900; ++i) edges.at<uchar>(rng.uniform(0, 240), rng.uniform(0, 320)) = 255;
  cv::Mat out;
  MaxFilterSquare(edges, 2, &out);
  EXPECT_EQ(cv::norm(out, Dilated(edges, 2), cv::NORM_INF), 0);
  // A view inside a larger image (row step wider than the row): the pixels outside it do not
  // count, as for cv::dilate of the view with its default border.
  const cv::Mat view = edges(cv::Rect(7, 9, 100, 50));
  cv::Mat view_out;
  MaxFilterSquare(view, 2, &view_out);
  EXPECT_EQ(cv::norm(view_out, Dilated(view.clone(), 2), cv::NORM_INF), 0);
  // In place: the result replaces the image.
  cv::Mat same = edges.clone();
  MaxFilterSquare(same, 2, &same);
  EXPECT_EQ(cv::norm(same, out, cv::NORM_INF), 0);
}

}  // namespace
}  // namespace corridor
