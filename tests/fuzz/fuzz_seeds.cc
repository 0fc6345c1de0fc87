// Writes the seed corpora of the fuzz targets:
//   fuzz_seeds <recover_depth_corpus_dir> <camera_yaml_corpus_dir>
// recover_depth: small rendered corridors with each solver and rasteriser, and junction pairs
// to reconstruct directly; camera_yaml: valid calibrations in the variants ReadCameraYaml takes.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "corridor_depth/camera_yaml.h"
#include "tests/fuzz/fuzz_input.h"
#include "tests/reliability/corridor_image.h"

namespace corridor {
namespace {

void Save(const std::filesystem::path& dir, const std::string& name, const std::string& bytes) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << bytes;
}

int Main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: fuzz_seeds RECOVER_DEPTH_DIR CAMERA_YAML_DIR\n");
    return 2;
  }
  const std::filesystem::path recover_dir(argv[1]), yaml_dir(argv[2]);
  const Camera camera = testing_util::ReliabilityCamera(64, 48);
  int n = 0;
  for (double yaw : {0.0, 0.1}) {
    const cv::Mat image =
        testing_util::RenderTestCorridor(camera, testing_util::ReliabilityGeometry(yaw), 3);
    for (uint8_t solver = 0; solver < 6; ++solver) {
      for (uint8_t rasterizer = 0; rasterizer < 2; ++rasterizer) {
        std::string bytes = fuzz::EncodeFuzzSeed(image, solver, rasterizer);
        Save(recover_dir, "corridor_" + std::to_string(n++), bytes);
        // The same with junctions to reconstruct: both lines running to a central point.
        bytes[2] = static_cast<char>(bytes[2] | 16);
        const uint8_t ends[8] = {20, 255, 120, 140, 235, 255, 135, 140};
        for (int i = 0; i < 8; ++i) bytes[19 + i] = static_cast<char>(ends[i]);
        Save(recover_dir, "junctions_" + std::to_string(n++), bytes);
      }
    }
  }
  Camera yaml_camera = testing_util::ReliabilityCamera(640, 480);
  const std::string path = (yaml_dir / "camera.yaml").string();
  std::filesystem::create_directories(yaml_dir);
  if (!WriteCameraYaml(path, yaml_camera).ok()) return 1;
  yaml_camera.distortion = {-0.1, 0.02, 0.001, -0.001, 0.0};
  if (!WriteCameraYaml((yaml_dir / "distorted.yaml").string(), yaml_camera).ok()) return 1;
  Save(yaml_dir, "minimal.yaml",
       "image_width: 640\nimage_height: 480\ncamera_matrix:\n  data: [500, 0, 319.5, 0, 500, "
       "239.5, 0, 0, 1]\ndistortion_model: none\ncamera_height: 1.2\n");
  Save(yaml_dir, "short_distortion.yaml",
       "image_width: 64\nimage_height: 48\ncamera_matrix: {rows: 3, cols: 3, data: [50, 0, 32, "
       "0, 50, 24, 0, 0, 1]}\ndistortion_coefficients: {rows: 1, cols: 2, data: [0.1, -0.2]}\n");
  std::printf("fuzz_seeds: %d recover_depth seeds in %s, 4 camera_yaml seeds in %s\n", n,
              recover_dir.c_str(), yaml_dir.c_str());
  return 0;
}

}  // namespace
}  // namespace corridor

int main(int argc, char** argv) { return corridor::Main(argc, argv); }
