// Bad files: a missing path, an empty file, a truncated PNG and JPEG, a text file named .png, a
// folder with no images. Each through the library (ReadColorImage, ResolveInput) and through
// corridor_depth: a clear message naming the file, the documented exit code (2 for a missing
// input or folder without images, 1 for a frame that cannot be read), no crash, no depth.

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "corridor_depth/image_io.h"
#include "tests/reliability/reliability_util.h"
#include "tools/input_source.h"

namespace corridor {
namespace {

using testing_util::Contains;
using testing_util::ExpectCleanExit;
using testing_util::ListFiles;
using testing_util::RunDepthTool;
using testing_util::ScratchDir;

std::string Encoded(const std::string& ext) {
  const Camera camera = testing_util::ReliabilityCamera();
  std::vector<uchar> bytes;
  EXPECT_TRUE(cv::imencode(ext, testing_util::RenderTestCorridor(camera, testing_util::ReliabilityGeometry()), bytes));
  return std::string(bytes.begin(), bytes.end());
}

// A folder with camera.yaml and one file `name` holding `bytes`; returns the file's path.
std::string FrameFolder(const ScratchDir& dir, const std::string& name, const std::string& bytes) {
  dir.WriteCamera("in/camera.yaml", testing_util::ReliabilityCamera());
  return dir.Write("in/" + name, bytes);
}

struct BadFile {
  const char* label;
  const char* name;     // File name in the input folder.
  std::string bytes;    // Its content.
  StatusCode code;      // What ReadColorImage says.
  const char* message;  // A part of its message.
};

std::vector<BadFile> BadFiles() {
  const std::string png = Encoded(".png"), jpg = Encoded(".jpg");
  return {
      {"empty", "empty.png", "", StatusCode::kIoError, "file is empty"},
      {"truncated_png", "cut.png", png.substr(0, png.size() / 2), StatusCode::kIoError,
       "truncated PNG"},
      {"truncated_jpeg", "cut.jpg", jpg.substr(0, jpg.size() / 2), StatusCode::kIoError,
       "truncated JPEG"},
      {"text_named_png", "notes.png", "this is not an image\n", StatusCode::kIoError,
       "not a readable image"},
  };
}

TEST(BadFiles, LibraryNamesTheFileAndSaysWhatIsWrong) {
  ScratchDir dir;
  cv::Mat image;
  Status status = ReadColorImage(dir.Path("missing.png"), &image);
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_TRUE(Contains(status.message(), dir.Path("missing.png"))) << status.ToString();
  for (const BadFile& bad : BadFiles()) {
    const std::string path = FrameFolder(dir, bad.name, bad.bytes);
    status = ReadColorImage(path, &image);
    EXPECT_EQ(status.code(), bad.code) << bad.label << ": " << status.ToString();
    EXPECT_TRUE(Contains(status.message(), path)) << bad.label << ": " << status.ToString();
    EXPECT_TRUE(Contains(status.message(), bad.message)) << bad.label << ": " << status.ToString();
  }
}

TEST(BadFiles, LibraryRejectsMissingInputAndFolderWithoutImages) {
  ScratchDir dir;
  std::vector<InputScene> scenes;
  Status status = ResolveInput(dir.Path("nowhere"), CameraOverrides(), &scenes);
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_TRUE(Contains(status.message(), dir.Path("nowhere"))) << status.ToString();

  dir.WriteCamera("empty/camera.yaml", testing_util::ReliabilityCamera());
  dir.Write("empty/readme.txt", "no images here");
  status = ResolveInput(dir.Path("empty"), CameraOverrides(), &scenes);
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_TRUE(Contains(status.message(), dir.Path("empty"))) << status.ToString();
  EXPECT_TRUE(Contains(status.message(), "holds no images")) << status.ToString();
  EXPECT_TRUE(scenes.empty());
}

TEST(BadFiles, ToolExitsTwoOnMissingInput) {
  ScratchDir dir;
  const auto run = RunDepthTool(dir.Path("nowhere.png"), dir.Path("out"), dir);
  ExpectCleanExit(run, 2, {dir.Path("nowhere.png"), "no such file"});
  EXPECT_FALSE(testing_util::Exists(dir.Path("out")));  // Rejected before any work.
}

TEST(BadFiles, ToolExitsTwoOnFolderWithoutImages) {
  ScratchDir dir;
  dir.WriteCamera("empty/camera.yaml", testing_util::ReliabilityCamera());
  dir.Write("empty/readme.txt", "no images here");
  const auto run = RunDepthTool(dir.Path("empty"), dir.Path("out"), dir);
  ExpectCleanExit(run, 2, {dir.Path("empty"), "holds no images"});
  EXPECT_FALSE(testing_util::Exists(dir.Path("out")));
}

TEST(BadFiles, ToolFailsTheFrameAndWritesNoDepth) {
  for (const BadFile& bad : BadFiles()) {
    SCOPED_TRACE(bad.label);
    ScratchDir dir;
    const std::string path = FrameFolder(dir, bad.name, bad.bytes);
    const auto run = RunDepthTool(path, dir.Path("out"), dir);
    ExpectCleanExit(run, 1, {path, bad.message});
    EXPECT_TRUE(ListFiles(dir.Path("out/in/depth")).empty());
    // The failure is recorded in geometry.csv.
    const std::string csv = testing_util::ReadAll(dir.Path("out/in/geometry.csv"));
    EXPECT_TRUE(Contains(csv, bad.message)) << csv;
  }
}

}  // namespace
}  // namespace corridor
