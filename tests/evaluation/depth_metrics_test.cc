#include "corridor_depth/depth_metrics.h"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

namespace corridor {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTol = 1e-12;

// A rows x cols CV_32F image from row-major values (all exact in float).
cv::Mat Image(int rows, int cols, const std::vector<float>& values) {
  cv::Mat m(rows, cols, CV_32F);
  for (int i = 0; i < rows * cols; ++i) m.at<float>(i / cols, i % cols) = values[i];
  return m;
}

void ExpectErrorsNaN(const DepthMetrics& m) {
  for (double v : {m.abs_rel, m.sq_rel, m.rmse, m.rmse_log, m.rmse_log10, m.log10, m.delta1,
                   m.delta2, m.delta3}) {
    EXPECT_TRUE(std::isnan(v));
  }
}

TEST(DepthMetricsTest, EveryErrorMetricOnThreePixels) {
  // Pixels (gt, pred): (2, 1), (4, 4), (1, 2); the fourth has gt = 0 and is ignored.
  const cv::Mat gt = Image(2, 2, {2, 4, 1, 0});
  const cv::Mat pred = Image(2, 2, {1, 4, 2, 3});
  const DepthMetrics m = ComputeDepthMetrics(pred, gt, 40.0);
  EXPECT_EQ(m.num_gt, 3);
  EXPECT_EQ(m.num_evaluated, 3);
  EXPECT_EQ(m.num_images, 1);
  EXPECT_DOUBLE_EQ(m.coverage, 1.0);
  // |gt - pred| / gt = 1/2, 0, 1/1 -> mean 1.5 / 3 = 0.5.
  EXPECT_NEAR(m.abs_rel, 0.5, kTol);
  // (gt - pred)^2 / gt = 1/2, 0, 1/1 -> mean 0.5.
  EXPECT_NEAR(m.sq_rel, 0.5, kTol);
  // (gt - pred)^2 = 1, 0, 1 -> sqrt(2/3).
  EXPECT_NEAR(m.rmse, std::sqrt(2.0 / 3.0), kTol);
  // (ln gt - ln pred)^2 = ln2^2, 0, ln2^2 -> ln2 * sqrt(2/3) = 0.693147... * 0.816496...
  EXPECT_NEAR(m.rmse_log, 0.6931471805599453 * 0.816496580927726, kTol);
  // Same in log10: log10(2) = 0.30102999566398120.
  EXPECT_NEAR(m.rmse_log10, 0.3010299956639812 * 0.816496580927726, kTol);
  // |log10 gt - log10 pred| = log10 2, 0, log10 2 -> 2 log10(2) / 3.
  EXPECT_NEAR(m.log10, 2.0 * 0.3010299956639812 / 3.0, kTol);
  // Ratios max(gt/pred, pred/gt) = 2, 1, 2: only the exact pixel passes any threshold.
  EXPECT_NEAR(m.delta1, 1.0 / 3.0, kTol);
  EXPECT_NEAR(m.delta2, 1.0 / 3.0, kTol);
  EXPECT_NEAR(m.delta3, 1.0 / 3.0, kTol);
}

TEST(DepthMetricsTest, DeltaThresholdsAreStrictAndSymmetric) {
  // Ratios: 4/4 = 1, 3/2 = 1.5 (pred > gt), 1.75/1 = 1.75, 2/1 = 2, 5/4 = 1.25 exactly.
  const cv::Mat gt = Image(1, 5, {4, 2, 1.75f, 2, 5});
  const cv::Mat pred = Image(1, 5, {4, 3, 1, 1, 4});
  const DepthMetrics m = ComputeDepthMetrics(pred, gt, 40.0);
  // < 1.25: only ratio 1 (1.25 itself fails the strict test) -> 1/5.
  EXPECT_NEAR(m.delta1, 0.2, kTol);
  // < 1.5625: ratios 1, 1.25, 1.5 -> 3/5.
  EXPECT_NEAR(m.delta2, 0.6, kTol);
  // < 1.953125: ratios 1, 1.25, 1.5, 1.75 -> 4/5.
  EXPECT_NEAR(m.delta3, 0.8, kTol);
}

TEST(DepthMetricsTest, CapExcludesFarGroundTruthButKeepsTheCapItself) {
  // (gt, pred): (2, 2), (6, 1), (5, 5), (0, 1).
  const cv::Mat gt = Image(2, 2, {2, 6, 5, 0});
  const cv::Mat pred = Image(2, 2, {2, 1, 5, 1});
  // cap 5: gt 6 is out, gt 5 (== cap) is in -> two exact pixels.
  const DepthMetrics capped = ComputeDepthMetrics(pred, gt, 5.0);
  EXPECT_EQ(capped.num_gt, 2);
  EXPECT_EQ(capped.num_evaluated, 2);
  EXPECT_DOUBLE_EQ(capped.rmse, 0.0);
  EXPECT_DOUBLE_EQ(capped.abs_rel, 0.0);
  EXPECT_DOUBLE_EQ(capped.delta1, 1.0);
  // cap 40: (6, 1) joins: squared errors 0, 25, 0 -> rmse sqrt(25/3); abs_rel (5/6)/3 = 5/18.
  const DepthMetrics wide = ComputeDepthMetrics(pred, gt, 40.0);
  EXPECT_EQ(wide.num_gt, 3);
  EXPECT_NEAR(wide.rmse, std::sqrt(25.0 / 3.0), kTol);
  EXPECT_NEAR(wide.abs_rel, 5.0 / 18.0, kTol);
  EXPECT_NEAR(wide.delta1, 2.0 / 3.0, kTol);
}

TEST(DepthMetricsTest, CoverageCountsMissingAndInvalidPredictions) {
  // gt all valid (4 pixels); pred: 2 (ok), 0 (none), NaN (none), -1 (none) -> coverage 1/4.
  const cv::Mat gt = Image(2, 2, {2, 4, 1, 8});
  const cv::Mat pred = Image(2, 2, {2, 0, static_cast<float>(kNaN), -1});
  const DepthMetrics m = ComputeDepthMetrics(pred, gt, 40.0);
  EXPECT_EQ(m.num_gt, 4);
  EXPECT_EQ(m.num_evaluated, 1);
  EXPECT_DOUBLE_EQ(m.coverage, 0.25);
  // Errors only over the one pixel with both, which is exact.
  EXPECT_DOUBLE_EQ(m.rmse, 0.0);
  EXPECT_DOUBLE_EQ(m.delta1, 1.0);
}

TEST(DepthMetricsTest, NonFiniteGroundTruthIsNotGroundTruth) {
  // gt: NaN, +inf, -2, 3 -> only the 3 counts, even with an infinite cap; pred 3 there.
  const cv::Mat gt =
      Image(4, 1, {static_cast<float>(kNaN), static_cast<float>(kInf), -2, 3});
  const cv::Mat pred = Image(4, 1, {1, 1, 1, 3});
  const DepthMetrics m = ComputeDepthMetrics(pred, gt, kInf);
  EXPECT_EQ(m.num_gt, 1);
  EXPECT_EQ(m.num_evaluated, 1);
  EXPECT_DOUBLE_EQ(m.abs_rel, 0.0);
  EXPECT_DOUBLE_EQ(m.coverage, 1.0);
}

TEST(DepthMetricsTest, NoGroundTruthGivesNaNCoverage) {
  const DepthMetrics m = ComputeDepthMetrics(Image(1, 2, {1, 2}), Image(1, 2, {0, 0}), 40.0);
  EXPECT_EQ(m.num_gt, 0);
  EXPECT_TRUE(std::isnan(m.coverage));
  ExpectErrorsNaN(m);
}

TEST(DepthMetricsTest, GroundTruthWithoutPredictionsGivesZeroCoverage) {
  const DepthMetrics m = ComputeDepthMetrics(Image(1, 2, {0, 0}), Image(1, 2, {1, 2}), 40.0);
  EXPECT_EQ(m.num_gt, 2);
  EXPECT_EQ(m.num_evaluated, 0);
  EXPECT_DOUBLE_EQ(m.coverage, 0.0);
  ExpectErrorsNaN(m);
}

TEST(DepthMetricsTest, MismatchedInputsEvaluateNothing) {
  const DepthMetrics sizes = ComputeDepthMetrics(Image(1, 2, {1, 2}), Image(2, 1, {1, 2}), 40.0);
  EXPECT_EQ(sizes.num_gt, 0);
  EXPECT_TRUE(std::isnan(sizes.coverage));
  ExpectErrorsNaN(sizes);
  const cv::Mat doubles(1, 2, CV_64F, cv::Scalar(1.0));
  const DepthMetrics types = ComputeDepthMetrics(doubles, Image(1, 2, {1, 2}), 40.0);
  EXPECT_EQ(types.num_gt, 0);
  ExpectErrorsNaN(types);
}

DepthMetrics Record(double abs_rel, double rmse, double coverage, int64_t num_gt,
                    int64_t num_evaluated) {
  DepthMetrics m;
  m.abs_rel = m.sq_rel = m.rmse_log = m.rmse_log10 = m.log10 = abs_rel;
  m.rmse = rmse;
  m.delta1 = m.delta2 = m.delta3 = abs_rel;
  m.coverage = coverage;
  m.num_gt = num_gt;
  m.num_evaluated = num_evaluated;
  return m;
}

TEST(DepthMetricsTest, AverageSkipsNaNPerFieldAndCoverageWithoutGroundTruth) {
  const std::vector<DepthMetrics> images = {
      Record(0.5, 2.0, 1.0, 10, 10),   // A: full coverage.
      Record(kNaN, kNaN, 0.0, 4, 0),   // B: gt but no prediction.
      Record(kNaN, kNaN, kNaN, 0, 0),  // C: no gt at all.
      Record(0.1, 4.0, 0.5, 6, 3),     // D: half coverage.
  };
  const DepthMetrics avg = AverageDepthMetrics(images);
  // Errors over A and D: (0.5 + 0.1) / 2 = 0.3, (2 + 4) / 2 = 3.
  EXPECT_NEAR(avg.abs_rel, 0.3, kTol);
  EXPECT_NEAR(avg.log10, 0.3, kTol);
  EXPECT_NEAR(avg.delta3, 0.3, kTol);
  EXPECT_NEAR(avg.rmse, 3.0, kTol);
  // Coverage over A, B, D (C has no gt): (1 + 0 + 0.5) / 3 = 0.5.
  EXPECT_NEAR(avg.coverage, 0.5, kTol);
  // Counts: 10 + 4 + 0 + 6 = 20 gt pixels, 10 + 0 + 0 + 3 = 13 evaluated, 4 images.
  EXPECT_EQ(avg.num_gt, 20);
  EXPECT_EQ(avg.num_evaluated, 13);
  EXPECT_EQ(avg.num_images, 4);
}

TEST(DepthMetricsTest, AverageOfNothingIsNaN) {
  const DepthMetrics all_nan = AverageDepthMetrics({Record(kNaN, kNaN, kNaN, 0, 0)});
  ExpectErrorsNaN(all_nan);
  EXPECT_TRUE(std::isnan(all_nan.coverage));
  EXPECT_EQ(all_nan.num_images, 1);
  const DepthMetrics empty = AverageDepthMetrics({});
  ExpectErrorsNaN(empty);
  EXPECT_EQ(empty.num_images, 0);
}

TEST(DepthMetricsTest, RelativeError) {
  EXPECT_DOUBLE_EQ(RelativeError(1.5, 2.0), 0.25);  // |1.5 - 2| / 2.
  EXPECT_DOUBLE_EQ(RelativeError(2.5, 2.0), 0.25);  // |2.5 - 2| / 2.
  EXPECT_DOUBLE_EQ(RelativeError(2.0, 2.0), 0.0);
  EXPECT_TRUE(std::isnan(RelativeError(2.0, 0.0)));
  EXPECT_TRUE(std::isnan(RelativeError(2.0, -1.0)));
  EXPECT_TRUE(std::isnan(RelativeError(kNaN, 2.0)));
}

}  // namespace
}  // namespace corridor
