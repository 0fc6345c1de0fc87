#include "kernels/channel_plane.h"

#include <gtest/gtest.h>

namespace corridor {
namespace {

// Every channel of random images of 2 to 4 channels, at widths below, at and past a 32-pixel
// step and on a view, is cv::extractChannel's.
TEST(ChannelPlaneTest, GivesExtractChannelsBytes) {
  cv::RNG rng(7);
  for (const int type : {CV_8UC2, CV_8UC3, CV_8UC4}) {
    for (const int cols : {1, 31, 32, 33, 64, 95, 640}) {
      cv::Mat image(5, cols, type);
      rng.fill(image, cv::RNG::UNIFORM, 0, 256);
      for (int c = 0; c < image.channels(); ++c) {
        cv::Mat expected, plane;
        cv::extractChannel(image, expected, c);
        ChannelPlane(image, c, &plane);
        ASSERT_EQ(plane.size(), image.size());
        EXPECT_EQ(cv::norm(plane, expected, cv::NORM_INF), 0) << type << " " << cols << " " << c;
      }
    }
  }
  cv::Mat whole(8, 70, CV_8UC3);
  rng.fill(whole, cv::RNG::UNIFORM, 0, 256);
  const cv::Mat view = whole(cv::Rect(3, 2, 40, 5));
  cv::Mat expected, plane;
  cv::extractChannel(view, expected, 1);
  ChannelPlane(view, 1, &plane);
  EXPECT_EQ(cv::norm(plane, expected, cv::NORM_INF), 0);
}

// Another depth, one channel or a channel the image lacks: nothing.
TEST(ChannelPlaneTest, LeavesNothingForWhatItCannotSplit) {
  cv::Mat plane(2, 2, CV_8U);
  ChannelPlane(cv::Mat(4, 4, CV_16UC3), 0, &plane);
  EXPECT_TRUE(plane.empty());
  ChannelPlane(cv::Mat(4, 4, CV_8UC1), 0, &plane);
  EXPECT_TRUE(plane.empty());
  ChannelPlane(cv::Mat(4, 4, CV_8UC3), 3, &plane);
  EXPECT_TRUE(plane.empty());
}

}  // namespace
}  // namespace corridor
