// The fuzzers' findings, replayed as ordinary tests: every file under
// tests/fuzz/regressions/<target>/ is an input that once broke a contract of fuzz_checks.h or
// tripped a sanitizer (docs/reliability.md lists them). Each must now pass the same checks.

#include <gtest/gtest.h>

#include <filesystem>

#include "tests/fuzz/fuzz_checks.h"
#include "tests/reliability/reliability_util.h"

namespace corridor {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> Findings(const std::string& target) {
  std::vector<std::string> files;
  const fs::path dir = fs::path(CORRIDOR_SOURCE_DIR) / "tests/fuzz/regressions" / target;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (entry.is_regular_file() && entry.path().filename().string()[0] != '.') {
      files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string Check(const std::string& target, const std::string& bytes) {
  const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
  return target == "camera_yaml" ? fuzz::CheckCameraYamlInput(data, bytes.size())
                                 : fuzz::CheckRecoverDepthInput(data, bytes.size());
}

TEST(FuzzRegression, CameraYamlFindingsPass) {
  for (const std::string& file : Findings("camera_yaml")) {
    EXPECT_EQ(Check("camera_yaml", testing_util::ReadAll(file)), "") << file;
  }
}

TEST(FuzzRegression, RecoverDepthFindingsPass) {
  for (const std::string& file : Findings("recover_depth")) {
    EXPECT_EQ(Check("recover_depth", testing_util::ReadAll(file)), "") << file;
  }
}

// The checks themselves: a valid corridor passes, and the decoder's contract-breaking options
// (an unknown solver) are rejected cleanly.
TEST(FuzzRegression, ChecksAcceptAValidCorridorAndRejectedOptions) {
  const Camera camera = testing_util::ReliabilityCamera(64, 48);
  const cv::Mat image =
      testing_util::RenderTestCorridor(camera, testing_util::ReliabilityGeometry(), 3);
  for (uint8_t solver = 0; solver < 10; ++solver) {
    EXPECT_EQ(Check("recover_depth", fuzz::EncodeFuzzSeed(image, solver, 0)), "") << int(solver);
  }
  EXPECT_EQ(Check("camera_yaml",
                  "image_width: 64\nimage_height: 48\ncamera_matrix: {data: "
                  "[50, 0, 32, 0, 50, 24, 0, 0, 1]}\n"),
            "");
  EXPECT_EQ(Check("camera_yaml", "[unclosed"), "");
}

}  // namespace
}  // namespace corridor
