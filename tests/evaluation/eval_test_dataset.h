#pragma once

// A small corridor dataset on disk for the corridor_eval tests, in the dataset layout of
// io/dataset.h: flat-shaded corridor boxes (tests/reliability/corridor_image.h, rendered with
// the independent box ray caster of tests/depth/box_truth.h), their depth as 16-bit millimetre
// PNGs, camera.yaml and truth.yaml.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "corridor_depth/camera_yaml.h"
#include "corridor_depth/truth_yaml.h"
#include "tests/reliability/corridor_image.h"

namespace corridor {
namespace testing_util {

// A fresh folder under the test temp dir, removed at the end.
class EvalTempDir {
 public:
  explicit EvalTempDir(const std::string& tag) {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::path(::testing::TempDir()) /
            ("corridor_eval_" + tag + "_" + info->name() + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~EvalTempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  EvalTempDir(const EvalTempDir&) = delete;
  EvalTempDir& operator=(const EvalTempDir&) = delete;
  std::string Path(const std::string& relative = "") const { return (path_ / relative).string(); }

 private:
  std::filesystem::path path_;
};

// Writes <root>/<scene>/{rgb,depth}/<NNN>.png for each pose, with camera.yaml and truth.yaml.
inline void WriteEvalTestScene(const std::string& root, const std::string& scene,
                               const std::vector<CorridorGeometry>& poses) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(root) / scene;
  fs::create_directories(dir / "rgb");
  fs::create_directories(dir / "depth");
  const Camera camera = ReliabilityCamera();
  ASSERT_TRUE(WriteCameraYaml((dir / "camera.yaml").string(), camera).ok());
  std::vector<FrameTruth> truths;
  for (size_t i = 0; i < poses.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof(name), "%03zu", i);
    cv::Mat depth;
    const cv::Mat image = RenderTestCorridor(camera, poses[i], static_cast<int>(i) + 1, &depth);
    cv::Mat mm;
    depth.convertTo(mm, CV_16U, 1000.0);
    ASSERT_TRUE(cv::imwrite((dir / "rgb" / (std::string(name) + ".png")).string(), image));
    ASSERT_TRUE(cv::imwrite((dir / "depth" / (std::string(name) + ".png")).string(), mm));
    FrameTruth truth;
    truth.file = std::string(name) + ".png";
    truth.geometry = poses[i];
    truths.push_back(truth);
  }
  ASSERT_TRUE(WriteTruthYaml((dir / "truth.yaml").string(), truths).ok());
}

// Reads a 16-bit millimetre PNG as CV_32F metres with OpenCV alone (not io/image_io).
inline cv::Mat ReadMillimetrePng(const std::string& path) {
  const cv::Mat mm = cv::imread(path, cv::IMREAD_UNCHANGED);
  cv::Mat metres;
  if (mm.empty() || mm.type() != CV_16UC1) return metres;
  mm.convertTo(metres, CV_32F, 1e-3);
  return metres;
}

}  // namespace testing_util
}  // namespace corridor
