// Junction tracking in a sequence (RecoverDepthOptions::track_junctions): on a rendered drive the
// frames whose junctions were tracked from the previous frame's are as close to the generator's
// true width as the whole search's; a tracked frame whose own whole search its ceiling confirms
// keeps that search; a frame far from the previous one is searched whole; the two-thread
// FramePipeline tracks too; a bad tracker option is named; a frame whose ceiling does not confirm
// its walls does not let the next one be tracked.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "perception/junction_tracker.h"
#include "pipeline/frame_pipeline.h"
#include "corridor_depth/recover_depth.h"
#include "pipeline/sequence_holds.h"
#include "pipeline/sequence_prior.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

constexpr int kFrames = 8;

class JunctionTrackingTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    camera_ = Camera::FromHorizontalFov(480, 360, 80.0 * M_PI / 180, 0.66);
    for (int i = 0; i < kFrames; ++i) {
      const synth::CameraPose pose{0.03 + 0.01 * std::sin(0.7 * i), 0.05, 0.1 + 0.04 * std::sin(0.5 * i),
                                   0.66, 3.0 + 0.3 * i};
      frames_.push_back(testing_util::RenderCorridorFrame(camera_, 2.2, 2.7, 11, pose, 0.0));
    }
  }

  // Frames 0-2 through `recoverer` with `track`; the premise of the tests that start from a
  // trusted track.
  static void TrustTrack(const DepthRecoverer& recoverer, JunctionTrack* track,
                         RecoverDepthResult* result) {
    for (int i = 0; i < 3; ++i) {
      ASSERT_TRUE(recoverer.Recover(frames_[i].bgr, camera_, result, nullptr, track).ok());
    }
    ASSERT_TRUE(track->Trusted(RecoverDepthOptions().tracker.redetect_interval))
        << "premise: the track is trusted by frame 2";
  }

  // The drive's frames in order, for a FramePipeline.
  FramePipeline::Source DriveSource() const {
    return [next = 0](PipelineFrame* frame) mutable {
      if (next >= kFrames) return false;
      frame->name = std::to_string(next);
      frame->camera = &camera_;
      frame->image = frames_[next++].bgr;
      return true;
    };
  }

  // Runs the drive as a sequence; returns the frames whose junctions were tracked.
  int RunDrive(bool track_junctions, std::vector<double>* width_errors,
               RecoverDepthOptions options = RecoverDepthOptions()) const {
    options.track_junctions = track_junctions;
    std::unique_ptr<DepthRecoverer> recoverer;
    EXPECT_TRUE(DepthRecoverer::Create(options, &recoverer).ok());
    SequencePrior prior;
    JunctionTrack track;
    int tracked = 0;
    for (const synth::Frame& frame : frames_) {
      RecoverDepthResult result;
      const Status status =
          recoverer->Recover(frame.bgr, camera_, &result, prior.Previous(), &track);
      EXPECT_TRUE(status.ok()) << status.ToString();
      prior.Update(result);
      tracked += result.junctions_tracked;
      width_errors->push_back(std::abs(result.geometry.width / frame.truth.width - 1));
    }
    return tracked;
  }

  static Camera camera_;
  static std::vector<synth::Frame> frames_;
};

Camera JunctionTrackingTest::camera_;
std::vector<synth::Frame> JunctionTrackingTest::frames_;

// Without a ceiling search nothing confirms a frame's own search, and the tracked lines stand.
TEST_F(JunctionTrackingTest, TrackedFramesAreAsCloseToTheTrueWidth) {
  RecoverDepthOptions no_ceiling;
  no_ceiling.estimate_ceiling = false;
  std::vector<double> searched_errors, tracked_errors;
  EXPECT_EQ(RunDrive(false, &searched_errors, no_ceiling), 0);
  const int tracked = RunDrive(true, &tracked_errors, no_ceiling);
  // Frames 0 and 1 are searched whole (the second one's search agrees with its tracked pair);
  // frames 2 on may be tracked.
  EXPECT_GE(tracked, kFrames - 4);
  EXPECT_LE(tracked, kFrames - 2);
  for (int i = 0; i < kFrames; ++i) {
    EXPECT_LT(searched_errors[i], 0.02) << "frame " << i;
    EXPECT_LT(tracked_errors[i], 0.02) << "frame " << i;
  }
}

// With the ceiling searched, each tracked frame is searched whole too, and its own search, which
// its ceiling confirms on this clean drive, is kept: the widths are the frames' own, and the track
// goes on (the own search found the tracked pair).
TEST_F(JunctionTrackingTest, AnOwnSearchTheCeilingConfirmsIsKept) {
  std::vector<double> searched_errors, sequence_errors;
  EXPECT_EQ(RunDrive(false, &searched_errors), 0);
  EXPECT_EQ(RunDrive(true, &sequence_errors), 0);
  for (int i = 0; i < kFrames; ++i) {
    EXPECT_LT(sequence_errors[i], 0.02) << "frame " << i;
    EXPECT_NEAR(sequence_errors[i], searched_errors[i], 1e-9) << "frame " << i;
  }
  std::unique_ptr<DepthRecoverer> recoverer;
  ASSERT_TRUE(DepthRecoverer::Create(RecoverDepthOptions(), &recoverer).ok());
  JunctionTrack track;
  RecoverDepthResult result;
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(recoverer->Recover(frames_[i].bgr, camera_, &result, nullptr, &track).ok());
  }
  EXPECT_FALSE(result.junctions_tracked);
  EXPECT_TRUE(track.Trusted(RecoverDepthOptions().tracker.redetect_interval));
}

// The track is trusted only after a searched frame whose two ceiling sides agree with its walls.
// With the ceiling search limited to 1.8-2.2 m, under the drive's 2.7 m ceiling, no frame's
// ceiling is trusted: no frame is tracked, and each is as close to the truth as searched whole.
// Without a ceiling search there is nothing to confirm: the frames are tracked as before.
TEST_F(JunctionTrackingTest, NoFrameIsTrackedWithoutAConfirmingCeiling) {
  std::vector<double> errors;
  RecoverDepthOptions below;
  below.ceiling.max_height = 2.2;
  EXPECT_EQ(RunDrive(true, &errors, below), 0);
  for (int i = 0; i < kFrames; ++i) EXPECT_LT(errors[i], 0.02) << "frame " << i;
  RecoverDepthOptions no_ceiling;
  no_ceiling.estimate_ceiling = false;
  errors.clear();
  EXPECT_GE(RunDrive(true, &errors, no_ceiling), kFrames - 4);
}

// A tracked frame whose ceiling does not confirm its walls is searched whole again, and the next
// frame is searched whole too. Frames 0-2 with the defaults (frame 2 tracked), frame 3 with the
// ceiling search under the drive's ceiling (its ceiling cannot be trusted), frame 4 with the
// defaults again, all on one track.
TEST_F(JunctionTrackingTest, ATrackedFrameItsCeilingDoesNotConfirmIsSearchedWhole) {
  RecoverDepthOptions below;
  below.ceiling.max_height = 2.2;
  std::unique_ptr<DepthRecoverer> normal, blind;
  ASSERT_TRUE(DepthRecoverer::Create(RecoverDepthOptions(), &normal).ok());
  ASSERT_TRUE(DepthRecoverer::Create(below, &blind).ok());
  JunctionTrack track;
  RecoverDepthResult result;
  ASSERT_NO_FATAL_FAILURE(TrustTrack(*normal, &track, &result));
  ASSERT_TRUE(blind->Recover(frames_[3].bgr, camera_, &result, nullptr, &track).ok());
  EXPECT_FALSE(result.junctions_tracked);
  EXPECT_LT(std::abs(result.geometry.width / frames_[3].truth.width - 1), 0.02);
  ASSERT_TRUE(normal->Recover(frames_[4].bgr, camera_, &result, nullptr, &track).ok());
  EXPECT_FALSE(result.junctions_tracked);
}

TEST(TrackConfirmationTest, OnlyAFrameWithATrustedCeilingConfirms) {
  RecoverDepthOptions options;
  RecoverDepthResult result;  // Status ok, searched whole.
  result.ceiling_trusted = true;
  EXPECT_TRUE(TrackConfirmedBy(options, result));
  result.ceiling_trusted = false;
  EXPECT_FALSE(TrackConfirmedBy(options, result));
  result.junctions_tracked = true;  // A tracked frame too needs its ceiling.
  EXPECT_FALSE(TrackConfirmedBy(options, result));
  result.junctions_tracked = false;
  result.ceiling_trusted = true;
  result.status = Status::LowConfidence("refused");
  EXPECT_FALSE(TrackConfirmedBy(options, result));
  options.ceiling_height = 2.5;  // A given ceiling: nothing searched, nothing to confirm.
  EXPECT_TRUE(TrackConfirmedBy(options, result));
  options.ceiling_height = 0;
  options.estimate_ceiling = false;
  EXPECT_TRUE(TrackConfirmedBy(options, result));
}

TEST_F(JunctionTrackingTest, AFrameFarFromThePreviousOneIsSearchedWhole) {
  std::unique_ptr<DepthRecoverer> recoverer;
  ASSERT_TRUE(DepthRecoverer::Create(RecoverDepthOptions(), &recoverer).ok());
  JunctionTrack track;
  RecoverDepthResult result;
  ASSERT_NO_FATAL_FAILURE(TrustTrack(*recoverer, &track, &result));
  // The camera turned and moved aside: the previous lines are far from this frame's.
  const synth::Frame moved = testing_util::RenderCorridorFrame(
      camera_, 2.2, 2.7, 11, synth::CameraPose{-0.08, 0.05, -0.35, 0.66, 4.0}, 0.0);
  ASSERT_TRUE(recoverer->Recover(moved.bgr, camera_, &result, nullptr, &track).ok());
  EXPECT_FALSE(result.junctions_tracked);
  EXPECT_LT(std::abs(result.geometry.width / moved.truth.width - 1), 0.02);
}

// Without a ceiling search (nothing confirms a frame's own search) the tracked lines stand.
TEST_F(JunctionTrackingTest, TheTwoThreadPipelineTracks) {
  RecoverDepthOptions no_ceiling;
  no_ceiling.estimate_ceiling = false;
  std::unique_ptr<DepthRecoverer> recoverer;
  ASSERT_TRUE(DepthRecoverer::Create(no_ceiling, &recoverer).ok());
  FramePipeline pipeline(*recoverer, 2);
  int tracked = 0, delivered = 0;
  pipeline.Run(
      DriveSource(),
      [&](PipelineFrame&& frame) {
        EXPECT_TRUE(frame.result.status.ok()) << frame.result.status.ToString();
        EXPECT_EQ(frame.index, delivered);
        tracked += frame.result.junctions_tracked;
        EXPECT_LT(std::abs(frame.result.geometry.width / frames_[delivered].truth.width - 1), 0.02)
            << "frame " << delivered;
        ++delivered;
        return true;
      });
  EXPECT_EQ(delivered, kFrames);
  EXPECT_GE(tracked, kFrames - 4);
}

// The two-thread pipeline gives what Recover gives frame by frame: its extraction thread waits
// for a searched frame's confirmation before it tracks the next, so with the ceiling search under
// the drive's ceiling no frame is tracked there either.
TEST_F(JunctionTrackingTest, TheTwoThreadPipelineWaitsForTheConfirmation) {
  RecoverDepthOptions below;
  below.ceiling.max_height = 2.2;
  std::unique_ptr<DepthRecoverer> recoverer;
  ASSERT_TRUE(DepthRecoverer::Create(below, &recoverer).ok());
  FramePipeline pipeline(*recoverer, 4);
  int tracked = 0;
  const int64_t delivered = pipeline.Run(
      DriveSource(),
      [&](PipelineFrame&& frame) {
        tracked += frame.result.junctions_tracked;
        return true;
      });
  EXPECT_EQ(delivered, kFrames);
  EXPECT_EQ(tracked, 0);
}

TEST(JunctionTrackingOptionsTest, ABadTrackerOptionIsNamed) {
  RecoverDepthOptions options;
  options.tracker.reach_fraction = 0.5;
  std::unique_ptr<DepthRecoverer> recoverer;
  const Status status = DepthRecoverer::Create(options, &recoverer);
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.ToString().find("tracker: reach_fraction"), std::string::npos)
      << status.ToString();
}

}  // namespace
}  // namespace corridor
