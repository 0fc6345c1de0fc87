// The C++ path the Python tests and the overhead measurement compare the module with:
//   corridor_python_reference IMAGE CAMERA CAMERA_HEIGHT OUT_RAW [REPEAT]
// CAMERA is a calibration YAML or a horizontal field of view in degrees. Recovers depth from the
// image with the default options (RecoverDepth, as research code calls it), writes the float
// depth (CV_32F metres, rows x cols, row-major, raw) to OUT_RAW and prints the status, the
// geometry and the size as key=value lines. With REPEAT > 1, one untimed call, then REPEAT
// timed ones, whose mean seconds per call is printed (seconds_per_call=...).

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "corridor_depth/camera_yaml.h"
#include "corridor_depth/image_io.h"
#include "corridor_depth/recover_depth.h"

int main(int argc, char** argv) {
  if (argc < 5 || argc > 6) {
    std::fprintf(stderr, "usage: %s IMAGE CAMERA CAMERA_HEIGHT OUT_RAW [REPEAT]\n", argv[0]);
    return 2;
  }
  cv::Mat image;
  corridor::Status status = corridor::ReadColorImage(argv[1], &image);
  if (!status.ok()) {
    std::fprintf(stderr, "%s\n", status.ToString().c_str());
    return 2;
  }
  corridor::Camera camera;
  const std::string camera_arg = argv[2];
  char* end = nullptr;
  const double hfov = std::strtod(camera_arg.c_str(), &end);
  if (end != nullptr && *end == '\0') {
    camera = corridor::Camera::FromHorizontalFov(image.cols, image.rows, hfov * M_PI / 180.0, 0);
  } else if (!(status = corridor::ReadCameraYaml(camera_arg, &camera)).ok()) {
    std::fprintf(stderr, "%s\n", status.ToString().c_str());
    return 2;
  }
  camera.mount_height = std::atof(argv[3]);
  const int repeat = argc == 6 ? std::atoi(argv[5]) : 1;
  corridor::RecoverDepthResult result;
  if (repeat > 1) {  // Untimed: the first call initialises OpenCV's colour tables.
    corridor::RecoverDepth(image, camera, corridor::RecoverDepthOptions(), &result);
  }
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < repeat; ++i) {
    corridor::RecoverDepth(image, camera, corridor::RecoverDepthOptions(), &result);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ofstream out(argv[4], std::ios::binary);
  if (!result.depth.empty()) {
    for (int r = 0; r < result.depth.rows; ++r) {
      out.write(reinterpret_cast<const char*>(result.depth.ptr<float>(r)),
                static_cast<std::streamsize>(sizeof(float)) * result.depth.cols);
    }
  }
  const corridor::CorridorGeometry& g = result.geometry;
  std::printf("status=%s\nrows=%d\ncols=%d\n", result.status.ToString().c_str(), result.depth.rows,
              result.depth.cols);
  std::printf("yaw=%.17g\npitch=%.17g\noffset=%.17g\nwidth=%.17g\nceiling_height=%.17g\n", g.yaw,
              g.pitch, g.offset, g.width, g.ceiling_height);
  std::printf("seconds_per_call=%.9g\n", seconds / repeat);
  return result.status.ok() ? 0 : 1;
}
