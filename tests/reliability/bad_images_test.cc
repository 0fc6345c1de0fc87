// Bad images: tiny (1x1, 4x4) and absurd (20000x10) sizes; 16-bit colour, alpha and grey
// corridors (which must work); all black, all white, noise and non-corridor scenes (a brick wall
// close up, an outdoor scene), which must be "no corridor found" with no depth. Through
// RecoverDepth and through corridor_depth.

#include <gtest/gtest.h>

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "corridor_depth/recover_depth.h"
#include "tests/reliability/reliability_util.h"
#include "tests/support/outdoor_scene.h"

namespace corridor {
namespace {

using testing_util::ExpectCleanExit;
using testing_util::ListFiles;
using testing_util::ReliabilityCamera;
using testing_util::ReliabilityGeometry;
using testing_util::RunDepthTool;
using testing_util::ScratchDir;

cv::Mat Corridor() {
  return testing_util::RenderTestCorridor(ReliabilityCamera(), ReliabilityGeometry());
}

// A brick wall seen head-on from close by: only horizontal and vertical edges.
cv::Mat WallCloseUp() {
  cv::Mat image(240, 320, CV_8UC3, cv::Scalar(60, 70, 150));
  for (int row = 0; row * 20 < 240; ++row) {
    cv::line(image, {0, row * 20}, {319, row * 20}, cv::Scalar(190, 190, 190), 2);
    for (int u = (row % 2) * 25; u < 320; u += 50) {
      cv::line(image, {u, row * 20}, {u, row * 20 + 20}, cv::Scalar(190, 190, 190), 2);
    }
  }
  cv::Mat noise(image.size(), CV_8UC3);
  cv::RNG(5).fill(noise, cv::RNG::NORMAL, 0, 6);
  return image + noise;
}

cv::Mat Noise() {
  cv::Mat image(240, 320, CV_8UC3);
  cv::RNG(9).fill(image, cv::RNG::UNIFORM, 0, 256);
  return image;
}

struct NotACorridor {
  const char* name;
  cv::Mat image;
};

std::vector<NotACorridor> NotCorridors() {
  return {{"black", cv::Mat(240, 320, CV_8UC3, cv::Scalar::all(0))},
          {"white", cv::Mat(240, 320, CV_8UC3, cv::Scalar::all(255))},
          {"noise", Noise()},
          {"wall", WallCloseUp()},
          {"outdoor", testing_util::OutdoorScene(127)},
          {"tiny_1x1", cv::Mat(1, 1, CV_8UC3, cv::Scalar(90, 90, 90))},
          {"tiny_4x4", cv::Mat(4, 4, CV_8UC3, cv::Scalar(90, 90, 90))},
          {"wide_20000x10", cv::Mat(10, 20000, CV_8UC3, cv::Scalar(90, 90, 90))}};
}

// The camera that belongs to an image of any size: 90 degrees horizontal field of view.
Camera CameraFor(const cv::Mat& image) {
  return Camera::FromHorizontalFov(image.cols, image.rows, M_PI / 2, 1.2);
}

TEST(BadImages, LibrarySaysNoCorridorFoundAndGivesNoDepth) {
  for (const NotACorridor& bad : NotCorridors()) {
    RecoverDepthResult result;
    const Status status =
        RecoverDepth(bad.image, CameraFor(bad.image), RecoverDepthOptions(), &result);
    EXPECT_EQ(status.code(), StatusCode::kNoCorridorFound) << bad.name << ": " << status.ToString();
    EXPECT_FALSE(status.message().empty()) << bad.name;
    EXPECT_TRUE(result.depth.empty()) << bad.name;
    EXPECT_FALSE(result.has_geometry) << bad.name;
  }
}

TEST(BadImages, ToolReportsTheFrameAndWritesNoDepth) {
  for (const NotACorridor& bad : NotCorridors()) {
    SCOPED_TRACE(bad.name);
    ScratchDir dir;
    dir.WriteCamera("in/camera.yaml", CameraFor(bad.image));
    const std::string path = dir.WriteImage(std::string("in/") + bad.name + ".png", bad.image);
    const auto run = RunDepthTool(path, dir.Path("out"), dir);
    ExpectCleanExit(run, 1, {path, "no corridor found"});
    EXPECT_TRUE(ListFiles(dir.Path("out/in/depth")).empty());
  }
}

// The same corridor in the formats the readers accept; each must give the corridor's width.
struct Variant {
  const char* name;
  cv::Mat image;
};

std::vector<Variant> Variants() {
  const cv::Mat bgr = Corridor();
  cv::Mat sixteen, bgra, grey, grey_alpha;
  bgr.convertTo(sixteen, CV_16UC3, 257.0);
  cv::cvtColor(bgr, bgra, cv::COLOR_BGR2BGRA);
  bgra.forEach<cv::Vec4b>([](cv::Vec4b& p, const int* pos) { p[3] = pos[1] % 2 ? 255 : 128; });
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::Mat alpha(grey.size(), CV_8UC1, cv::Scalar(200));
  cv::merge(std::vector<cv::Mat>{grey, alpha}, grey_alpha);
  return {{"bgr", bgr}, {"sixteen_bit", sixteen}, {"alpha", bgra}, {"grey", grey}, {"grey_alpha", grey_alpha}};
}

TEST(BadImages, LibraryRecoversSixteenBitAlphaAndGreyCorridors) {
  const Camera camera = ReliabilityCamera();
  for (const Variant& variant : Variants()) {
    RecoverDepthResult result;
    const Status status = RecoverDepth(variant.image, camera, RecoverDepthOptions(), &result);
    ASSERT_TRUE(status.ok()) << variant.name << ": " << status.ToString();
    EXPECT_NEAR(result.geometry.width, ReliabilityGeometry().width, 0.25) << variant.name;
    EXPECT_EQ(result.depth.size(), cv::Size(camera.image_width, camera.image_height));
  }
}

TEST(BadImages, ToolRecoversSixteenBitAlphaAndGreyCorridors) {
  ScratchDir dir;
  dir.WriteCamera("in/camera.yaml", ReliabilityCamera());
  for (const Variant& variant : Variants()) {
    if (variant.image.channels() == 2) continue;  // PNG writers of OpenCV take 1, 3 or 4.
    dir.WriteImage(std::string("in/") + variant.name + ".png", variant.image);
  }
  const auto run = RunDepthTool(dir.Path("in"), dir.Path("out"), dir);
  ExpectCleanExit(run, 0, {});
  for (const char* name : {"bgr", "sixteen_bit", "alpha", "grey"}) {
    EXPECT_TRUE(testing_util::Exists(dir.Path(std::string("out/in/depth/") + name + ".png")))
        << name;
  }
}

}  // namespace
}  // namespace corridor
