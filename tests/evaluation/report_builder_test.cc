#include "corridor_depth/evaluation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/evaluation/eval_test_records.h"

namespace corridor {
namespace {

using testing_util::Frames;

TEST(ReportBuilder, ScenesMatchHandComputedValues) {
  const EvalReport r = BuildReport(Frames(), {1.5, 2.0}, "grid", "paper");
  EXPECT_EQ(r.ConfigName(), "grid:paper");
  ASSERT_EQ(r.scenes.size(), 2u);
  const GroupSummary& e = r.scenes[0];
  EXPECT_EQ(e.name, "Cord_E01");
  EXPECT_EQ(e.num_frames, 2);
  EXPECT_EQ(e.num_failed, 0);
  EXPECT_NEAR(e.width.estimated, 2.15, 1e-12);
  EXPECT_NEAR(e.width.truth, 2.1, 1e-12);
  EXPECT_NEAR(e.width.rel_error, 0.05 / 2.1, 1e-12);
  EXPECT_NEAR(e.width.mean_frame_rel_error, (0.1 / 2.1 + 0.2 / 2.1) / 2, 1e-12);
  EXPECT_EQ(e.width.num_gross, 1);  // 9.5% off; 4.8% is not gross.
  ASSERT_EQ(e.depth.size(), 2u);
  EXPECT_NEAR(e.depth[0].abs_rel, 0.15, 1e-12);
  EXPECT_NEAR(e.depth[0].rmse, 0.3, 1e-12);
  EXPECT_NEAR(e.depth[1].rmse, 0.45, 1e-12);
  EXPECT_NEAR(e.depth[0].coverage, 0.7, 1e-12);
  EXPECT_EQ(e.depth[0].num_images, 2);
  EXPECT_NEAR(e.pose.yaw, (0.02 + 0.08) / 2, 1e-12);
  EXPECT_NEAR(e.pose.pitch, 0.01, 1e-12);
  EXPECT_NEAR(e.pose.offset, 0.2, 1e-12);
  EXPECT_EQ(e.pose.num_frames, 2);
  EXPECT_NEAR(e.timing.total.median, 0.020, 1e-12);

  const GroupSummary& h = r.scenes[1];
  EXPECT_EQ(h.num_failed, 1);
  EXPECT_NEAR(h.width.estimated, 3.3, 1e-12);  // Only the frame with an estimate.
  EXPECT_NEAR(h.width.truth, 3.0, 1e-12);
  EXPECT_NEAR(h.width.rel_error, 0.1, 1e-12);
  EXPECT_NEAR(h.depth[0].abs_rel, 0.4, 1e-12);    // The failed image has no error...
  EXPECT_NEAR(h.depth[0].coverage, 0.25, 1e-12);  // ...but counts with coverage 0.
  EXPECT_EQ(h.depth[0].num_images, 2);
}

TEST(ReportBuilder, AllRowAveragesImagesNotScenes) {
  const EvalReport r = BuildReport(Frames(), {1.5, 2.0}, "grid", "paper");
  const GroupSummary& a = r.all;
  EXPECT_EQ(a.name, "all");
  EXPECT_EQ(a.num_frames, 4);
  EXPECT_EQ(a.num_failed, 1);
  EXPECT_NEAR(a.depth[0].abs_rel, (0.1 + 0.2 + 0.4) / 3, 1e-12);  // Not (0.15 + 0.4) / 2.
  EXPECT_NEAR(a.depth[0].coverage, (0.8 + 0.6 + 0.5 + 0.0) / 4, 1e-12);
  EXPECT_EQ(a.depth[0].num_images, 4);
  EXPECT_EQ(a.depth[0].num_gt, 400);
  // Width: the mean of the scenes' relative errors, as the paper's "mean relative error".
  EXPECT_NEAR(a.width.rel_error, (0.05 / 2.1 + 0.1) / 2, 1e-12);
  EXPECT_TRUE(std::isnan(a.width.estimated));
  // Times of the four frames 10, 30, 20, 40 ms: median 25, p90 37 (linear interpolation).
  EXPECT_NEAR(a.timing.total.median, 0.025, 1e-12);
  EXPECT_NEAR(a.timing.total.p90, 0.037, 1e-12);
  EXPECT_NEAR(a.timing.perception.median, 0.0075, 1e-12);  // 5, 15, 10 ms and the failure's 0.
  EXPECT_EQ(a.timing.num_frames, 4);

  ASSERT_EQ(r.failures.size(), 1u);
  EXPECT_EQ(r.failures[0].scene, "Cord_H01");
  EXPECT_EQ(r.failures[0].frame, "001");
  EXPECT_NE(r.failures[0].reason.find("no lines"), std::string::npos);
}

TEST(ReportBuilder, EasyAndHardGroups) {
  const EvalReport r = BuildReport(Frames(), {1.5, 2.0}, "grid", "paper");
  ASSERT_EQ(r.groups.size(), 2u);
  EXPECT_EQ(r.groups[0].name, "easy");
  EXPECT_EQ(r.groups[0].num_frames, 2);
  EXPECT_NEAR(r.groups[0].depth[0].abs_rel, 0.15, 1e-12);
  EXPECT_EQ(r.groups[1].name, "hard");
  EXPECT_NEAR(r.groups[1].width.rel_error, 0.1, 1e-12);

  std::vector<FrameRecord> plain = Frames();
  for (auto& f : plain) f.scene = "hallway";
  EXPECT_TRUE(BuildReport(plain, {1.5, 2.0}, "grid", "paper").groups.empty());
}

TEST(ReportBuilder, DepthBinsArePixelWeighted) {
  const EvalReport r = BuildReport(Frames(), {1.5, 2.0}, "grid", "paper");
  ASSERT_EQ(r.depth_bins.size(), 2u);
  EXPECT_NEAR(r.depth_bins[0].abs_rel, 3.0 / 20, 1e-12);
  EXPECT_EQ(r.depth_bins[0].pixels, 20);
  EXPECT_NEAR(r.depth_bins[1].abs_rel, 0.3, 1e-12);
  EXPECT_DOUBLE_EQ(r.depth_bins[1].start, 1.0);
  EXPECT_DOUBLE_EQ(r.depth_bins[1].end, 2.0);
}

// Ceiling rows by hand: frames in view count whether or not they were found; the error is
// |H_est - H_true| / H_true over those found, and "within" means at most 3%.
TEST(ReportBuilder, CeilingCountsFramesInViewFoundAndWithinTolerance) {
  std::vector<FrameRecord> frames = Frames();
  for (FrameRecord& f : frames) {
    f.truth.camera_height = 0.5;
    f.truth.ceiling_height = 2.5;
  }
  frames[0].ceiling_visible = frames[0].ceiling_estimated = true;
  frames[0].estimate.ceiling_height = 2.55;  // 2% off: within.
  frames[1].ceiling_visible = frames[1].ceiling_estimated = true;
  frames[1].estimate.ceiling_height = 2.75;  // 10% off.
  frames[2].ceiling_visible = true;          // In view, not found.
  frames[2].ceiling_estimated = false;
  frames[3].ceiling_visible = false;  // Failed frame, not in view: not counted.
  const EvalReport r = BuildReport(frames, {1.5, 2.0}, "grid", "paper");
  const CeilingSummary& e = r.scenes[0].ceiling;
  EXPECT_EQ(e.num_visible, 2);
  EXPECT_EQ(e.num_found, 2);
  EXPECT_EQ(e.num_within, 1);
  EXPECT_NEAR(e.mean_rel_error, (0.02 + 0.10) / 2, 1e-12);
  EXPECT_NEAR(e.max_rel_error, 0.10, 1e-12);
  const CeilingSummary& h = r.scenes[1].ceiling;
  EXPECT_EQ(h.num_visible, 1);
  EXPECT_EQ(h.num_found, 0);
  EXPECT_TRUE(std::isnan(h.mean_rel_error));
  EXPECT_EQ(r.all.ceiling.num_visible, 3);
  EXPECT_EQ(r.all.ceiling.num_within, 1);
}

TEST(ReportBuilder, SceneDifficulty) {
  EXPECT_EQ(SceneDifficulty("Cord_E01_z"), "easy");
  EXPECT_EQ(SceneDifficulty("Cord_H02_z"), "hard");
  EXPECT_EQ(SceneDifficulty("E3"), "easy");
  EXPECT_EQ(SceneDifficulty("H12_corridor"), "hard");
  EXPECT_EQ(SceneDifficulty("Hallway"), "");
  EXPECT_EQ(SceneDifficulty("office_Entrance"), "");
  EXPECT_EQ(SceneDifficulty("CE01"), "");
}

TEST(ReportBuilder, CapKeysAndParsing) {
  EXPECT_EQ(CapKey(5), "lt5");
  EXPECT_EQ(CapKey(40), "lt40");
  EXPECT_EQ(CapKey(2.5), "lt2p5");
  std::vector<double> caps;
  ASSERT_TRUE(ParseCaps("5,40", &caps).ok());
  EXPECT_EQ(caps, (std::vector<double>{5, 40}));
  ASSERT_TRUE(ParseCaps(" 2.5 , 10 ", &caps).ok());
  EXPECT_EQ(caps, (std::vector<double>{2.5, 10}));
  for (const std::string bad : {"", "5,", "five", "5,-1", "0", "5,5.0", "nan", "5;40", "1e9"}) {
    const Status status = ParseCaps(bad, &caps);
    EXPECT_EQ(status.code(), StatusCode::kInvalidArgument) << bad;
    EXPECT_NE(status.message().find("--caps"), std::string::npos) << status.message();
  }
}

TEST(ReportBuilder, Percentile) {
  EXPECT_TRUE(std::isnan(Percentile({}, 50)));
  EXPECT_DOUBLE_EQ(Percentile({3}, 90), 3);
  EXPECT_DOUBLE_EQ(Percentile({4, 1, 3, 2}, 50), 2.5);
  EXPECT_DOUBLE_EQ(Percentile({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}, 90), 10);
  EXPECT_DOUBLE_EQ(Percentile({1, 2}, 100), 2);
}

}  // namespace
}  // namespace corridor
