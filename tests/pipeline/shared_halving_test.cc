// Large frames: the recoverer halves the whole image once for the junction search and the
// ceiling/end-wall searches. Against a recoverer that halves twice (search_max_width 641 halves to
// the same 640 px but is not shared), the depth, geometry and ceiling are the same, and the width
// is the generator's.
#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "pipeline/recover_depth.h"
#include "synth/corridor_renderer.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

TEST(SharedHalvingTest, OneHalvingGivesWhatTwoGive) {
  const Camera camera = Camera::FromHorizontalFov(1280, 720, 85.0 * M_PI / 180, 0.7);
  const synth::Frame frame = testing_util::RenderCorridorFrame(
      camera, 2.2, 2.8, 5, synth::CameraPose{0.06, 0.04, 0.15, 0.7, 3.0});
  ASSERT_FALSE(frame.bgr.empty());
  RecoverDepthOptions shared_options, twice_options;
  ASSERT_EQ(shared_options.search_max_width, shared_options.perception.max_work_width);
  twice_options.search_max_width = shared_options.search_max_width + 1;
  RecoverDepthResult shared, twice;
  ASSERT_TRUE(RecoverDepth(frame.bgr, camera, shared_options, &shared).ok())
      << shared.status.ToString();
  ASSERT_TRUE(RecoverDepth(frame.bgr, camera, twice_options, &twice).ok())
      << twice.status.ToString();
  EXPECT_EQ(shared.search.scale, 2);
  EXPECT_EQ(shared.search.bgr.cols, 640);
  EXPECT_TRUE(twice.search.bgr.empty());
  EXPECT_NEAR(shared.geometry.width, frame.truth.width, 0.03 * frame.truth.width);
  EXPECT_EQ(shared.geometry.width, twice.geometry.width);
  EXPECT_EQ(shared.geometry.yaw, twice.geometry.yaw);
  EXPECT_EQ(shared.ceiling.found, twice.ceiling.found);
  EXPECT_EQ(shared.geometry.ceiling_height, twice.geometry.ceiling_height);
  ASSERT_EQ(shared.depth.size(), twice.depth.size());
  EXPECT_EQ(cv::norm(shared.depth, twice.depth, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace corridor
