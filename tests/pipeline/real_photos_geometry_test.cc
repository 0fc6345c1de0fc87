// Issue 10's bar on the eleven real photographs of ../shared/data/real-corridors/, through the
// whole pipeline with the cameras their README gives (popup_1: its uEye calibration; popup_2/3:
// the Kinect default; rtabmap_*: a 60-degree field of view) and a 1.0 m camera height: both
// junctions on at least 10 of the 11, each with a width between 1 and 6 m and a pitch within
// +-20 degrees.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "pipeline/recover_depth.h"

namespace corridor {
namespace {

const std::string kDir = std::string(CORRIDOR_SHARED_DIR) + "/data/real-corridors/";

Camera Pinhole(int width, int height, double fx, double fy, double cx, double cy) {
  Camera c;
  c.image_width = width;
  c.image_height = height;
  c.fx = fx;
  c.fy = fy;
  c.cx = cx;
  c.cy = cy;
  c.mount_height = 1.0;
  return c;
}

TEST(RealPhotosGeometryTest, BothJunctionsAndAPlausibleCorridorOnTenOfEleven) {
  std::vector<std::pair<std::string, Camera>> photos = {
      {"popup_1.png", Pinhole(640, 512, 371.975, 372.164, 315.632, 250.593)},
      {"popup_2.png", Pinhole(640, 480, 570.342, 570.342, 319.5, 239.5)},
      {"popup_3.png", Pinhole(640, 480, 570.342, 570.342, 319.5, 239.5)}};
  for (int i = 1; i <= 8; ++i) {
    const std::string name = "rtabmap_" + std::to_string(i) + ".jpg";
    const cv::Mat image = cv::imread(kDir + name);
    ASSERT_FALSE(image.empty()) << name;
    photos.emplace_back(name, Camera::FromHorizontalFov(image.cols, image.rows, M_PI / 3, 1.0));
  }
  int good = 0;
  for (const auto& [name, camera] : photos) {
    const cv::Mat image = cv::imread(kDir + name);
    ASSERT_FALSE(image.empty()) << name;
    RecoverDepthResult result;
    RecoverDepth(image, camera, RecoverDepthOptions(), &result);
    const CorridorGeometry& g = result.geometry;
    const bool both = result.status.ok() && result.junctions.status.ok() && result.fallback.empty();
    const bool plausible = g.width >= 1.0 && g.width <= 6.0 && std::abs(g.pitch) <= M_PI / 9;
    std::printf("%-14s %s width %.2f m pitch %.1f deg\n", name.c_str(),
                both ? "both junctions" : result.status.ToString().c_str(), g.width,
                g.pitch * 180 / M_PI);
    good += both && plausible;
  }
  EXPECT_GE(good, 10);
}

}  // namespace
}  // namespace corridor
