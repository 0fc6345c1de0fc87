// The corridor width bound (RecoverDepthOptions::max_width, --max_corridor_width): a frame whose
// layout is wider than a corridor is refused with a message that names the bound, and a user with
// a wide hall raises the bound to have it recovered. Truth from the generator's ray caster.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "corridor_depth/recover_depth.h"
#include "synth/presets.h"
#include "tests/support/corridor_frame.h"
#include "tests/support/preset_frame.h"

namespace corridor {
namespace {

using testing_util::PresetFrame;
using testing_util::RenderCorridorFrame;
using testing_util::RenderPreset;

// The mix class's second scene (a chair rail on two-tone walls, sofas along both), frame 12: the
// rail is taken for the junction on both walls, and the width comes out almost three times the
// truth. The bound refuses it; without it (20 m) it is reported, and wrong.
TEST(CorridorWidthBoundTest, ARailTakenOnBothWallsIsRefusedAsWiderThanACorridor) {
  const PresetFrame f = RenderPreset("mix", 1, 12);
  ASSERT_FALSE(f.frame.bgr.empty());
  RecoverDepthOptions options;
  RecoverDepthResult refused;
  const Status status = RecoverDepth(f.frame.bgr, f.camera, options, &refused);
  EXPECT_EQ(status.code(), StatusCode::kImplausibleGeometry) << status.ToString();
  EXPECT_NE(status.message().find("wider than max_corridor_width 5 m"), std::string::npos)
      << status.ToString();
  EXPECT_TRUE(refused.depth.empty());

  options.max_width = 20;
  RecoverDepthResult reported;
  ASSERT_TRUE(RecoverDepth(f.frame.bgr, f.camera, options, &reported).ok())
      << reported.status.ToString();
  EXPECT_GT(reported.geometry.width, RecoverDepthOptions().max_width);
  EXPECT_GT(std::abs(reported.geometry.width - f.true_width) / f.true_width, 0.5);
}

// A 6 m wide hall, plain: refused by default, recovered within 3% with the bound raised to 8 m.
TEST(CorridorWidthBoundTest, AWideHallIsRecoveredWhenTheBoundIsRaised) {
  const synth::ScenePreset preset = testing_util::PaperScene("Cord_E06");
  synth::CameraPose pose;
  pose.pitch = 0.2;
  pose.yaw = 0.03;
  pose.offset = 0.3;
  pose.height = 1.4;
  pose.distance = 3.0;
  const double true_width = 6.0;
  Camera camera = preset.camera;
  camera.mount_height = pose.height;
  const synth::Frame frame = RenderCorridorFrame(camera, true_width, 3.0, 11, pose);
  ASSERT_FALSE(frame.bgr.empty());

  RecoverDepthOptions options;
  RecoverDepthResult refused;
  const Status status = RecoverDepth(frame.bgr, camera, options, &refused);
  EXPECT_EQ(status.code(), StatusCode::kImplausibleGeometry) << status.ToString();
  EXPECT_NE(status.message().find("max_corridor_width"), std::string::npos) << status.ToString();

  options.max_width = 8;
  RecoverDepthResult recovered;
  ASSERT_TRUE(RecoverDepth(frame.bgr, camera, options, &recovered).ok())
      << recovered.status.ToString();
  EXPECT_NEAR(recovered.geometry.width, true_width, 0.03 * true_width);
}

}  // namespace
}  // namespace corridor
