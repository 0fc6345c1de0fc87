// One junction hidden: a generated corridor cropped so that the right junction is out
// of the image. Without a known width the frame fails cleanly (no made-up second line); with a
// width prior, or the previous frame's width in a sequence, the geometry and the depth follow
// the generator's truth.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "corridor_depth/depth_metrics.h"
#include "pipeline/frame_pipeline.h"
#include "corridor_depth/recover_depth.h"
#include "synth/corridor_renderer.h"

namespace corridor {
namespace {

constexpr int kCropWidth = 360;

struct Views {
  Camera full_camera, crop_camera;
  synth::Frame full;
  cv::Mat crop_bgr, crop_depth;
};

// The corridor's vanishing point lies right of centre (yaw > 0): the right junction runs from it
// to the bottom right, outside the left 360 columns.
Views MakeViews() {
  synth::SceneOptions scene;
  scene.width = 2.3;
  scene.clutter = 0;
  scene.door_density = 0.3;
  scene.seed = 1;
  Views v;
  v.full_camera = Camera::FromHorizontalFov(640, 480, M_PI / 2, 0.66);
  const synth::CameraPose pose{0.08, 0.16, 0.5, 0.66, 2.0};
  EXPECT_TRUE(synth::RenderFrame(scene, v.full_camera, pose, &v.full).ok());
  v.crop_camera = v.full_camera;
  v.crop_camera.image_width = kCropWidth;  // Same intrinsics: a crop keeps cx and cy.
  v.crop_bgr = v.full.bgr.colRange(0, kCropWidth).clone();
  v.crop_depth = v.full.depth.colRange(0, kCropWidth).clone();
  return v;
}

TEST(OneJunctionTest, WithoutAWidthTheFrameFailsCleanly) {
  const Views v = MakeViews();
  RecoverDepthResult result;
  EXPECT_EQ(RecoverDepth(v.crop_bgr, v.crop_camera, RecoverDepthOptions(), &result).code(),
            StatusCode::kNoCorridorFound);
  EXPECT_TRUE(result.junctions.has_single);
  EXPECT_TRUE(result.junctions.single_is_left);
  EXPECT_NE(result.status.message().find("width"), std::string::npos) << result.status.message();
  EXPECT_FALSE(result.has_geometry);
  EXPECT_TRUE(result.depth.empty());
}

TEST(OneJunctionTest, AWidthPriorGivesTheGeometryAndTheDepth) {
  const Views v = MakeViews();
  const CorridorGeometry& truth = v.full.truth;
  RecoverDepthOptions options;
  options.width_prior = truth.width;
  RecoverDepthResult result;
  ASSERT_TRUE(RecoverDepth(v.crop_bgr, v.crop_camera, options, &result).ok())
      << result.status.ToString();
  EXPECT_NE(result.fallback.find("left junction only"), std::string::npos) << result.fallback;
  const CorridorGeometry& g = result.geometry;
  std::printf("one junction: yaw %.4f (true %.4f), pitch %.4f (%.4f), offset %.3f (%.3f); %s\n",
              g.yaw, truth.yaw, g.pitch, truth.pitch, g.offset, truth.offset,
              result.fallback.c_str());
  EXPECT_DOUBLE_EQ(g.width, truth.width);
  EXPECT_NEAR(g.yaw, truth.yaw, 0.02);
  EXPECT_NEAR(g.pitch, truth.pitch, 0.02);
  EXPECT_NEAR(g.offset, truth.offset, 0.1);
  const DepthMetrics m = ComputeDepthMetrics(result.depth, v.crop_depth, 5.0);
  std::printf("one junction: AbsRel < 5 m %.4f, coverage %.3f\n", m.abs_rel, m.coverage);
  EXPECT_LT(m.abs_rel, 0.08);
}

TEST(OneJunctionTest, InASequenceThePreviousFramesWidthStandsIn) {
  const Views v = MakeViews();
  std::unique_ptr<DepthRecoverer> recoverer;
  ASSERT_TRUE(DepthRecoverer::Create(RecoverDepthOptions(), &recoverer).ok());
  int next = 0;
  std::vector<PipelineFrame> out;
  FramePipeline(*recoverer).Run([&](PipelineFrame* frame) {
        if (next == 2) return false;
        frame->name = next == 0 ? "full" : "crop";
        frame->camera = next == 0 ? &v.full_camera : &v.crop_camera;
        frame->image = next == 0 ? v.full.bgr : v.crop_bgr;
        ++next;
        return true; }, [&](PipelineFrame&& frame) {
        out.push_back(std::move(frame));
        return true; });
  ASSERT_EQ(out.size(), 2u);
  ASSERT_TRUE(out[0].result.status.ok()) << out[0].result.status.ToString();
  // The full frame's width is the generator's (whatever checks it took to get there).
  EXPECT_NEAR(out[0].result.geometry.width, v.full.truth.width, 0.03 * v.full.truth.width)
      << out[0].result.fallback;
  ASSERT_TRUE(out[1].result.status.ok()) << out[1].result.status.ToString();
  EXPECT_NE(out[1].result.fallback.find("previous frame"), std::string::npos)
      << out[1].result.fallback;
  EXPECT_DOUBLE_EQ(out[1].result.geometry.width, out[0].result.geometry.width);
  EXPECT_NEAR(out[1].result.geometry.offset, v.full.truth.offset, 0.15);
}

}  // namespace
}  // namespace corridor
