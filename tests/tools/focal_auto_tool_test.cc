// corridor_depth --focal=auto on generated corridors with doors and tile grout: the
// focal length it records in camera_used.yaml is the generator camera's within 3%; without a
// second vanishing point it falls back to --hfov and says so; bad combinations exit 2.

#include <cmath>

#include "synth/corridor_renderer.h"
#include "tests/reliability/reliability_util.h"

namespace corridor {
namespace testing_util {
namespace {

constexpr double kDeg = M_PI / 180.0;

// A 640x480 frame of a corridor with doors and 0.6 m tiles at `hfov_deg`, in <dir>/<name>/ (no
// camera.yaml); returns the generator camera's fx.
double WriteFrame(const ScratchDir& dir, const std::string& name, double hfov_deg, double yaw_deg,
                  double pitch_deg) {
  synth::SceneOptions scene;
  scene.door_density = 0.9;
  scene.tile_size = 0.6;
  scene.seed = 5;
  const Camera camera = Camera::FromHorizontalFov(640, 480, hfov_deg * kDeg, 0.66);
  synth::CameraPose pose;
  pose.yaw = yaw_deg * kDeg;
  pose.pitch = pitch_deg * kDeg;
  pose.offset = 0.1;
  pose.height = 0.66;
  synth::Frame frame;
  EXPECT_TRUE(synth::RenderFrame(scene, camera, pose, &frame).ok());
  dir.WriteImage(name + "/000000.png", frame.bgr);
  return camera.fx;
}

TEST(FocalAutoToolTest, RecordsTheFocalOfTheVanishingPoints) {
  ScratchDir dir;
  const double fx = WriteFrame(dir, "tilted", 70, 6, 4);
  EXPECT_NEAR(fx, 320.0 / std::tan(35 * kDeg), 1e-9);  // The generator's camera, by hand.
  const ToolRun run = RunDepthTool(dir.Path("tilted"), dir.Path("out"), dir,
                                   {"--focal=auto", "--camera_height=0.66"});
  ASSERT_FALSE(run.signaled);
  ASSERT_LE(run.exit_code, 1) << run.err;
  EXPECT_TRUE(Contains(run.out, "from vanishing points")) << run.out;
  Camera used;
  ASSERT_TRUE(ReadCameraYaml(dir.Path("out/tilted/camera_used.yaml"), &used).ok());
  EXPECT_NEAR(used.fx, fx, 0.03 * fx);
  EXPECT_EQ(used.fy, used.fx);
  EXPECT_DOUBLE_EQ(used.cx, 319.5);
}

TEST(FocalAutoToolTest, FallsBackToTheFieldOfViewAndSaysSo) {
  ScratchDir dir;
  WriteFrame(dir, "ahead", 70, 0, 0);  // Across and vertical lines parallel: f unobservable.
  const ToolRun run = RunDepthTool(dir.Path("ahead"), dir.Path("out"), dir,
                                   {"--focal=auto", "--hfov=50", "--camera_height=0.66"});
  ASSERT_FALSE(run.signaled);
  ASSERT_LE(run.exit_code, 1) << run.err;
  EXPECT_TRUE(Contains(run.out, "fell back to --hfov=50")) << run.out;
  Camera used;
  ASSERT_TRUE(ReadCameraYaml(dir.Path("out/ahead/camera_used.yaml"), &used).ok());
  EXPECT_NEAR(used.fx, 320.0 / std::tan(25 * kDeg), 1e-6);
}

TEST(FocalAutoToolTest, BadCombinationsAreConfigurationErrors) {
  ScratchDir dir;
  WriteFrame(dir, "tilted", 70, 6, 4);
  ExpectCleanExit(RunDepthTool(dir.Path("tilted"), dir.Path("out"), dir,
                               {"--focal=auto", "--fx=300", "--camera_height=0.66"}),
                  2, {"--focal=auto", "--fx"});
  ExpectCleanExit(RunDepthTool(dir.Path("tilted"), dir.Path("out"), dir,
                               {"--focal=600", "--camera_height=0.66"}),
                  2, {"--focal=600", "auto"});
  ExpectCleanExit(RunDepthTool(dir.Path("tilted"), dir.Path("out"), dir, {"--focal=auto"}), 2,
                  {"camera height"});
}

}  // namespace
}  // namespace testing_util
}  // namespace corridor
