// Issue 5's check: with the true geometry, the exact rasteriser reproduces the generator's ray
// caster on a pure box corridor (no clutter, no doors), to within the 1 mm of the depth PNG.
#include <gtest/gtest.h>

#include "depth/exact_rasterizer.h"
#include "evaluation/depth_metrics.h"
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
    RasterizerOptions options;
    options.max_range = 40;
    cv::Mat depth;
    ASSERT_TRUE(ExactRasterizer(options).Render(frame.truth, camera, &depth).ok());
    const DepthMetrics m = ComputeDepthMetrics(depth, truth, 40.0);
    EXPECT_LT(m.abs_rel, 0.001);
    EXPECT_DOUBLE_EQ(m.coverage, 1.0);
  }
}

}  // namespace
}  // namespace corridor
