// The predicted floor against the hand-labelled floor masks of the real photographs, with the
// intrinsics their README gives and the 1.0 m camera height their source assumes; and against
// the generator's floor on synthetic frames; and a plausible geometry on all eleven photos.
#include "pipeline/floor_mask.h"

#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "corridor_depth/recover_depth.h"
#include "synth/corridor_renderer.h"
#include "synth/presets.h"

namespace corridor {
namespace {

const std::string kDir = std::string(CORRIDOR_SOURCE_DIR) + "/tests/data/real-corridors/";

Camera PhotoCamera(int width, int height, double fx, double fy, double cx, double cy) {
  Camera c;
  c.image_width = width;
  c.image_height = height;
  c.fx = fx;
  c.fy = fy;
  c.cx = cx;
  c.cy = cy;
  c.mount_height = 1.0;
  return c;
}

TEST(FloorMaskTest, IoUOnTheLabelledPhotos) {
  struct Labelled {
    const char* name;
    Camera camera;
    double min_iou;  // The lowest IoU accepted (docs/results.md gives the measured ones).
  };
  const Labelled photos[] = {
      {"popup_1", PhotoCamera(640, 512, 371.975, 372.164, 315.632, 250.593), 0.75},
      {"popup_2", PhotoCamera(640, 480, 570.342, 570.342, 319.5, 239.5), 0.85},
      {"popup_3", PhotoCamera(640, 480, 570.342, 570.342, 319.5, 239.5), 0.75},
  };
  for (const auto& photo : photos) {
    const cv::Mat image = cv::imread(kDir + photo.name + ".png");
    const cv::Mat label = cv::imread(kDir + photo.name + "_floor.png", cv::IMREAD_GRAYSCALE);
    ASSERT_FALSE(image.empty());
    ASSERT_FALSE(label.empty());
    // The geometry's floor, whatever the frame's confidence (popup_3's right junction is a few
    // percent of the height off, and the default confidence threshold refuses it).
    RecoverDepthOptions options;
    options.min_confidence = 0;
    RecoverDepthResult result;
    ASSERT_TRUE(RecoverDepth(image, photo.camera, options, &result).ok())
        << photo.name << ": " << result.status.ToString();
    const double iou = MaskIoU(PredictFloorMask(photo.camera, result.geometry), label);
    std::printf("%s floor IoU %.3f\n", photo.name, iou);
    EXPECT_GE(iou, photo.min_iou) << photo.name;
  }
}

TEST(FloorMaskTest, TrueGeometryGivesTheGeneratorsFloor) {
  const auto preset = synth::PaperPreset()[0];
  synth::Frame frame;
  ASSERT_TRUE(synth::RenderFrame(preset.scene, preset.camera, preset.poses[0], &frame).ok());
  // The generator's floor: pixels whose true depth equals the floor's, h / (n.r), by hand.
  const CorridorGeometry& g = frame.truth;
  cv::Mat truth(frame.depth.size(), CV_8U, cv::Scalar(0));
  for (int v = 0; v < truth.rows; ++v) {
    for (int u = 0; u < truth.cols; ++u) {
      const double y = (v - preset.camera.cy) / preset.camera.fy;
      const double nr = std::cos(g.pitch) * y + std::sin(g.pitch);
      const float z = frame.depth.at<float>(v, u);
      if (nr > 0 && std::abs(z - g.camera_height / nr) < 1e-3 * z && z <= 40) truth.at<uchar>(v, u) = 255;
    }
  }
  EXPECT_GT(MaskIoU(PredictFloorMask(preset.camera, g), truth), 0.97);
}

// With an end wall 8 m ahead, the floor stops there: the generator's floor pixels (true depth =
// the floor's, by hand) are the prediction's.
TEST(FloorMaskTest, AnEndWallEndsTheFloor) {
  synth::SceneOptions scene;
  scene.length = 10;
  scene.clutter = 0;
  scene.door_density = 0;
  const Camera camera = synth::PaperCamera(0.66);
  const synth::CameraPose pose{0.08, 0.05, 0.1, 0.66, 2.0};
  synth::Frame frame;
  ASSERT_TRUE(synth::RenderFrame(scene, camera, pose, &frame).ok());
  CorridorGeometry g = frame.truth;
  cv::Mat truth(frame.depth.size(), CV_8U, cv::Scalar(0));
  for (int v = 0; v < truth.rows; ++v) {
    for (int u = 0; u < truth.cols; ++u) {
      const double y = (v - camera.cy) / camera.fy;
      const double nr = std::cos(g.pitch) * y + std::sin(g.pitch);  // Floor normal (0, c, s).
      const float z = frame.depth.at<float>(v, u);
      if (nr > 0 && std::abs(z - g.camera_height / nr) < 1e-3 * z) truth.at<uchar>(v, u) = 255;
    }
  }
  const double open = MaskIoU(PredictFloorMask(camera, g), truth);
  g.end_distance = scene.length - pose.distance;
  const double closed = MaskIoU(PredictFloorMask(camera, g), truth);
  std::printf("floor IoU without the end wall %.3f, with it %.3f\n", open, closed);
  EXPECT_GT(closed, 0.97);
  EXPECT_GT(closed, open + 0.01);
}

// A plausible corridor on all eleven photographs, through the whole pipeline with the same cameras
// (rtabmap_*: a 60-degree field of view) and a 1.0 m camera height: both junctions on at least
// 10 of the 11, each with a width between 1 and 6 m and a pitch within +-20 degrees.
TEST(RealPhotosGeometryTest, BothJunctionsAndAPlausibleCorridorOnTenOfEleven) {
  std::vector<std::pair<std::string, Camera>> photos = {
      {"popup_1.png", PhotoCamera(640, 512, 371.975, 372.164, 315.632, 250.593)},
      {"popup_2.png", PhotoCamera(640, 480, 570.342, 570.342, 319.5, 239.5)},
      {"popup_3.png", PhotoCamera(640, 480, 570.342, 570.342, 319.5, 239.5)}};
  for (int i = 1; i <= 8; ++i) {
    const std::string name = "rtabmap_" + std::to_string(i) + ".jpg";
    const cv::Mat image = cv::imread(kDir + name);
    ASSERT_FALSE(image.empty()) << name;
    photos.emplace_back(name, Camera::FromHorizontalFov(image.cols, image.rows, M_PI / 3, 1.0));
  }
  int good = 0;
  for (const auto& [name, camera] : photos) {
    const cv::Mat image = cv::imread(kDir + name);
    ASSERT_FALSE(image.empty()) << name;
    RecoverDepthResult result;
    RecoverDepth(image, camera, RecoverDepthOptions(), &result);
    const CorridorGeometry& g = result.geometry;
    // Both junction lines found and used: not one line and a known width (junctions.status) nor a
    // held width. A wall the ceiling moved (a baseboard or inner-line note) still comes from both.
    const bool both = result.status.ok() && result.junctions.status.ok() && !result.width_held;
    const bool plausible = g.width >= 1.0 && g.width <= 6.0 && std::abs(g.pitch) <= M_PI / 9;
    std::printf("%-14s %s width %.2f m pitch %.1f deg\n", name.c_str(),
                both ? "both junctions" : result.status.ToString().c_str(), g.width,
                g.pitch * 180 / M_PI);
    good += both && plausible;
  }
  EXPECT_GE(good, 10);
}

}  // namespace
}  // namespace corridor
