// DepthSequence: a rendered drive fed frame by frame comes out within 2% of the generator's true
// width, as the two-thread FramePipeline computes it, and Reset starts a new stream.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "corridor_depth/depth_sequence.h"
#include "pipeline/frame_pipeline.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

constexpr int kFrames = 6;

class DepthSequenceTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    camera_ = Camera::FromHorizontalFov(480, 360, 80.0 * M_PI / 180, 0.66);
    for (int i = 0; i < kFrames; ++i) {
      const synth::CameraPose pose{0.03 + 0.01 * std::sin(0.7 * i), 0.05,
                                   0.1 + 0.04 * std::sin(0.5 * i), 0.66, 3.0 + 0.3 * i};
      frames_.push_back(testing_util::RenderCorridorFrame(camera_, 2.2, 2.7, 11, pose, 0.0));
    }
  }
  static Camera camera_;
  static std::vector<synth::Frame> frames_;
};

Camera DepthSequenceTest::camera_;
std::vector<synth::Frame> DepthSequenceTest::frames_;

TEST_F(DepthSequenceTest, FramesInOrderMatchTheTruthAndThePipeline) {
  std::unique_ptr<DepthSequence> sequence;
  ASSERT_TRUE(DepthSequence::Create(RecoverDepthOptions(), &sequence).ok());
  std::vector<RecoverDepthResult> results(kFrames);
  for (int i = 0; i < kFrames; ++i) {
    ASSERT_TRUE(sequence->Process(frames_[i].bgr, camera_, &results[i]).ok()) << "frame " << i;
    EXPECT_LT(std::abs(results[i].geometry.width / frames_[i].truth.width - 1), 0.02)
        << "frame " << i;
  }
  // The two-thread pipeline carries the same state from frame to frame.
  std::unique_ptr<DepthRecoverer> recoverer;
  ASSERT_TRUE(DepthRecoverer::Create(RecoverDepthOptions(), &recoverer).ok());
  int next = 0;
  std::vector<PipelineFrame> delivered;
  FramePipeline(*recoverer).Run([&](PipelineFrame* frame) {
        if (next == kFrames) return false;
        frame->name = std::to_string(next);
        frame->camera = &camera_;
        frame->image = frames_[next++].bgr;
        return true; }, [&](PipelineFrame&& frame) {
        delivered.push_back(std::move(frame));
        return true; });
  ASSERT_EQ(delivered.size(), static_cast<size_t>(kFrames));
  for (int i = 0; i < kFrames; ++i) {
    EXPECT_EQ(delivered[i].result.junctions_tracked, results[i].junctions_tracked) << i;
    EXPECT_NEAR(delivered[i].result.geometry.width, results[i].geometry.width, 1e-9) << i;
    EXPECT_NEAR(delivered[i].result.geometry.yaw, results[i].geometry.yaw, 1e-9) << i;
  }
  // Every frame's own whole search is confirmed by its ceiling on this clean drive: no frame keeps
  // tracked lines (OwnSearchKept), in Recover and in the pipeline alike.
  int tracked = 0;
  for (const auto& r : results) tracked += r.junctions_tracked;
  EXPECT_EQ(tracked, 0);
}

TEST_F(DepthSequenceTest, ResetStartsANewStream) {
  std::unique_ptr<DepthSequence> sequence;
  ASSERT_TRUE(DepthSequence::Create(RecoverDepthOptions(), &sequence).ok());
  RecoverDepthResult result;
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(sequence->Process(frames_[i].bgr, camera_, &result).ok());
  sequence->Reset();
  ASSERT_TRUE(sequence->Process(frames_[4].bgr, camera_, &result).ok());
  EXPECT_FALSE(result.junctions_tracked);
  RecoverDepthResult alone;
  ASSERT_TRUE(RecoverDepth(frames_[4].bgr, camera_, RecoverDepthOptions(), &alone).ok());
  EXPECT_NEAR(result.geometry.width, alone.geometry.width, 1e-9);
  EXPECT_NEAR(result.geometry.pitch, alone.geometry.pitch, 1e-9);
}

TEST(DepthSequence, ABadOptionIsNamed) {
  RecoverDepthOptions options;
  options.points_per_line = 1;
  std::unique_ptr<DepthSequence> sequence;
  const Status status = DepthSequence::Create(options, &sequence);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(status.message().find("points_per_line"), std::string::npos);
}

}  // namespace
}  // namespace corridor
