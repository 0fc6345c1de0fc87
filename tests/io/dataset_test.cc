#include "corridor_depth/dataset.h"

#include <filesystem>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "corridor_depth/image_io.h"
#include "tests/io/test_dir.h"

namespace corridor {
namespace {

using testing_util::Contains;
using testing_util::TestDir;

// A minimal camera.yaml with focal length `f`.
std::string CameraText(int f) {
  return "image_width: 8\nimage_height: 6\ncamera_matrix:\n  rows: 3\n  cols: 3\n  data: [" +
         std::to_string(f) + ", 0, 3.5, 0, " + std::to_string(f) +
         ", 2.5, 0, 0, 1]\ncamera_height: 0.5\n";
}

// Writes an 8-bit image of the given size with plain cv::imwrite.
void WriteImage(const TestDir& dir, const std::string& rel, int width, int height) {
  const std::string path = dir.Path(rel);
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  ASSERT_TRUE(cv::imwrite(path, cv::Mat(height, width, CV_8UC3, cv::Scalar(1, 2, 3))));
}

// Writes a 16-bit depth image of the given size with plain cv::imwrite.
void WriteDepth(const TestDir& dir, const std::string& rel, int width, int height) {
  const std::string path = dir.Path(rel);
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  ASSERT_TRUE(cv::imwrite(path, cv::Mat(height, width, CV_16UC1, cv::Scalar(1500))));
}

// Two scenes: "a_scene" with its own camera and one JPEG, "b_scene" using the shared root camera
// with two frames, depth for one, a floor mask and truth for the other.
void MakeDataset(const TestDir& dir) {
  dir.Write("camera.yaml", CameraText(100));
  dir.Write("a_scene/camera.yaml", CameraText(200));
  WriteImage(dir, "a_scene/rgb/000000.jpg", 8, 6);
  WriteImage(dir, "b_scene/rgb/000001.png", 8, 6);
  WriteImage(dir, "b_scene/rgb/000000.png", 8, 6);
  WriteDepth(dir, "b_scene/depth/000000.png", 8, 6);
  WriteImage(dir, "b_scene/floor/000001.png", 8, 6);
  dir.Write("b_scene/truth.yaml",
            "frames:\n  - {file: 000001.png, pitch: 0.1, yaw: 0.2, offset: 0.3, width: 2.5, "
            "camera_height: 0.5}\n  - {file: 999999.png, pitch: 0, yaw: 0, offset: 0, width: 1, "
            "camera_height: 0.5}\n");
  dir.Write("not_a_scene/readme.txt", "no rgb here");
  dir.Write("notes.txt", "a file at the top");
}

TEST(DatasetTest, LoadsScenesWithSharedCamera) {
  TestDir dir;
  MakeDataset(dir);
  EXPECT_TRUE(IsDatasetRoot(dir.root().string()));
  std::vector<DatasetScene> scenes;
  const Status status = LoadDataset(dir.root().string(), &scenes);
  ASSERT_TRUE(status.ok()) << status.ToString();
  ASSERT_EQ(scenes.size(), 2u);

  const DatasetScene& a = scenes[0];
  EXPECT_EQ(a.name, "a_scene");
  EXPECT_EQ(a.camera_path, dir.Path("a_scene/camera.yaml"));
  EXPECT_EQ(a.camera.fx, 200.0);
  ASSERT_EQ(a.frames.size(), 1u);
  EXPECT_EQ(a.frames[0].name, "000000");
  EXPECT_EQ(a.frames[0].rgb_path, dir.Path("a_scene/rgb/000000.jpg"));
  EXPECT_TRUE(a.frames[0].depth_path.empty());
  EXPECT_FALSE(a.frames[0].has_truth);

  const DatasetScene& b = scenes[1];
  EXPECT_EQ(b.name, "b_scene");
  EXPECT_EQ(b.dir, dir.Path("b_scene"));
  EXPECT_EQ(b.camera_path, dir.Path("camera.yaml"));
  EXPECT_EQ(b.camera.fx, 100.0);
  EXPECT_EQ(b.camera.mount_height, 0.5);
  ASSERT_EQ(b.frames.size(), 2u);
  EXPECT_EQ(b.frames[0].name, "000000");
  EXPECT_EQ(b.frames[0].depth_path, dir.Path("b_scene/depth/000000.png"));
  EXPECT_TRUE(b.frames[0].floor_mask_path.empty());
  EXPECT_FALSE(b.frames[0].has_truth);
  EXPECT_EQ(b.frames[1].name, "000001");
  EXPECT_TRUE(b.frames[1].depth_path.empty());
  EXPECT_EQ(b.frames[1].floor_mask_path, dir.Path("b_scene/floor/000001.png"));
  ASSERT_TRUE(b.frames[1].has_truth);
  EXPECT_EQ(b.frames[1].truth.file, "000001.png");
  EXPECT_EQ(b.frames[1].truth.geometry.pitch, 0.1);
  EXPECT_EQ(b.frames[1].truth.geometry.width, 2.5);
}

TEST(DatasetTest, RootWithRgbIsOneScene) {
  TestDir dir;
  dir.Write("corridor7/camera.yaml", CameraText(150));
  WriteImage(dir, "corridor7/rgb/frame.png", 8, 6);
  const std::string root = dir.Path("corridor7") + "/";  // A trailing slash still names it.
  EXPECT_TRUE(IsDatasetRoot(root));
  std::vector<DatasetScene> scenes;
  ASSERT_TRUE(LoadDataset(root, &scenes).ok());
  ASSERT_EQ(scenes.size(), 1u);
  EXPECT_EQ(scenes[0].name, "corridor7");
  EXPECT_EQ(scenes[0].camera.fx, 150.0);
  ASSERT_EQ(scenes[0].frames.size(), 1u);
  EXPECT_EQ(scenes[0].frames[0].name, "frame");
}

TEST(DatasetTest, MissingCameraNamesBothPaths) {
  TestDir dir;
  WriteImage(dir, "s/rgb/0.png", 8, 6);
  std::vector<DatasetScene> scenes;
  const Status status = LoadDataset(dir.root().string(), &scenes);
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_TRUE(Contains(status.message(), dir.Path("s/camera.yaml"))) << status.message();
  EXPECT_TRUE(Contains(status.message(), dir.Path("camera.yaml"))) << status.message();
}

TEST(DatasetTest, BadYamlNamesTheFile) {
  TestDir dir;
  WriteImage(dir, "s/rgb/0.png", 8, 6);
  dir.Write("s/camera.yaml", "image_width: [\n");
  std::vector<DatasetScene> scenes;
  Status status = LoadDataset(dir.root().string(), &scenes);
  EXPECT_TRUE(Contains(status.message(), dir.Path("s/camera.yaml"))) << status.message();
  dir.Write("s/camera.yaml", CameraText(100));
  dir.Write("s/truth.yaml", "frames:\n  - {file: 0.png}\n");
  status = LoadDataset(dir.root().string(), &scenes);
  EXPECT_TRUE(Contains(status.message(), dir.Path("s/truth.yaml"))) << status.message();
  EXPECT_TRUE(Contains(status.message(), "frames[0].pitch")) << status.message();
}

TEST(DatasetTest, MissingOrEmptyRoot) {
  TestDir dir;
  std::vector<DatasetScene> scenes;
  Status status = LoadDataset(dir.Path("nope"), &scenes);
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_TRUE(Contains(status.message(), dir.Path("nope")));
  dir.Write("just/a/file.txt", "x");
  status = LoadDataset(dir.root().string(), &scenes);
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_TRUE(Contains(status.message(), "no scenes")) << status.message();
  EXPECT_FALSE(IsDatasetRoot(dir.root().string()));
  EXPECT_FALSE(IsDatasetRoot(dir.Path("nope")));
}

TEST(DatasetTest, DuplicateFrameNamesAreAnError) {
  TestDir dir;
  dir.Write("camera.yaml", CameraText(100));
  WriteImage(dir, "s/rgb/0.png", 8, 6);
  WriteImage(dir, "s/rgb/0.jpg", 8, 6);
  std::vector<DatasetScene> scenes;
  const Status status = LoadDataset(dir.root().string(), &scenes);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(Contains(status.message(), "'0'")) << status.message();
}

TEST(DatasetTest, DepthSizeMismatchNamesTheDepthFile) {
  TestDir dir;
  dir.Write("camera.yaml", CameraText(100));
  WriteImage(dir, "s/rgb/0.png", 8, 6);
  WriteDepth(dir, "s/depth/0.png", 4, 3);
  std::vector<DatasetScene> scenes;
  ASSERT_TRUE(LoadDataset(dir.root().string(), &scenes).ok());
  const DatasetFrame& frame = scenes[0].frames[0];
  cv::Mat bgr, depth;
  ASSERT_TRUE(ReadColorImage(frame.rgb_path, &bgr).ok());
  ASSERT_TRUE(ReadDepthPng(frame.depth_path, &depth).ok());
  const Status status = CheckDepthMatchesImage(frame.depth_path, bgr.size(), depth);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(status.message(),
            "depth image " + dir.Path("s/depth/0.png") + " is 4x3 but its colour image is 8x6");
  EXPECT_TRUE(CheckDepthMatchesImage("x.png", cv::Size(4, 3), depth).ok());
}

TEST(DatasetTest, ListImagesFiltersAndSorts) {
  TestDir dir;
  dir.Write("imgs/b.PNG", "x");
  dir.Write("imgs/a.jpg", "x");
  dir.Write("imgs/d.tiff", "x");
  dir.Write("imgs/c.txt", "x");
  dir.Write("imgs/.hidden.tmp-1-0.png", "x");
  std::filesystem::create_directories(dir.Path("imgs/e.png"));
  std::vector<std::string> paths;
  ASSERT_TRUE(ListImages(dir.Path("imgs"), &paths).ok());
  const std::vector<std::string> expected = {dir.Path("imgs/a.jpg"), dir.Path("imgs/b.PNG"),
                                             dir.Path("imgs/d.tiff")};
  EXPECT_EQ(paths, expected);
}

TEST(DatasetTest, ListImagesErrorsNameTheFolder) {
  TestDir dir;
  std::vector<std::string> paths;
  Status status = ListImages(dir.Path("missing"), &paths);
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_TRUE(Contains(status.message(), dir.Path("missing")));
  dir.Write("only_text/readme.txt", "x");
  status = ListImages(dir.Path("only_text"), &paths);
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_TRUE(Contains(status.message(), dir.Path("only_text")) &&
              Contains(status.message(), "no images"))
      << status.message();
}

TEST(DatasetTest, MakeSceneDirs) {
  TestDir dir;
  std::string rgb, depth;
  ASSERT_TRUE(MakeSceneDirs(dir.Path("out"), "s1", &rgb, &depth).ok());
  EXPECT_EQ(rgb, dir.Path("out/s1/rgb"));
  EXPECT_EQ(depth, dir.Path("out/s1/depth"));
  EXPECT_TRUE(std::filesystem::is_directory(rgb));
  EXPECT_TRUE(std::filesystem::is_directory(depth));
  ASSERT_TRUE(MakeSceneDirs(dir.Path("out"), "s1", &rgb, &depth).ok());  // Idempotent.
  EXPECT_EQ(MakeSceneDirs(dir.Path("out"), "a/b", &rgb, &depth).code(),
            StatusCode::kInvalidArgument);
  EXPECT_EQ(MakeSceneDirs(dir.Path("out"), "", &rgb, &depth).code(),
            StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace corridor
