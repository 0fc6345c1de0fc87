// corridor_depth's --write_cloud and video input: PLY files read back by a parser
// written here, and their points lie on the ray caster's corridor; a video written with OpenCV's
// VideoWriter goes through the tool like its decoded frames in a folder.

#include <algorithm>
#include <cstring>
#include <opencv2/videoio.hpp>

#include "tests/robotics/robotics_test_data.h"

namespace corridor {
namespace testing_util {
namespace {

// A binary little-endian PLY of x y z float + red green blue uchar, parsed here.
struct Ply {
  std::vector<cv::Point3f> points;
  std::vector<cv::Vec3b> rgb;
};

bool ReadPly(const std::string& path, Ply* ply, std::string* why) {
  const std::string bytes = ReadAll(path);
  const size_t end = bytes.find("end_header\n");
  if (bytes.rfind("ply\nformat binary_little_endian 1.0\n", 0) != 0 || end == std::string::npos) {
    *why = "not a binary little-endian PLY";
    return false;
  }
  const std::string header = bytes.substr(0, end);
  const std::string expected_props =
      "property float x\nproperty float y\nproperty float z\nproperty uchar red\n"
      "property uchar green\nproperty uchar blue\n";
  if (header.find(expected_props) == std::string::npos) {
    *why = "unexpected properties:\n" + header;
    return false;
  }
  const size_t at = header.find("element vertex ");
  const size_t n = std::stoul(header.substr(at + 15));
  const size_t body = end + std::strlen("end_header\n");
  if (bytes.size() != body + 15 * n) {
    *why = "size " + std::to_string(bytes.size()) + " does not hold " + std::to_string(n) + " vertices";
    return false;
  }
  for (size_t i = 0; i < n; ++i) {
    const char* p = bytes.data() + body + 15 * i;
    float xyz[3];
    std::memcpy(xyz, p, 12);  // This host is little-endian, as the file says.
    ply->points.emplace_back(xyz[0], xyz[1], xyz[2]);
    ply->rgb.emplace_back(static_cast<uchar>(p[12]), static_cast<uchar>(p[13]),
                          static_cast<uchar>(p[14]));
  }
  return true;
}

TEST(PointCloudTest, PlyPointsLieOnTheRayCastCorridor) {
  ScratchDir dir;
  const TestFrames frames = MakeTestFrames();
  for (size_t i = 0; i < frames.images.size(); ++i) {
    dir.WriteImage("frames/" + std::to_string(i) + ".png", frames.images[i]);
  }
  dir.WriteCamera("frames/camera.yaml", frames.camera);
  const ToolRun run = RunDepthTool(dir.Path("frames"), dir.Path("out"), dir, {"--write_cloud"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (size_t i = 0; i < frames.images.size(); ++i) {
    SCOPED_TRACE(i);
    Ply ply;
    std::string why;
    ASSERT_TRUE(ReadPly(dir.Path("out/frames/cloud/" + std::to_string(i) + ".ply"), &ply, &why))
        << why;
    const cv::Mat png = ReadDepthMm(dir.Path("out/frames/depth/" + std::to_string(i) + ".png"));
    ASSERT_EQ(ply.points.size(), static_cast<size_t>(cv::countNonZero(png)));
    const Camera& c = frames.camera;
    std::vector<double> errors;
    for (size_t k = 0; k < ply.points.size(); ++k) {
      const cv::Point3f& p = ply.points[k];
      ASSERT_GT(p.z, 0);
      // The pixel the point came from: its projection.
      const int u = static_cast<int>(std::lround(c.fx * p.x / p.z + c.cx));
      const int v = static_cast<int>(std::lround(c.fy * p.y / p.z + c.cy));
      ASSERT_TRUE(u >= 0 && u < c.image_width && v >= 0 && v < c.image_height) << p;
      EXPECT_NEAR(p.z, png.at<uint16_t>(v, u) * 1e-3, 1e-3) << "point " << k;
      const cv::Vec3b bgr = frames.images[i].at<cv::Vec3b>(v, u);
      EXPECT_EQ(ply.rgb[k], cv::Vec3b(bgr[2], bgr[1], bgr[0])) << "point " << k;
      const float truth = frames.depths[i].at<float>(v, u);
      if (truth > 0) errors.push_back(std::abs(p.z - truth) / truth);
    }
    ASSERT_GT(errors.size(), ply.points.size() * 9 / 10);
    std::sort(errors.begin(), errors.end());
    const double median = errors[errors.size() / 2];
    const double p90 = errors[errors.size() * 9 / 10];
    std::printf(
        "[ cloud    ] frame %zu: %zu points, relative distance to the true surface: "
        "median %.4f, p90 %.4f\n",
        i, ply.points.size(), median, p90);
    EXPECT_LT(median, 0.03);
    EXPECT_LT(p90, 0.08);
  }
}

TEST(VideoInputTest, AVideoGoesThroughTheToolLikeItsFrames) {
  ScratchDir dir;
  const TestFrames frames = MakeTestFrames();
  const std::string video = dir.Path("walk.avi");
  {
    cv::VideoWriter writer(video, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 10.0,
                           frames.images.front().size());
    ASSERT_TRUE(writer.isOpened());
    for (const auto& image : frames.images) writer.write(image);
  }
  const std::string camera = dir.WriteCamera("camera.yaml", frames.camera);
  const ToolRun run = RunDepthTool(video, dir.Path("out_video"), dir, {"--camera=" + camera});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // The frames as OpenCV decodes them, in a folder, named by index.
  cv::VideoCapture capture(video);
  ASSERT_TRUE(capture.isOpened());
  cv::Mat decoded;
  int count = 0;
  while (capture.read(decoded)) {
    char name[16];
    std::snprintf(name, sizeof(name), "%06d.png", count++);
    dir.WriteImage(std::string("decoded/") + name, decoded);
  }
  ASSERT_EQ(count, static_cast<int>(frames.images.size()));
  const ToolRun folder = RunDepthTool(dir.Path("decoded"), dir.Path("out_folder"), dir,
                                      {"--camera=" + camera});
  ASSERT_EQ(folder.exit_code, 0) << folder.err;
  for (int i = 0; i < count; ++i) {
    char name[16];
    std::snprintf(name, sizeof(name), "%06d.png", i);
    const cv::Mat a = ReadDepthMm(dir.Path(std::string("out_video/walk/depth/") + name));
    const cv::Mat b = ReadDepthMm(dir.Path(std::string("out_folder/decoded/depth/") + name));
    ASSERT_FALSE(a.empty()) << name;
    ASSERT_FALSE(b.empty()) << name;
    EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0) << name;
  }
  EXPECT_FALSE(Exists(dir.Path("out_video/walk/depth/000003.png")));
}

TEST(VideoInputTest, BadVideosGetAClearMessage) {
  ScratchDir dir;
  const TestFrames frames = MakeTestFrames();
  const std::string camera = dir.WriteCamera("camera.yaml", frames.camera);
  const std::string text = dir.Write("notes.avi", "not a video at all\n");
  ExpectCleanExit(RunDepthTool(text, dir.Path("out"), dir, {"--camera=" + camera}), 2, {text});
  const std::string video = dir.Path("walk.avi");
  {
    cv::VideoWriter writer(video, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 10.0,
                           frames.images.front().size());
    for (const auto& image : frames.images) writer.write(image);
  }
  // No calibration: a video carries none.
  ExpectCleanExit(RunDepthTool(video, dir.Path("out"), dir, {}), 2, {video, "--camera"});
}

}  // namespace
}  // namespace testing_util
}  // namespace corridor
