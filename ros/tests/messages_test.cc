// The node's message conversions against hand-computed bytes: depth in both encodings (every kind
// of "no estimate": NaN, 0, negative, infinite), and the camera_info checks that refuse a frame.

#include <cmath>
#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include "io/ros_depth_message.h"
#include "ros/camera_info.h"

namespace corridor {
namespace {

cv::Mat TestDepth() {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  cv::Mat depth(2, 4, CV_32F);
  const float values[8] = {nan, 0.0f, -1.0f, inf, 1.2345f, 2.0f, 70.0f, 0.0004f};
  std::memcpy(depth.data, values, sizeof(values));
  return depth;
}

TEST(DepthMessageTest, MetresWithNaNForNone) {
  sensor_msgs::Image image;
  ASSERT_TRUE(FillDepthImage(TestDepth(), "32FC1", &image).ok());
  EXPECT_EQ(image.encoding, "32FC1");
  EXPECT_EQ(image.width, 4u);
  EXPECT_EQ(image.height, 2u);
  EXPECT_EQ(image.step, 16u);
  EXPECT_EQ(image.is_bigendian, 0);
  ASSERT_EQ(image.data.size(), 32u);
  std::vector<float> out(8);
  for (size_t i = 0; i < 8; ++i) {  // Little-endian IEEE 754, assembled by hand.
    const uint32_t bits = image.data[4 * i] | (image.data[4 * i + 1] << 8) |
                          (image.data[4 * i + 2] << 16) |
                          (static_cast<uint32_t>(image.data[4 * i + 3]) << 24);
    std::memcpy(&out[i], &bits, 4);
  }
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(std::isnan(out[i])) << i;
  EXPECT_EQ(out[4], 1.2345f);
  EXPECT_EQ(out[5], 2.0f);
  EXPECT_EQ(out[6], 70.0f);
  EXPECT_EQ(out[7], 0.0004f);
}

TEST(DepthMessageTest, MillimetresWithZeroForNone) {
  sensor_msgs::Image image;
  ASSERT_TRUE(FillDepthImage(TestDepth(), "16UC1", &image).ok());
  EXPECT_EQ(image.encoding, "16UC1");
  EXPECT_EQ(image.step, 8u);
  ASSERT_EQ(image.data.size(), 16u);
  const int expected[8] = {0, 0, 0, 0, 1235, 2000, 65535, 0};  // Rounded, clamped; 0.4 mm -> 0.
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(image.data[2 * i] | (image.data[2 * i + 1] << 8), expected[i]) << i;
  }
  EXPECT_FALSE(FillDepthImage(TestDepth(), "mono16", &image).ok());
  EXPECT_FALSE(FillDepthImage(cv::Mat(2, 2, CV_64F, cv::Scalar(1)), "32FC1", &image).ok());
}

sensor_msgs::CameraInfo GoodInfo() {
  sensor_msgs::CameraInfo info;
  info.width = 640;
  info.height = 480;
  info.distortion_model = "plumb_bob";
  info.D = {0.1, -0.05, 0, 0, 0};
  info.K = {500, 0, 320, 0, 510, 240, 0, 0, 1};
  return info;
}

TEST(CameraInfoTest, TakesIntrinsicsAndDistortion) {
  Camera camera;
  ASSERT_TRUE(CameraFromInfo(GoodInfo(), 640, 480, &camera).ok());
  EXPECT_EQ(camera.fx, 500);
  EXPECT_EQ(camera.fy, 510);
  EXPECT_EQ(camera.cx, 320);
  EXPECT_EQ(camera.cy, 240);
  EXPECT_EQ(camera.distortion[0], 0.1);
  EXPECT_EQ(camera.distortion[1], -0.05);
  sensor_msgs::CameraInfo rational = GoodInfo();
  rational.distortion_model = "rational_polynomial";
  rational.D = {0.1, -0.05, 0, 0, 0, 0, 0, 0};
  EXPECT_TRUE(CameraFromInfo(rational, 640, 480, &camera).ok());
}

TEST(CameraInfoTest, RefusesWhatItCannotUse) {
  Camera camera;
  const auto refused = [&](const sensor_msgs::CameraInfo& info, int w, int h,
                           const std::string& why) {
    const Status status = CameraFromInfo(info, w, h, &camera);
    EXPECT_EQ(status.code(), StatusCode::kInvalidArgument) << why;
    EXPECT_NE(status.message().find(why), std::string::npos) << status.message();
  };
  refused(GoodInfo(), 320, 240, "camera_info is 640x480 but the image is 320x240");
  sensor_msgs::CameraInfo zero = GoodInfo();
  zero.K[0] = 0;
  refused(zero, 640, 480, "focal length");
  sensor_msgs::CameraInfo nan = GoodInfo();
  nan.K[2] = std::nan("");
  refused(nan, 640, 480, "principal point");
  sensor_msgs::CameraInfo binned = GoodInfo();
  binned.binning_x = 2;
  refused(binned, 640, 480, "binning");
  sensor_msgs::CameraInfo fisheye = GoodInfo();
  fisheye.distortion_model = "equidistant";
  refused(fisheye, 640, 480, "equidistant");
  sensor_msgs::CameraInfo rational = GoodInfo();
  rational.distortion_model = "rational_polynomial";
  rational.D = {0.1, -0.05, 0, 0, 0, 0.01, 0, 0};
  refused(rational, 640, 480, "beyond plumb_bob");
}

}  // namespace
}  // namespace corridor
