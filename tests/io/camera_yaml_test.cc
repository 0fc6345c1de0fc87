#include "corridor_depth/camera_yaml.h"

#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "tests/io/test_dir.h"
#include "tests/support/camera_expect.h"

namespace corridor {
namespace {

using testing_util::Contains;
using testing_util::TestDir;

const char kK[] = "[500, 0, 319.5, 0, 510, 239.5, 0, 0, 1]";
const char kPlumbBob[] =
    "distortion_model: plumb_bob\n"
    "distortion_coefficients:\n  rows: 1\n  cols: 5\n  data: [0.1, -0.2, 0.001, 0.002, 0.05]\n";

// A ROS camera_info file as the calibration tools write it, with replaceable parts.
std::string RosYaml(const std::string& k = kK, const std::string& distortion = kPlumbBob,
                    const std::string& extra = "camera_height: 0.66\n") {
  return "image_width: 640\nimage_height: 480\ncamera_name: zed_left\n"
         "camera_matrix:\n  rows: 3\n  cols: 3\n  data: " +
         k + "\n" + distortion +
         "rectification_matrix:\n  rows: 3\n  cols: 3\n  data: [1, 0, 0, 0, 1, 0, 0, 0, 1]\n" +
         extra;
}

// Writes `text` as camera.yaml in `dir` and reads it back.
Status ReadText(const TestDir& dir, const std::string& text, Camera* camera) {
  return ReadCameraYaml(dir.Write("camera.yaml", text), camera);
}

// Expects a failure whose message names camera.yaml and contains `part`.
void ExpectError(const TestDir& dir, const std::string& text, const std::string& part) {
  Camera c;
  const Status status = ReadText(dir, text, &c);
  EXPECT_FALSE(status.ok());
  EXPECT_TRUE(Contains(status.message(), dir.Path("camera.yaml"))) << status.message();
  EXPECT_TRUE(Contains(status.message(), part)) << status.message();
}

TEST(CameraYamlTest, ReadsRosCameraInfo) {
  TestDir dir;
  Camera c;
  ASSERT_TRUE(ReadText(dir, RosYaml(), &c).ok());
  testing_util::ExpectPinhole(c, 640, 480, 500.0, 510.0, 319.5, 239.5);
  EXPECT_EQ(c.distortion[0], 0.1);
  EXPECT_EQ(c.distortion[1], -0.2);
  EXPECT_EQ(c.distortion[2], 0.001);
  EXPECT_EQ(c.distortion[3], 0.002);
  EXPECT_EQ(c.distortion[4], 0.05);
  EXPECT_EQ(c.mount_height, 0.66);
}

TEST(CameraYamlTest, ShortDistortionIsZeroPadded) {
  TestDir dir;
  Camera c;
  const std::string d =
      "distortion_model: plumb_bob\ndistortion_coefficients:\n"
      "  rows: 1\n  cols: 2\n  data: [0.1, -0.2]\n";
  ASSERT_TRUE(ReadText(dir, RosYaml(kK, d), &c).ok());
  EXPECT_EQ(c.distortion[0], 0.1);
  EXPECT_EQ(c.distortion[1], -0.2);
  EXPECT_EQ(c.distortion[2], 0.0);
  EXPECT_EQ(c.distortion[3], 0.0);
  EXPECT_EQ(c.distortion[4], 0.0);
}

TEST(CameraYamlTest, NoneOrAbsentDistortionIsZero) {
  TestDir dir;
  Camera c;
  const std::string none =
      "distortion_model: none\ndistortion_coefficients:\n"
      "  rows: 1\n  cols: 1\n  data: [0.3]\n";
  ASSERT_TRUE(ReadText(dir, RosYaml(kK, none), &c).ok());
  EXPECT_FALSE(c.HasDistortion());
  ASSERT_TRUE(ReadText(dir, RosYaml(kK, ""), &c).ok());
  EXPECT_FALSE(c.HasDistortion());
}

TEST(CameraYamlTest, CameraHeightIsOptional) {
  TestDir dir;
  Camera c;
  c.mount_height = 5;
  ASSERT_TRUE(ReadText(dir, RosYaml(kK, kPlumbBob, ""), &c).ok());
  EXPECT_EQ(c.mount_height, 0.0);
}

TEST(CameraYamlTest, RoundTripIsExact) {
  TestDir dir;
  Camera c;
  c.image_width = 421;
  c.image_height = 359;
  c.fx = 1.0 / 3.0 * 700;
  c.fy = 233.33333333333334;
  c.cx = 209.49999999999997;
  c.cy = 0.1 + 0.2;  // 0.30000000000000004: needs all 17 digits.
  c.distortion = {0.1, -1e-17, 3.0e-5, -2.5e-4, 0.7};
  c.mount_height = 0.6612345678901234;
  const std::string path = dir.Path("out/cam.yaml");
  ASSERT_TRUE(WriteCameraYaml(path, c).ok());
  Camera r;
  ASSERT_TRUE(ReadCameraYaml(path, &r).ok());
  EXPECT_EQ(r.image_width, 421);
  EXPECT_EQ(r.image_height, 359);
  EXPECT_EQ(r.fx, 1.0 / 3.0 * 700);
  EXPECT_EQ(r.fy, 233.33333333333334);
  EXPECT_EQ(r.cx, 209.49999999999997);
  EXPECT_EQ(r.cy, 0.1 + 0.2);
  EXPECT_EQ(r.distortion, c.distortion);
  EXPECT_EQ(r.mount_height, 0.6612345678901234);
  // It is a ROS file: a plain YAML reader finds the ROS keys.
  const YAML::Node node = YAML::LoadFile(path);
  EXPECT_EQ(node["distortion_model"].as<std::string>(), "plumb_bob");
  EXPECT_EQ(node["projection_matrix"]["data"].size(), 12u);
  EXPECT_EQ(node["camera_matrix"]["data"][8].as<double>(), 1.0);
}

TEST(CameraYamlTest, WriteRefusesInvalidCamera) {
  TestDir dir;
  Camera c;  // Size 0x0, focal 0.
  const std::string path = dir.Path("cam.yaml");
  const Status status = WriteCameraYaml(path, c);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(Contains(status.message(), path));
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(CameraYamlTest, MissingFile) {
  TestDir dir;
  Camera c;
  const Status status = ReadCameraYaml(dir.Path("none.yaml"), &c);
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_TRUE(Contains(status.message(), dir.Path("none.yaml")));
}

TEST(CameraYamlTest, MissingKeysAreNamed) {
  TestDir dir;
  ExpectError(dir, "image_width: 640\ncamera_matrix: {data: " + std::string(kK) + "}\n",
              "missing key 'image_height'");
  ExpectError(dir, "image_width: 640\nimage_height: 480\n", "missing key 'camera_matrix'");
  ExpectError(dir, "image_width: 640\nimage_height: 480\ncamera_matrix: {rows: 3, cols: 3}\n",
              "missing key 'camera_matrix.data'");
}

TEST(CameraYamlTest, MalformedYamlNamesLine) {
  TestDir dir;
  ExpectError(dir, "image_width: 640\nimage_height: 480\ncamera_matrix: {data: [1, 2\n",
              "YAML syntax error at line");
  ExpectError(dir, "", "empty");
}

TEST(CameraYamlTest, NonNumericValuesAreNamed) {
  TestDir dir;
  ExpectError(dir, RosYaml("[abc, 0, 319.5, 0, 510, 239.5, 0, 0, 1]"),
              "'camera_matrix.data[0]' is not a number: 'abc'");
  ExpectError(dir, RosYaml(kK, kPlumbBob, "camera_height: tall\n"), "'camera_height'");
  ExpectError(dir, "image_width: wide\n", "'image_width' is not an integer");
}

TEST(CameraYamlTest, NaNFocalIsRejected) {
  TestDir dir;
  ExpectError(dir, RosYaml("[.nan, 0, 319.5, 0, 510, 239.5, 0, 0, 1]"), "focal");
  ExpectError(dir, RosYaml("[-500, 0, 319.5, 0, 510, 239.5, 0, 0, 1]"), "focal");
}

TEST(CameraYamlTest, BadMatrixShapesAreRejected) {
  TestDir dir;
  ExpectError(dir, RosYaml("[500, 0, 319.5, 0, 510, 239.5, 0, 0]"), "camera_matrix");
  ExpectError(dir, RosYaml("[500, 2, 319.5, 0, 510, 239.5, 0, 0, 1]"), "no skew");
  ExpectError(dir, RosYaml("[500, 0, 1000, 0, 510, 239.5, 0, 0, 1]"), "principal point");
  const std::string rational =
      "distortion_model: plumb_bob\ndistortion_coefficients:\n"
      "  data: [0, 0, 0, 0, 0, 0, 0, 0]\n";
  ExpectError(dir, RosYaml(kK, rational), "distortion_coefficients.data' has 8 values");
}

TEST(CameraYamlTest, UnknownDistortionModelIsNamed) {
  TestDir dir;
  ExpectError(dir, RosYaml(kK, "distortion_model: equidistant\n"), "'equidistant'");
}

}  // namespace
}  // namespace corridor
