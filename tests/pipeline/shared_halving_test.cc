// Large frames: the recoverer halves the whole image once for the junction search, and the
// ceiling/end-wall searches take their image from that halving (halved further when
// search_max_width asks for less). Against the independent path (HalveToWidth of the frame itself,
// and the junction search that halves only its own region), the search image and camera are the
// same to the pixel, the junctions the same lines, and the width is the generator's.
#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "perception/junction_detector.h"
#include "perception/working_image.h"
#include "pipeline/frame_handover.h"
#include "corridor_depth/recover_depth.h"
#include "synth/corridor_renderer.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

class SharedHalvingTest : public ::testing::TestWithParam<int> {};

TEST_P(SharedHalvingTest, SearchImageIsTheFramesOwnHalving) {
  const Camera camera = Camera::FromHorizontalFov(1280, 720, 85.0 * M_PI / 180, 0.7);
  const synth::Frame frame = testing_util::RenderCorridorFrame(
      camera, 2.2, 2.8, 5, synth::CameraPose{0.06, 0.04, 0.15, 0.7, 3.0});
  ASSERT_FALSE(frame.bgr.empty());
  RecoverDepthOptions options;
  options.search_max_width = GetParam();
  ASSERT_EQ(options.perception.max_work_width, 640);
  RecoverDepthResult result;
  ASSERT_TRUE(RecoverDepth(frame.bgr, camera, options, &result).ok())
      << result.status.ToString();

  // 1280 px halve to 640 for the junctions; 640 or 480 px ask for one or two halvings.
  const int expected_scale = GetParam() >= 640 ? 2 : 4;
  ASSERT_NE(result.handover, nullptr);
  const WorkingImage& search = result.handover->search;
  EXPECT_EQ(search.scale, expected_scale);
  EXPECT_EQ(search.bgr.cols, 1280 / expected_scale);
  const WorkingImage direct = HalveToWidth(frame.bgr, camera, options.search_max_width);
  ASSERT_EQ(direct.bgr.size(), search.bgr.size());
  EXPECT_EQ(cv::norm(direct.bgr, search.bgr, cv::NORM_INF), 0.0);
  EXPECT_EQ(direct.camera.fx, search.camera.fx);
  EXPECT_EQ(direct.camera.cx, search.camera.cx);
  EXPECT_EQ(direct.camera.cy, search.camera.cy);
  EXPECT_EQ(direct.camera.image_width, search.camera.image_width);

  JunctionPair own;
  ASSERT_TRUE(DetectJunctions(frame.bgr, options.perception, &own).ok());
  ASSERT_TRUE(own.status.ok()) << own.status.ToString();
  EXPECT_EQ((own.left.line - result.junctions.left.line).norm(), 0.0);
  EXPECT_EQ((own.right.line - result.junctions.right.line).norm(), 0.0);
  EXPECT_NEAR(result.geometry.width, frame.truth.width, 0.03 * frame.truth.width);
}

INSTANTIATE_TEST_SUITE_P(SearchWidths, SharedHalvingTest, ::testing::Values(640, 480));

}  // namespace
}  // namespace corridor
