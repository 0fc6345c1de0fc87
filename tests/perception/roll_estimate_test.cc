// EstimateRoll on frames of the generator's head-mounted class, whose poses carry a roll of up
// to 3 degrees: the roll found against the pose's, and none found on the same frames rendered
// without it, nor on level cameras of other classes, even when the corridor's fit gives them a
// wrong pitch. RollTurn against a rotation
// worked out by hand.
#include "perception/roll_estimate.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "synth/corridor_renderer.h"
#include "synth/real_buildings.h"

namespace corridor {
namespace {

constexpr double kDeg = M_PI / 180.0;

// Scene `scene` of a class of the real-buildings preset with its first `frames` poses.
synth::ScenePreset ClassScene(const char* name, int scene, int frames) {
  synth::RealBuildingsOptions options;
  options.scenes = scene + 1;
  options.frames = frames;
  std::vector<synth::ScenePreset> presets;
  EXPECT_TRUE(synth::RealBuildingsPreset(name, options, &presets).ok());
  return presets.at(scene);
}
synth::ScenePreset HeadScene(int scene, int frames) { return ClassScene("head", scene, frames); }

// Frames 5-10 of the first scene: rolls of -3.0 to 2.8 degrees.
constexpr size_t kFirst = 5, kEnd = 11;

TEST(RollEstimateTest, FindsTheRollOfAHeadMountedCamera) {
  const synth::ScenePreset preset = HeadScene(0, kEnd);
  int found = 0;
  for (size_t i = kFirst; i < kEnd; ++i) {
    synth::Frame frame;
    ASSERT_TRUE(synth::RenderFrame(preset.scene, preset.camera, preset.poses[i], &frame).ok());
    const RollEstimate roll =
        EstimateRoll(frame.bgr, preset.camera, frame.truth, RollEstimateOptions());
    std::printf("frame %zu: true roll %.2f deg, found %d, %.2f deg from %d segments\n", i,
                preset.poses[i].roll / kDeg, roll.found, roll.roll / kDeg, roll.segments);
    if (!roll.found) continue;
    ++found;
    EXPECT_NEAR(roll.roll, preset.poses[i].roll, 0.2 * kDeg) << "frame " << i;
  }
  EXPECT_GE(found, 4);  // The premise: the scene's door frames show the roll.
}

TEST(RollEstimateTest, FindsNoneWithoutRoll) {
  synth::ScenePreset preset = HeadScene(0, kEnd);
  for (size_t i = kFirst; i < kEnd; ++i) {
    synth::CameraPose pose = preset.poses[i];
    pose.roll = 0;
    synth::Frame frame;
    ASSERT_TRUE(synth::RenderFrame(preset.scene, preset.camera, pose, &frame).ok());
    const RollEstimate roll =
        EstimateRoll(frame.bgr, preset.camera, frame.truth, RollEstimateOptions());
    EXPECT_LE(std::abs(roll.roll), 0.3 * kDeg) << "frame " << i;
  }
}

// Rolled head-mounted cameras whose agreeing door frames stand on one wall only (head_s3756
// frames 11, 12 and 18) or on one wall but one (head_s3763 frame 14): spread along that wall,
// they fix the vertical vanishing point alone, less tightly than two walls do (0.4 degrees off on
// frame 12).
TEST(RollEstimateTest, FindsTheRollFromOneWallsVerticals) {
  const struct {
    int scene, frame;
  } cases[] = {{8, 11}, {8, 12}, {8, 18}, {9, 14}};
  for (const auto& c : cases) {
    const synth::ScenePreset preset = HeadScene(c.scene, c.frame + 1);
    const synth::CameraPose& pose = preset.poses[c.frame];
    ASSERT_GT(std::abs(pose.roll), 2.0 * kDeg);  // The premise: a roll worth leveling.
    synth::Frame frame;
    ASSERT_TRUE(synth::RenderFrame(preset.scene, preset.camera, pose, &frame).ok());
    const RollEstimate roll =
        EstimateRoll(frame.bgr, preset.camera, frame.truth, RollEstimateOptions());
    EXPECT_TRUE(roll.found) << "scene " << c.scene << " frame " << c.frame;
    EXPECT_NEAR(roll.roll, pose.roll, 0.5 * kDeg) << "scene " << c.scene << " frame " << c.frame;
  }
}

// Level cameras whose verticals stand mostly on one side (a low robot's door frames, a pillar
// at the image's edge beside a carpet): short segments and an unbalanced pitch tilt, no roll.
TEST(RollEstimateTest, FindsNoneOnLevelCamerasWithOneSidedVerticals) {
  const struct {
    const char* name;
    int scene, frame;
  } cases[] = {{"low", 1, 3}, {"low", 2, 3}, {"carpet", 4, 19}, {"carpet", 3, 12}};
  for (const auto& c : cases) {
    const synth::ScenePreset preset = ClassScene(c.name, c.scene, c.frame + 1);
    synth::Frame frame;
    ASSERT_TRUE(synth::RenderFrame(preset.scene, preset.camera, preset.poses[c.frame], &frame).ok());
    ASSERT_EQ(preset.poses[c.frame].roll, 0.0);
    for (const double error : {-1.0, 0.0, 1.0}) {
      CorridorGeometry fit = frame.truth;
      fit.pitch += error * kDeg;
      const RollEstimate roll = EstimateRoll(frame.bgr, preset.camera, fit, RollEstimateOptions());
      std::printf("%s %d/%d pitch %+.0f: found %d, %.2f deg\n", c.name, c.scene, c.frame, error, roll.found, roll.roll / kDeg);
      EXPECT_LE(std::abs(roll.roll), 0.3 * kDeg)
          << c.name << " scene " << c.scene << " frame " << c.frame << ", pitch off by " << error;
    }
  }
}

TEST(RollEstimateTest, RollTurnIsARotationAboutThePrincipalPoint) {
  Camera camera;
  camera.fx = camera.fy = 500;
  camera.cx = 320;
  camera.cy = 240;
  const cv::Mat m = RollTurn(camera, 90 * kDeg);
  // Turned by 90 degrees (Rz: x' = -y, y' = x about the principal point): (420, 240), 100 px
  // right of it, goes 100 px below it; the principal point stays.
  const auto map = [&](double u, double v) {
    return cv::Point2d(m.at<double>(0, 0) * u + m.at<double>(0, 1) * v + m.at<double>(0, 2),
                       m.at<double>(1, 0) * u + m.at<double>(1, 1) * v + m.at<double>(1, 2));
  };
  EXPECT_NEAR(map(420, 240).x, 320, 1e-9);
  EXPECT_NEAR(map(420, 240).y, 340, 1e-9);
  EXPECT_NEAR(map(320, 240).x, 320, 1e-9);
  EXPECT_NEAR(map(320, 240).y, 240, 1e-9);
}

TEST(RollEstimateTest, BadOptionsAreRejected) {
  RollEstimateOptions options;
  std::string why;
  EXPECT_TRUE(options.Check(&why)) << why;
  options.max_cost_fraction = 0;
  EXPECT_FALSE(options.Check(&why));
  EXPECT_NE(why.find("max_cost_fraction"), std::string::npos) << why;
}

}  // namespace
}  // namespace corridor
