// One photo to depth with the installed library: corridor_consumer PHOTO HFOV_DEG CAMERA_HEIGHT_M
// Prints the status, the geometry and the fraction of pixels with a depth.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <corridor_depth/corridor_depth.h>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s PHOTO HFOV_DEG CAMERA_HEIGHT_M\n", argv[0]);
    return 2;
  }
  cv::Mat image;
  corridor::Status status = corridor::ReadColorImage(argv[1], &image);
  if (!status.ok()) {
    std::fprintf(stderr, "%s\n", status.ToString().c_str());
    return 2;
  }
  const corridor::Camera camera = corridor::Camera::FromHorizontalFov(
      image.cols, image.rows, std::atof(argv[2]) * M_PI / 180, std::atof(argv[3]));
  corridor::RecoverDepthResult result;
  status = corridor::RecoverDepth(image, camera, corridor::RecoverDepthOptions(), &result);
  std::printf("status=%s\n", status.ToString().c_str());
  if (!status.ok()) return 1;
  int with_depth = 0;
  for (int v = 0; v < result.depth.rows; ++v) {
    for (int u = 0; u < result.depth.cols; ++u) with_depth += std::isfinite(result.depth.at<float>(v, u));
  }
  std::printf("width_m=%.3f yaw_rad=%.4f pitch_rad=%.4f confidence=%.2f depth_fraction=%.3f\n",
              result.geometry.width, result.geometry.yaw, result.geometry.pitch, result.confidence,
              static_cast<double>(with_depth) / (result.depth.rows * result.depth.cols));
  return 0;
}
