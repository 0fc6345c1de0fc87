// A result's memory is used again: the next frame of a thread renders into the previous depth's
// matrix and fills the previous junctions' vectors (junction_memory.h, the halving's and the
// depth's in the handover). A result filled again gives what a new one gives, a rolled frame's
// nested level recovery included, and another result of the thread never shares or overwrites
// its memory.
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "corridor_depth/recover_depth.h"
#include "synth/corridor_renderer.h"
#include "synth/real_buildings.h"
#include "tests/support/corridor_frame.h"

namespace corridor {
namespace {

// What a frame's result says, deep-copied.
struct Snapshot {
  Status status;
  CorridorGeometry geometry;
  double confidence = 0;
  cv::Mat depth;
  std::vector<Eigen::Vector2d> left, right;
  std::vector<cv::Vec4f> segments;
};

Snapshot Take(const RecoverDepthResult& r) {
  return {r.status, r.geometry, r.confidence, r.depth.clone(),
          r.junctions.left.support, r.junctions.right.support, r.junctions.segments};
}

// Byte for byte (NaN depths included).
bool SameDepth(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != b.type()) return false;
  if (a.empty()) return true;
  const cv::Mat ca = a.isContinuous() ? a : a.clone(), cb = b.isContinuous() ? b : b.clone();
  return std::memcmp(ca.data, cb.data, ca.total() * ca.elemSize()) == 0;
}

void ExpectSame(const Snapshot& expected, const RecoverDepthResult& r, const char* what) {
  EXPECT_EQ(r.status.code(), expected.status.code()) << what;
  EXPECT_EQ(r.geometry.width, expected.geometry.width) << what;
  EXPECT_EQ(r.geometry.yaw, expected.geometry.yaw) << what;
  EXPECT_EQ(r.geometry.pitch, expected.geometry.pitch) << what;
  EXPECT_EQ(r.confidence, expected.confidence) << what;
  EXPECT_TRUE(SameDepth(r.depth, expected.depth)) << what;
  EXPECT_EQ(r.junctions.left.support, expected.left) << what;
  EXPECT_EQ(r.junctions.right.support, expected.right) << what;
  EXPECT_EQ(r.junctions.segments, expected.segments) << what;
}

synth::Frame Frame(uint32_t seed, double yaw) {
  const Camera camera = Camera::FromHorizontalFov(640, 480, 70.0 * M_PI / 180, 1.3);
  return testing_util::RenderCorridorFrame(camera, 2.2, 2.7, seed,
                                           synth::CameraPose{yaw, 0.03, 0.1, 1.3, 2.0});
}

TEST(ResultMemoryTest, AResultFilledAgainMatchesANewOne) {
  const Camera camera = Camera::FromHorizontalFov(640, 480, 70.0 * M_PI / 180, 1.3);
  const synth::Frame a = Frame(3, 0.05), b = Frame(11, -0.08);
  std::unique_ptr<DepthRecoverer> recoverer;
  ASSERT_TRUE(DepthRecoverer::Create(RecoverDepthOptions(), &recoverer).ok());
  RecoverDepthResult fresh_a, fresh_b;
  ASSERT_TRUE(recoverer->Recover(a.bgr, camera, &fresh_a).ok()) << fresh_a.status.ToString();
  ASSERT_TRUE(recoverer->Recover(b.bgr, camera, &fresh_b).ok()) << fresh_b.status.ToString();
  const Snapshot want_a = Take(fresh_a), want_b = Take(fresh_b);
  ASSERT_FALSE(want_a.left.empty());
  ASSERT_FALSE(want_a.segments.empty());

  RecoverDepthResult reused;
  recoverer->Recover(a.bgr, camera, &reused);
  ExpectSame(want_a, reused, "a, first");
  recoverer->Recover(b.bgr, camera, &reused);
  ExpectSame(want_b, reused, "b after a");
  recoverer->Recover(a.bgr, camera, &reused);
  ExpectSame(want_a, reused, "a after b");

  // Another result of the thread, filled again and again, leaves this one as it was.
  RecoverDepthResult other;
  for (const synth::Frame* f : {&b, &a, &b}) recoverer->Recover(f->bgr, camera, &other);
  ExpectSame(want_a, reused, "a after another result's frames");
  ExpectSame(want_b, other, "the other result");
  EXPECT_NE(reused.depth.data, other.depth.data);
  // A copy of the depth held by the caller is not written by the next frame.
  const cv::Mat held = reused.depth;
  recoverer->Recover(b.bgr, camera, &reused);
  ExpectSame(want_b, reused, "b with a's depth held");
  EXPECT_TRUE(SameDepth(held, want_a.depth));
}

TEST(ResultMemoryTest, ARolledFrameRecoveredLevelAgainMatchesANewOne) {
  // Head scene 0, frame 9: rolled by -3 degrees, recovered level (a whole Detect and Reconstruct
  // inside the frame's Reconstruct).
  synth::RealBuildingsOptions preset_options;
  preset_options.scenes = 1;
  preset_options.frames = 11;
  std::vector<synth::ScenePreset> presets;
  ASSERT_TRUE(synth::RealBuildingsPreset("head", preset_options, &presets).ok());
  const synth::ScenePreset& preset = presets.back();
  synth::Frame rolled;
  ASSERT_TRUE(synth::RenderFrame(preset.scene, preset.camera, preset.poses[9], &rolled).ok());
  RecoverDepthOptions options;
  options.level_roll = true;
  std::unique_ptr<DepthRecoverer> recoverer;
  ASSERT_TRUE(DepthRecoverer::Create(options, &recoverer).ok());
  RecoverDepthResult fresh;
  ASSERT_TRUE(recoverer->Recover(rolled.bgr, preset.camera, &fresh).ok());
  ASSERT_NE(fresh.roll, 0);
  const Snapshot want = Take(fresh);
  RecoverDepthResult reused;
  for (int i = 0; i < 3; ++i) {
    recoverer->Recover(rolled.bgr, preset.camera, &reused);
    ExpectSame(want, reused, "rolled");
    EXPECT_EQ(reused.roll, fresh.roll);
  }
  ExpectSame(want, fresh, "the first result");
}

}  // namespace
}  // namespace corridor
