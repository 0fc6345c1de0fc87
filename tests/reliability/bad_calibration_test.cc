// Bad calibration: a missing key; focal length negative, zero, NaN; the principal point outside
// the image; non-finite distortion; camera height 0, negative, above 10 m; an image whose size
// is not the calibration's. Through the library (ReadCameraYaml, Camera::Check, ResolveInput,
// RecoverDepth) and corridor_depth: exit 2 before any work, naming the file and the key.

#include <gtest/gtest.h>

#include <map>

#include "corridor_depth/camera_yaml.h"
#include "corridor_depth/recover_depth.h"
#include "tests/reliability/reliability_util.h"
#include "tools/input_source.h"

namespace corridor {
namespace {

using testing_util::Contains;
using testing_util::ExpectCleanExit;
using testing_util::ListFiles;
using testing_util::ReliabilityCamera;
using testing_util::ReliabilityGeometry;
using testing_util::RunDepthTool;
using testing_util::ScratchDir;

// A ROS camera_info YAML for ReliabilityCamera(); `changes` replace values, "" drops the key.
std::string CameraText(const std::map<std::string, std::string>& changes) {
  std::map<std::string, std::string> v = {{"image_width", "320"}, {"image_height", "240"}, {"fx", "250"}, {"fy", "250"}, {"cx", "159.5"}, {"cy", "119.5"}, {"k1", "0"}, {"camera_height", "1.2"}, {"camera_matrix", "yes"}};
  for (const auto& [key, value] : changes) v[key] = value;
  std::string text;
  for (const char* key : {"image_width", "image_height", "camera_height"}) {
    if (!v[key].empty()) text += std::string(key) + ": " + v[key] + "\n";
  }
  if (!v["camera_matrix"].empty()) {
    text += "camera_matrix:\n  rows: 3\n  cols: 3\n  data: [" + v["fx"] + ", 0, " + v["cx"] +
            ", 0, " + v["fy"] + ", " + v["cy"] + ", 0, 0, 1]\n";
  }
  text += "distortion_model: plumb_bob\ndistortion_coefficients:\n  rows: 1\n  cols: 5\n  data: [" +
          v["k1"] + ", 0, 0, 0, 0]\n";
  return text;
}

struct BadCalibration {
  const char* name;
  std::map<std::string, std::string> changes;
  bool parses;          // ReadCameraYaml accepts it (only the height is wrong).
  const char* message;  // A part of the message, from the library and the tool.
};

std::vector<BadCalibration> BadCalibrations() {
  return {
      {"missing_camera_matrix", {{"camera_matrix", ""}}, false, "missing key 'camera_matrix'"},
      {"missing_image_width", {{"image_width", ""}}, false, "missing key 'image_width'"},
      {"focal_negative", {{"fx", "-250"}}, false, "focal lengths"},
      {"focal_zero", {{"fy", "0"}}, false, "focal lengths"},
      {"focal_nan", {{"fx", ".nan"}}, false, "focal lengths"},
      {"principal_point_outside", {{"cx", "500"}}, false, "principal point"},
      {"principal_point_negative", {{"cy", "-3"}}, false, "principal point"},
      {"distortion_nan", {{"k1", ".nan"}}, false, "distortion coefficients must be finite"},
      {"distortion_inf", {{"k1", "-.inf"}}, false, "distortion coefficients must be finite"},
      {"height_zero", {{"camera_height", "0"}}, true, "camera height unknown"},
      {"height_negative", {{"camera_height", "-1.2"}}, true, "camera height -1.2 m"},
      {"height_above_10m", {{"camera_height", "12"}}, true, "camera height 12 m"},
      {"height_nan", {{"camera_height", ".nan"}}, true, "camera height nan m"},
  };
}

TEST(BadCalibration, LibraryNamesTheFileAndWhatIsWrong) {
  for (const BadCalibration& bad : BadCalibrations()) {
    SCOPED_TRACE(bad.name);
    ScratchDir dir;
    const std::string yaml = dir.Write("in/camera.yaml", CameraText(bad.changes));
    dir.WriteImage("in/frame.png", testing_util::RenderTestCorridor(ReliabilityCamera(),
                                                                    ReliabilityGeometry()));
    Camera camera;
    const Status read = ReadCameraYaml(yaml, &camera);
    if (bad.parses) {
      EXPECT_TRUE(read.ok()) << read.ToString();
      EXPECT_FALSE(camera.Check(nullptr));
    } else {
      EXPECT_EQ(read.code(), StatusCode::kInvalidArgument);
      EXPECT_TRUE(Contains(read.message(), yaml)) << read.ToString();
      EXPECT_TRUE(Contains(read.message(), bad.message)) << read.ToString();
    }
    std::vector<InputScene> scenes;
    const Status resolved = ResolveInput(dir.Path("in"), CameraOverrides(), &scenes);
    EXPECT_EQ(resolved.code(), StatusCode::kInvalidArgument);
    EXPECT_TRUE(Contains(resolved.message(), yaml)) << resolved.ToString();
    EXPECT_TRUE(Contains(resolved.message(), bad.message)) << resolved.ToString();
  }
}

TEST(BadCalibration, ToolExitsTwoBeforeAnyWork) {
  for (const BadCalibration& bad : BadCalibrations()) {
    SCOPED_TRACE(bad.name);
    ScratchDir dir;
    const std::string yaml = dir.Write("in/camera.yaml", CameraText(bad.changes));
    dir.WriteImage("in/frame.png", testing_util::RenderTestCorridor(ReliabilityCamera(),
                                                                    ReliabilityGeometry()));
    const auto run = RunDepthTool(dir.Path("in"), dir.Path("out"), dir);
    ExpectCleanExit(run, 2, {yaml, bad.message});
    EXPECT_FALSE(testing_util::Exists(dir.Path("out")));
  }
}

TEST(BadCalibration, CameraHeightFlagIsCheckedToo) {
  ScratchDir dir;
  dir.WriteCamera("in/camera.yaml", ReliabilityCamera());
  dir.WriteImage("in/frame.png",
                 testing_util::RenderTestCorridor(ReliabilityCamera(), ReliabilityGeometry()));
  for (const char* height : {"-1", "0.0001e6", "nan"}) {
    SCOPED_TRACE(height);
    const auto run = RunDepthTool(dir.Path("in"), dir.Path("out"), dir,
                                  {std::string("--camera_height=") + height});
    ExpectCleanExit(run, 2, {"--camera_height", "camera height"});
    EXPECT_FALSE(testing_util::Exists(dir.Path("out")));
  }
}

TEST(BadCalibration, LibraryRejectsAnImageOfAnotherSize) {
  const cv::Mat image =
      testing_util::RenderTestCorridor(ReliabilityCamera(), ReliabilityGeometry());
  RecoverDepthResult result;
  const Status status =
      RecoverDepth(image, ReliabilityCamera(640, 480), RecoverDepthOptions(), &result);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(Contains(status.message(), "320x240")) << status.ToString();
  EXPECT_TRUE(Contains(status.message(), "640x480")) << status.ToString();
  EXPECT_TRUE(result.depth.empty());
}

// Every frame of another size: the calibration is wrong, a configuration error.
TEST(BadCalibration, ToolExitsTwoWhenTheCameraIsNotTheImagesSize) {
  ScratchDir dir;
  const std::string yaml = dir.WriteCamera("in/camera.yaml", ReliabilityCamera(640, 480));
  const std::string frame = dir.WriteImage(
      "in/000.png", testing_util::RenderTestCorridor(ReliabilityCamera(), ReliabilityGeometry()));
  const auto run = RunDepthTool(dir.Path("in"), dir.Path("out"), dir);
  ExpectCleanExit(run, 2, {yaml, frame, "320x240", "640x480"});
  EXPECT_FALSE(testing_util::Exists(dir.Path("out")));
}

// One odd frame in a run: that frame fails (exit 1), the others are written.
TEST(BadCalibration, ToolFailsOnlyTheOddSizedFrame) {
  ScratchDir dir;
  const Camera camera = ReliabilityCamera();
  dir.WriteCamera("in/camera.yaml", camera);
  dir.WriteImage("in/000.png", testing_util::RenderTestCorridor(camera, ReliabilityGeometry()));
  const std::string odd = dir.WriteImage(
      "in/001.png",
      testing_util::RenderTestCorridor(ReliabilityCamera(160, 120), ReliabilityGeometry()));
  dir.WriteImage("in/002.png", testing_util::RenderTestCorridor(camera, ReliabilityGeometry(-0.1)));
  const auto run = RunDepthTool(dir.Path("in"), dir.Path("out"), dir);
  ExpectCleanExit(run, 1, {odd, "160x120", "320x240"});
  EXPECT_TRUE(testing_util::Exists(dir.Path("out/in/depth/000.png")));
  EXPECT_FALSE(testing_util::Exists(dir.Path("out/in/depth/001.png")));
  EXPECT_TRUE(testing_util::Exists(dir.Path("out/in/depth/002.png")));
}

}  // namespace
}  // namespace corridor
