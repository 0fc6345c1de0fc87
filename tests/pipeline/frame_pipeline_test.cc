#include "pipeline/frame_pipeline.h"

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "synth/corridor_renderer.h"
#include "synth/presets.h"

namespace corridor {
namespace {

constexpr int kFrames = 1000;
constexpr int kCapacity = 3;

// One small rendered corridor (160x120, the paper camera scaled), reused for every good frame.
class FramePipelineTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    camera_ = synth::PaperCamera(0.66);
    const double scale = 160.0 / camera_.image_width;
    camera_.image_width = 160;
    camera_.image_height = 120;
    camera_.fx = camera_.fy = camera_.fx * scale;
    camera_.cx = 79.5;
    camera_.cy = 59.5;
    synth::SceneOptions scene;
    scene.width = 2.1;
    scene.door_density = 0.2;
    synth::CameraPose pose;
    pose.pitch = 0.05;
    pose.yaw = 0.03;
    pose.offset = 0.1;
    synth::Frame frame;
    ASSERT_TRUE(synth::RenderFrame(scene, camera_, pose, &frame).ok());
    image_ = frame.bgr;
  }

  void SetUp() override {
    ASSERT_TRUE(DepthRecoverer::Create(RecoverDepthOptions(), &recoverer_).ok());
  }

  // Frame i of the stream: mostly the corridor; every 7th could not be read (read_status), every
  // 11th is an empty image with no read error, every 13th has no camera.
  enum class Kind { kGood,
                    kUnreadable,
                    kEmpty,
                    kNoCamera };
  static Kind KindOf(int i) {
    if (i % 7 == 3) return Kind::kUnreadable;
    if (i % 11 == 5) return Kind::kEmpty;
    if (i % 13 == 8) return Kind::kNoCamera;
    return Kind::kGood;
  }

  static void Fill(int i, PipelineFrame* frame) {
    frame->name = "frame" + std::to_string(i);
    frame->camera = &camera_;
    switch (KindOf(i)) {
      case Kind::kGood:
        frame->image = image_;
        break;
      case Kind::kUnreadable:
        frame->read_status = Status::IoError(frame->name + ": unreadable");
        break;
      case Kind::kEmpty:
        break;
      case Kind::kNoCamera:
        frame->image = image_;
        frame->camera = nullptr;
        break;
    }
  }

  static Camera camera_;
  static cv::Mat image_;
  std::unique_ptr<DepthRecoverer> recoverer_;
};

Camera FramePipelineTest::camera_;
cv::Mat FramePipelineTest::image_;

TEST_F(FramePipelineTest, TheRenderedCorridorGivesDepth) {
  RecoverDepthResult result;
  ASSERT_TRUE(recoverer_->Recover(image_, camera_, &result).ok()) << result.status.ToString();
  EXPECT_EQ(result.depth.size(), image_.size());
}

TEST_F(FramePipelineTest, EveryFrameOnceInOrderAndFailuresCarryTheirStatus) {
  FramePipeline pipeline(*recoverer_, kCapacity);
  int next = 0;
  const auto source = [&](PipelineFrame* frame) {
    if (next >= kFrames) return false;
    Fill(next++, frame);
    return true;
  };
  std::vector<int> seen;
  int good = 0;
  const auto sink = [&](PipelineFrame&& frame) {
    const int i = static_cast<int>(frame.index);
    seen.push_back(i);
    EXPECT_EQ(frame.name, "frame" + std::to_string(i));
    const Status& status = frame.result.status;
    switch (KindOf(i)) {
      case Kind::kGood:
        EXPECT_TRUE(status.ok()) << frame.name << ": " << status.ToString();
        EXPECT_TRUE(frame.result.has_geometry);
        EXPECT_EQ(frame.result.depth.size(), image_.size());
        ++good;
        break;
      case Kind::kUnreadable:
        EXPECT_EQ(status.code(), StatusCode::kIoError) << frame.name;
        EXPECT_EQ(status.message(), frame.name + ": unreadable");
        EXPECT_TRUE(frame.result.depth.empty());
        break;
      case Kind::kEmpty:
        EXPECT_EQ(status.code(), StatusCode::kInvalidArgument) << frame.name;
        EXPECT_NE(status.message().find("empty"), std::string::npos) << status.message();
        EXPECT_TRUE(frame.result.depth.empty());
        break;
      case Kind::kNoCamera:
        EXPECT_EQ(status.code(), StatusCode::kInvalidArgument) << frame.name;
        EXPECT_NE(status.message().find("no camera"), std::string::npos) << status.message();
        break;
    }
    return true;
  };
  EXPECT_EQ(pipeline.Run(source, sink), kFrames);
  ASSERT_EQ(seen.size(), static_cast<size_t>(kFrames));
  for (int i = 0; i < kFrames; ++i) ASSERT_EQ(seen[i], i) << "out of order or repeated";
  EXPECT_GT(good, kFrames / 2);
  EXPECT_GE(pipeline.last_high_water(), 1u);
  EXPECT_LE(pipeline.last_high_water(), static_cast<size_t>(kCapacity));
}

TEST_F(FramePipelineTest, ASlowSinkFillsTheQueueButNeverBeyondItsCapacity) {
  FramePipeline pipeline(*recoverer_, kCapacity);
  int next = 0;
  const auto source = [&](PipelineFrame* frame) {
    if (next >= 40) return false;
    frame->name = std::to_string(next++);
    frame->read_status = Status::IoError("unreadable");  // Instant for the extraction thread.
    return true;
  };
  int delivered = 0;
  const auto sink = [&](PipelineFrame&&) {
    if (delivered++ % 10 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(30));
    return true;
  };
  EXPECT_EQ(pipeline.Run(source, sink), 40);
  EXPECT_EQ(pipeline.last_high_water(), static_cast<size_t>(kCapacity));
}

TEST_F(FramePipelineTest, ASinkReturningFalseStopsTheStreamCleanly) {
  for (int stop_at : {0, 1, 100, kFrames - 1}) {
    FramePipeline pipeline(*recoverer_, kCapacity);
    int requested = 0;
    const auto source = [&](PipelineFrame* frame) {
      if (requested >= kFrames) return false;
      Fill(requested++, frame);
      return true;
    };
    int last = -1;
    const auto sink = [&](PipelineFrame&& frame) {
      EXPECT_EQ(frame.index, last + 1);
      last = static_cast<int>(frame.index);
      return frame.index < stop_at;
    };
    // Returns (no deadlock) with the frames up to and including the one that stopped it.
    EXPECT_EQ(pipeline.Run(source, sink), stop_at + 1);
    EXPECT_EQ(last, stop_at);
    // The extraction thread stops soon: at most the queue and one frame in each thread more.
    EXPECT_LE(requested, stop_at + 1 + kCapacity + 2);
    EXPECT_LE(pipeline.last_high_water(), static_cast<size_t>(kCapacity));
  }
}

TEST_F(FramePipelineTest, AnEmptySourceDeliversNothing) {
  FramePipeline pipeline(*recoverer_, kCapacity);
  int calls = 0;
  EXPECT_EQ(pipeline.Run([](PipelineFrame*) { return false; },
                         [&](PipelineFrame&&) { return ++calls > 0; }),
            0);
  EXPECT_EQ(calls, 0);
}

}  // namespace
}  // namespace corridor
