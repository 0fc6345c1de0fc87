// With the true geometry, the exact rasteriser reproduces the generator's ray
// caster on a pure box corridor (no clutter, no doors), to within the 1 mm of the depth PNG.
#include <gtest/gtest.h>

#include "depth/exact_rasterizer.h"
#include "corridor_depth/depth_metrics.h"
#include "synth/corridor_renderer.h"
#include "synth/presets.h"

namespace corridor {
namespace {

TEST(ExactVsGeneratorTest, PureBoxMatchesTheRayCaster) {
  synth::SceneOptions scene;
  scene.width = 2.4;
  scene.ceiling_height = 2.7;
  scene.length = 500;  // The end wall lies beyond the 40 m cap.
  scene.clutter = 0;
  scene.door_density = 0;
  const Camera camera = synth::PaperCamera(0.66);
  for (const synth::CameraPose& pose :
       {synth::CameraPose{0.05, 0.1, 0.2, 0.66, 2.0}, synth::CameraPose{-0.02, -0.15, -0.3, 0.66, 5.0}}) {
    synth::Frame frame;
    ASSERT_TRUE(synth::RenderFrame(scene, camera, pose, &frame).ok());
    // The depth PNG's rounding to whole millimetres.
    cv::Mat truth;
    frame.depth.convertTo(truth, CV_16U, 1000.0);
    truth.convertTo(truth, CV_32F, 1e-3);
    // Both row kernels: AVX2 (where the CPU has it) and the baseline.
    for (const bool avx2 : {true, false}) {
      RasterizerOptions options;
      options.max_range = 40;
      options.use_avx2 = avx2;
      cv::Mat depth;
      ASSERT_TRUE(ExactRasterizer(options).Render(frame.truth, camera, &depth).ok());
      const DepthMetrics m = ComputeDepthMetrics(depth, truth, 40.0);
      EXPECT_LT(m.abs_rel, 0.001) << avx2;
      EXPECT_DOUBLE_EQ(m.coverage, 1.0) << avx2;
    }
  }
}

// An end wall 10 m ahead (the generator's, at the corridor's length): with end_distance set, the
// exact rasteriser closes the box there as the ray caster does.
TEST(ExactVsGeneratorTest, PureBoxWithAnEndWallMatchesTheRayCaster) {
  synth::SceneOptions scene;
  scene.width = 2.2;
  scene.ceiling_height = 2.6;
  scene.length = 12;
  scene.clutter = 0;
  scene.door_density = 0;
  const Camera camera = synth::PaperCamera(0.66);
  for (const synth::CameraPose& pose :
       {synth::CameraPose{0.06, 0.08, 0.15, 0.66, 2.0}, synth::CameraPose{0.0, -0.1, -0.2, 0.66, 4.5}}) {
    synth::Frame frame;
    ASSERT_TRUE(synth::RenderFrame(scene, camera, pose, &frame).ok());
    cv::Mat truth;
    frame.depth.convertTo(truth, CV_16U, 1000.0);
    truth.convertTo(truth, CV_32F, 1e-3);
    CorridorGeometry g = frame.truth;
    g.end_distance = scene.length - pose.distance;  // Z_W of the end wall, by the scene's layout.
    RasterizerOptions options;
    options.max_range = 40;
    cv::Mat with_wall, without_wall, baseline;
    ASSERT_TRUE(ExactRasterizer(options).Render(g, camera, &with_wall).ok());
    // The baseline rows (no AVX2) give the same depths.
    options.use_avx2 = false;
    ASSERT_TRUE(ExactRasterizer(options).Render(g, camera, &baseline).ok());
    EXPECT_EQ(cv::norm(with_wall, baseline, cv::NORM_INF), 0.0);
    options.use_avx2 = true;
    const DepthMetrics m = ComputeDepthMetrics(with_wall, truth, 40.0);
    EXPECT_LT(m.abs_rel, 0.001);
    EXPECT_DOUBLE_EQ(m.coverage, 1.0);
    // The end wall covers a real part of the image, where the open box would be far off.
    g.end_distance = 0;
    ASSERT_TRUE(ExactRasterizer(options).Render(g, camera, &without_wall).ok());
    const int changed = cv::countNonZero(cv::abs(with_wall - without_wall) > 0.01f);
    EXPECT_GT(changed, 500);
    EXPECT_GT(ComputeDepthMetrics(without_wall, truth, 40.0).abs_rel, 10 * m.abs_rel);
  }
}

}  // namespace
}  // namespace corridor
