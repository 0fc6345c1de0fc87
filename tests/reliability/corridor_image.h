#pragma once

// A flat-shaded corridor image rendered with the independent box ray caster of
// tests/depth/box_truth.h: floor dark, walls light, ceiling lighter, the far end (beyond 60 m)
// black, with seeded noise. For the reliability tests and the fuzzers' seed corpus.

#include <cmath>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "tests/depth/box_truth.h"

namespace corridor {
namespace testing_util {

inline Camera ReliabilityCamera(int width = 320, int height = 240) {
  Camera c;
  c.image_width = width;
  c.image_height = height;
  c.fx = c.fy = 250.0 * width / 320.0;
  c.cx = 0.5 * (width - 1);
  c.cy = 0.5 * (height - 1);
  c.mount_height = 1.2;
  return c;
}

inline CorridorGeometry ReliabilityGeometry(double yaw = 0.05, double pitch = 0.08,
                                            double offset = 0.1, double width = 2.1) {
  CorridorGeometry g;
  g.yaw = yaw;
  g.pitch = pitch;
  g.offset = offset;
  g.width = width;
  g.camera_height = 1.2;
  return g;
}

// `depth` (may be null) gets the camera-frame z in metres (0 beyond 60 m).
inline cv::Mat RenderTestCorridor(const Camera& camera, const CorridorGeometry& g, int seed = 1,
                                  cv::Mat* depth = nullptr) {
  cv::Mat image(camera.image_height, camera.image_width, CV_8UC3);
  if (depth != nullptr) *depth = cv::Mat::zeros(image.size(), CV_32F);
  cv::RNG rng(seed);
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      int surface = -1;
      const double z = testing::BoxDepth(camera, g, u, v, &surface);
      double shade = 20;
      if (std::isfinite(z) && z <= 60) {
        if (depth != nullptr) depth->at<float>(v, u) = static_cast<float>(z);
        shade = surface == 0 ? 70 : surface == 1 ? 190
                                                 : 225;
      }
      const double noise = rng.gaussian(2.0);
      image.at<cv::Vec3b>(v, u) = cv::Vec3b(cv::saturate_cast<uchar>(shade + noise),
                                            cv::saturate_cast<uchar>(shade + 5 + noise),
                                            cv::saturate_cast<uchar>(shade + 10 + noise));
    }
  }
  return image;
}

}  // namespace testing_util
}  // namespace corridor
