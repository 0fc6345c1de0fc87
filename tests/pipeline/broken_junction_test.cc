// A faint junction broken into short pieces by door bottoms (the real photo rtabmap_6's case):
// the junction search's second, relaxed Hough look finds it, and the geometry and the depth follow
// the generator's truth; without the second look the frame gets "no corridor found".
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "corridor_depth/depth_metrics.h"
#include "corridor_depth/recover_depth.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

TEST(BrokenJunctionTest, TheSecondLookGivesTheTrueGeometryAndSaysSo) {
  const Camera camera = Camera::FromHorizontalFov(640, 480, 80.0 * M_PI / 180, 1.2);
  const synth::Frame frame =
      testing_util::CorridorWithBrokenRightJunction(camera, {0.05, 0.03, 0.1, 1.2, 2.0});
  ASSERT_FALSE(frame.bgr.empty());
  const CorridorGeometry& truth = frame.truth;

  RecoverDepthOptions first_only;
  first_only.perception.relaxed_hough_threshold = 0;
  RecoverDepthResult failed;
  EXPECT_EQ(RecoverDepth(frame.bgr, camera, first_only, &failed).code(),
            StatusCode::kNoCorridorFound);

  RecoverDepthResult result;
  ASSERT_TRUE(RecoverDepth(frame.bgr, camera, RecoverDepthOptions(), &result).ok())
      << result.status.ToString();
  EXPECT_TRUE(result.junctions.relaxed_hough);
  EXPECT_NE(result.fallback.find("relaxed Hough"), std::string::npos) << result.fallback;
  EXPECT_NEAR(result.geometry.width, truth.width, 0.02 * truth.width);
  EXPECT_NEAR(result.geometry.yaw, truth.yaw, 0.01);
  EXPECT_NEAR(result.geometry.pitch, truth.pitch, 0.01);
  const DepthMetrics metrics = ComputeDepthMetrics(result.depth, frame.depth, 5.0);
  std::printf("width %.3f m (true %.3f), AbsRel < 5 m %.4f\n", result.geometry.width, truth.width,
              metrics.abs_rel);
  EXPECT_LT(metrics.abs_rel, 0.03);
}

}  // namespace
}  // namespace corridor
