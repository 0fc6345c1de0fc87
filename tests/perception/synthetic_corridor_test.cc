// The detector on frames of the generator (an independent ray caster): the detected junctions
// against the true ones, projected by hand from the frame's truth.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "perception/junction_detector.h"
#include "synth/corridor_renderer.h"
#include "synth/presets.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

// The angle (degrees) between a found line and the true one, and the larger distance (px) of the
// found line's support ends from the true line.
std::pair<double, double> LineError(const Eigen::Vector3d& truth, const JunctionLine& found) {
  const double angle_deg =
      std::acos(std::min(1.0, std::abs(truth.head<2>().dot(found.line.head<2>())))) * 180 / M_PI;
  const double offset_px = std::max(std::abs(truth.dot(found.near_end.homogeneous())),
                                    std::abs(truth.dot(found.far_end.homogeneous())));
  return {angle_deg, offset_px};
}

// Easy scenes of the paper preset, first and last frame of each: most lines within 1.5 degrees
// and 3 px of the truth at both ends of their support, none grossly off (measured: 21 of 24
// close; the misses are near-field baseboards and a door beside the camera).
TEST(SyntheticCorridorTest, DetectedJunctionsMatchTheTrueOnes) {
  int checked = 0, close = 0;
  for (const auto& preset : synth::PaperPreset()) {
    if (preset.name.find("_E") == std::string::npos) continue;
    const synth::CorridorScene scene = synth::BuildScene(preset.scene);
    for (size_t f : {size_t{0}, preset.poses.size() - 1}) {
      synth::Frame frame;
      ASSERT_TRUE(synth::RenderFrame(scene, preset.camera, preset.poses[f], &frame).ok());
      JunctionPair pair;
      ASSERT_TRUE(DetectJunctions(frame.bgr, JunctionDetectorOptions(), &pair).ok());
      ASSERT_TRUE(pair.status.ok()) << preset.name << " " << f << ": " << pair.status.ToString();
      for (int side = -1; side <= 1; side += 2) {
        const Eigen::Vector3d truth = testing_util::TrueJunction(frame.truth, preset.camera, side);
        const auto [angle_deg, offset_px] = LineError(truth, side < 0 ? pair.left : pair.right);
        EXPECT_LT(angle_deg, 8.0) << preset.name << " frame " << f << " side " << side;
        close += angle_deg < 1.5 && offset_px < 3.0;
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 24);
  EXPECT_GE(close, 20);
}

// 1280x720 frames, their lines found at the working resolution (halved to 640 px) and at full
// resolution: the halved search finds about as many junctions within 1 degree and 4 px of the
// truth (at both ends of their support) as the full one, and most of them.
TEST(SyntheticCorridorTest, WorkingResolutionKeepsTheLinesOfLargeImages) {
  const Camera camera = Camera::FromHorizontalFov(1280, 720, 85.0 * M_PI / 180, 0.7);
  JunctionDetectorOptions full, halved;
  full.max_work_width = 0;
  ASSERT_EQ(halved.max_work_width, 640);
  int close[2] = {0, 0}, total = 0;
  for (const uint32_t seed : {7u, 8u}) {
    synth::SceneOptions scene;
    scene.width = seed == 7 ? 2.4 : 2.0;
    scene.clutter = 0.1;
    scene.seed = seed;
    const synth::CorridorScene built = synth::BuildScene(scene);
    for (const double yaw : {-0.06, 0.0, 0.05}) {
      const synth::CameraPose pose{0.05, yaw, 0.2, 0.7, 3.0};
      synth::Frame frame;
      ASSERT_TRUE(synth::RenderFrame(built, camera, pose, &frame).ok());
      for (int k = 0; k < 2; ++k) {
        JunctionPair found;
        ASSERT_TRUE(DetectJunctions(frame.bgr, k == 0 ? full : halved, &found).ok());
        if (!found.status.ok()) continue;
        for (int side = -1; side <= 1; side += 2) {
          const Eigen::Vector3d truth = testing_util::TrueJunction(frame.truth, camera, side);
          const auto [angle_deg, offset_px] =
              LineError(truth, side < 0 ? found.left : found.right);
          close[k] += angle_deg < 1.0 && offset_px < 4.0;
        }
      }
      total += 2;
    }
  }
  std::printf("within 1 deg and 4 px: full resolution %d, halved %d, of %d\n", close[0], close[1],
              total);
  EXPECT_GE(close[1], close[0] - 1);
  EXPECT_GE(close[1], total * 3 / 4);
}

// A caller's halving of the whole image (shared with the ceiling and end-wall searches) gives
// exactly the lines of the detector's own halving of the search region: the region's rows do not
// see the crop's border. Sizes 1280x720 (halved once) and 2560x1440 (twice).
TEST(SyntheticCorridorTest, ACallersHalvedImageGivesTheSameLines) {
  for (const int width : {1280, 2560}) {
    const Camera camera = Camera::FromHorizontalFov(width, width * 9 / 16, 85.0 * M_PI / 180, 0.7);
    synth::SceneOptions scene;
    scene.clutter = 0.1;
    synth::Frame frame;
    ASSERT_TRUE(synth::RenderFrame(synth::BuildScene(scene), camera,
                                   synth::CameraPose{0.05, 0.03, 0.2, 0.7, 3.0}, &frame)
                    .ok());
    cv::Mat halved = frame.bgr;
    for (int w = width; w > 640; w = (w + 1) / 2) cv::pyrDown(halved, halved);
    JunctionPair own, shared;
    ASSERT_TRUE(DetectJunctions(frame.bgr, JunctionDetectorOptions(), &own).ok());
    ASSERT_TRUE(DetectJunctions(frame.bgr, halved, JunctionDetectorOptions(), &shared).ok());
    ASSERT_TRUE(own.status.ok()) << own.status.ToString();
    ASSERT_TRUE(shared.status.ok()) << shared.status.ToString();
    EXPECT_EQ(own.segments.size(), shared.segments.size()) << width;
    EXPECT_EQ(own.left.line, shared.left.line) << width;
    EXPECT_EQ(own.right.line, shared.right.line) << width;
    EXPECT_EQ(own.vanishing_point, shared.vanishing_point) << width;
  }
}

// A junction broken into short pieces by door bottoms (CorridorWithBrokenRightJunction): the
// first Hough finds no right candidate, and the second, relaxed look finds the pieces and merges
// them into the junction. Truth: the generator's walls, projected by hand.
TEST(SyntheticCorridorTest, AJunctionBrokenByDoorBottomsIsFoundOnASecondLook) {
  const Camera camera = Camera::FromHorizontalFov(640, 480, 80.0 * M_PI / 180, 1.2);
  const synth::Frame frame =
      testing_util::CorridorWithBrokenRightJunction(camera, {0.05, 0.03, 0.1, 1.2, 2.0});
  ASSERT_FALSE(frame.bgr.empty());
  const Eigen::Vector3d left_truth = testing_util::TrueJunction(frame.truth, camera, -1);
  const Eigen::Vector3d right_truth = testing_util::TrueJunction(frame.truth, camera, 1);
  JunctionDetectorOptions first_only;
  first_only.relaxed_hough_threshold = 0;
  JunctionPair first;
  ASSERT_TRUE(DetectJunctions(frame.bgr, first_only, &first).ok());
  EXPECT_FALSE(first.status.ok()) << "the broken junction is found without the second look";
  JunctionPair pair;
  ASSERT_TRUE(DetectJunctions(frame.bgr, JunctionDetectorOptions(), &pair).ok());
  ASSERT_TRUE(pair.status.ok()) << pair.status.ToString();
  EXPECT_TRUE(pair.relaxed_hough);
  const auto [left_angle, left_offset] = LineError(left_truth, pair.left);
  const auto [right_angle, right_offset] = LineError(right_truth, pair.right);
  std::printf("left %.2f deg %.2f px, right %.2f deg %.2f px\n", left_angle, left_offset,
              right_angle, right_offset);
  EXPECT_LT(left_angle, 0.5);
  EXPECT_LT(left_offset, 2.0);
  EXPECT_LT(right_angle, 0.5);
  EXPECT_LT(right_offset, 2.0);
}

// The second look is only for frames the first one cannot pair: an intact corridor keeps the
// first look's lines.
TEST(SyntheticCorridorTest, TheSecondLookLeavesAFoundPairAlone) {
  const Camera camera = Camera::FromHorizontalFov(640, 480, 80.0 * M_PI / 180, 1.2);
  const synth::Frame frame =
      testing_util::RenderCorridorFrame(camera, 2.2, 2.8, 5, {0.05, 0.03, 0.1, 1.2, 2.0}, 0.0);
  JunctionDetectorOptions first_only;
  first_only.relaxed_hough_threshold = 0;
  JunctionPair first, pair;
  ASSERT_TRUE(DetectJunctions(frame.bgr, first_only, &first).ok());
  ASSERT_TRUE(DetectJunctions(frame.bgr, JunctionDetectorOptions(), &pair).ok());
  ASSERT_TRUE(first.status.ok()) << first.status.ToString();
  EXPECT_FALSE(pair.relaxed_hough);
  EXPECT_EQ(first.left.line, pair.left.line);
  EXPECT_EQ(first.right.line, pair.right.line);
}

TEST(SyntheticCorridorTest, AHalvedImageOfTheWrongSizeIsRejected) {
  const Camera camera = Camera::FromHorizontalFov(1280, 720, 85.0 * M_PI / 180, 0.7);
  synth::Frame frame;
  ASSERT_TRUE(synth::RenderFrame(synth::BuildScene(synth::SceneOptions()), camera,
                                 synth::CameraPose{0.05, 0.0, 0.2, 0.7, 3.0}, &frame)
                  .ok());
  cv::Mat wrong;
  cv::resize(frame.bgr, wrong, cv::Size(600, 360));
  JunctionPair pair;
  const Status status = DetectJunctions(frame.bgr, wrong, JunctionDetectorOptions(), &pair);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(status.message().find("halved image"), std::string::npos) << status.ToString();
}

TEST(SyntheticCorridorTest, WorkingWidthBelowTwiceTheSmallestImageIsRejected) {
  JunctionDetectorOptions options;
  options.max_work_width = 20;
  std::string why;
  EXPECT_FALSE(options.Check(&why));
  EXPECT_NE(why.find("max_work_width"), std::string::npos) << why;
  options.max_work_width = 0;
  EXPECT_TRUE(options.Check(&why));
}

}  // namespace
}  // namespace corridor
