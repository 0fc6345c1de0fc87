#include "corridor_depth/truth_yaml.h"

#include <cmath>

#include <gtest/gtest.h>

#include "tests/io/test_dir.h"

namespace corridor {
namespace {

using testing_util::Contains;
using testing_util::TestDir;

// Expects reading `text` as truth.yaml to fail, naming the file and containing `part`.
void ExpectError(const TestDir& dir, const std::string& text, const std::string& part) {
  const std::string path = dir.Write("truth.yaml", text);
  std::vector<FrameTruth> frames;
  const Status status = ReadTruthYaml(path, &frames);
  EXPECT_FALSE(status.ok());
  EXPECT_TRUE(Contains(status.message(), path)) << status.message();
  EXPECT_TRUE(Contains(status.message(), part)) << status.message();
}

TEST(TruthYamlTest, ReadsHandWrittenFile) {
  TestDir dir;
  const std::string path = dir.Write("truth.yaml",
                                     "frames:\n"
                                     "  - file: 000000.png\n"
                                     "    pitch: 0.1\n    yaw: -0.05\n    offset: 0.2\n"
                                     "    width: 2.4\n    camera_height: 0.66\n"
                                     "    ceiling_height: 2.8\n"
                                     "  - {file: 000001.png, pitch: 0, yaw: 0, offset: 0, "
                                     "width: 3, camera_height: 1}\n");
  std::vector<FrameTruth> frames;
  ASSERT_TRUE(ReadTruthYaml(path, &frames).ok());
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].file, "000000.png");
  EXPECT_EQ(frames[0].geometry.pitch, 0.1);
  EXPECT_EQ(frames[0].geometry.yaw, -0.05);
  EXPECT_EQ(frames[0].geometry.offset, 0.2);
  EXPECT_EQ(frames[0].geometry.width, 2.4);
  EXPECT_EQ(frames[0].geometry.camera_height, 0.66);
  EXPECT_EQ(frames[0].geometry.ceiling_height, 2.8);
  EXPECT_EQ(frames[1].file, "000001.png");
  EXPECT_EQ(frames[1].geometry.width, 3.0);
  EXPECT_EQ(frames[1].geometry.ceiling_height, 0.0);  // Optional: no ceiling.
}

TEST(TruthYamlTest, RoundTripKeepsEveryBit) {
  TestDir dir;
  std::vector<FrameTruth> frames(2);
  frames[0].file = "000000.png";
  frames[0].geometry.pitch = 0.1 + 0.2;  // 0.30000000000000004
  frames[0].geometry.yaw = -M_PI / 7;
  frames[0].geometry.offset = 1e-17;
  frames[0].geometry.width = 1.0 / 3.0;
  frames[0].geometry.camera_height = 0.6612345678901234;
  frames[0].geometry.ceiling_height = 123456.789;
  frames[1].file = "frame with spaces: and colon.jpg";
  frames[1].geometry.width = 2.0;
  const std::string path = dir.Path("sub/truth.yaml");
  ASSERT_TRUE(WriteTruthYaml(path, frames).ok());
  std::vector<FrameTruth> read;
  ASSERT_TRUE(ReadTruthYaml(path, &read).ok());
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0].file, "000000.png");
  EXPECT_EQ(read[0].geometry.pitch, 0.1 + 0.2);
  EXPECT_EQ(read[0].geometry.yaw, -M_PI / 7);
  EXPECT_EQ(read[0].geometry.offset, 1e-17);
  EXPECT_EQ(read[0].geometry.width, 1.0 / 3.0);
  EXPECT_EQ(read[0].geometry.camera_height, 0.6612345678901234);
  EXPECT_EQ(read[0].geometry.ceiling_height, 123456.789);
  EXPECT_EQ(read[1].file, "frame with spaces: and colon.jpg");
  EXPECT_EQ(read[1].geometry.width, 2.0);
  EXPECT_EQ(read[1].geometry.pitch, 0.0);
}

TEST(TruthYamlTest, EmptyListRoundTrips) {
  TestDir dir;
  const std::string path = dir.Path("truth.yaml");
  ASSERT_TRUE(WriteTruthYaml(path, {}).ok());
  std::vector<FrameTruth> read(3);
  ASSERT_TRUE(ReadTruthYaml(path, &read).ok());
  EXPECT_TRUE(read.empty());
}

TEST(TruthYamlTest, MissingFile) {
  TestDir dir;
  std::vector<FrameTruth> frames;
  const Status status = ReadTruthYaml(dir.Path("truth.yaml"), &frames);
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_TRUE(Contains(status.message(), dir.Path("truth.yaml")));
}

TEST(TruthYamlTest, ErrorsNameFileAndKey) {
  TestDir dir;
  ExpectError(dir, "scenes: []\n", "missing key 'frames'");
  ExpectError(dir, "frames: 3\n", "'frames' is not a list");
  ExpectError(dir, "frames:\n  - 3\n", "'frames[0]' is not a map");
  ExpectError(dir,
              "frames:\n"
              "  - {file: a.png, pitch: 0, yaw: 0, offset: 0, width: 2, camera_height: 1}\n"
              "  - {file: b.png, yaw: 0, offset: 0, width: 2, camera_height: 1}\n",
              "missing key 'frames[1].pitch'");
  ExpectError(dir,
              "frames:\n"
              "  - {file: a.png, pitch: 0, yaw: 0, offset: 0, width: wide, camera_height: 1}\n",
              "'frames[0].width' is not a number: 'wide'");
  ExpectError(dir,
              "frames:\n"
              "  - {pitch: 0, yaw: 0, offset: 0, width: 2, camera_height: 1}\n",
              "missing key 'frames[0].file'");
  ExpectError(dir,
              "frames:\n"
              "  - {file: a.png, pitch: 0, yaw: 0, offset: 0, width: 2, camera_height: 1}\n"
              "  - {file: a.png, pitch: 0, yaw: 0, offset: 0, width: 2, camera_height: 1}\n",
              "'a.png' is listed twice");
  ExpectError(dir, "frames: [\n", "YAML syntax error at line");
}

}  // namespace
}  // namespace corridor
