#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

namespace corridor {

// Depth metrics of docs/geometry.md, section 7, for one image or averaged over a scene.
struct DepthMetrics {
  double abs_rel = 0;         // mean |gt - pred| / gt
  double sq_rel = 0;          // mean (gt - pred)^2 / gt
  double rmse = 0;            // sqrt(mean (gt - pred)^2)
  double rmse_log = 0;        // sqrt(mean (ln gt - ln pred)^2)   (standard)
  double rmse_log10 = 0;      // sqrt(mean (log10 gt - log10 pred)^2)   (the paper's printed RMSElog)
  double log10 = 0;           // mean |log10 gt - log10 pred|
  double delta1 = 0;          // fraction with max(gt/pred, pred/gt) < 1.25
  double delta2 = 0;          // ... < 1.25^2
  double delta3 = 0;          // ... < 1.25^3
  double coverage = 0;        // predicted (> 0) pixels among those with 0 < gt <= cap
  int64_t num_gt = 0;         // Pixels with 0 < gt <= cap.
  int64_t num_evaluated = 0;  // Of those, pixels that also have a prediction > 0.
  int num_images = 1;         // Images averaged into this record.
};

// Metrics over pixels with 0 < gt <= cap (metres); pred and gt are CV_32F metres, 0 = none.
// Non-finite values count as "none" in either image. When no pixel has both, the error fields
// are NaN and coverage is 0 (or NaN without gt). Inputs of different sizes or not CV_32FC1 are
// a caller's mistake: then every field is NaN and num_gt = 0.
DepthMetrics ComputeDepthMetrics(const cv::Mat& pred, const cv::Mat& gt, double cap);

// Per-image metrics averaged over images (each image weighs the same). Images whose error
// fields are NaN are left out of those fields' means but still count for coverage; coverage is
// averaged over the images that have ground-truth pixels. num_gt and num_evaluated are summed,
// num_images is per_image.size().
DepthMetrics AverageDepthMetrics(const std::vector<DepthMetrics>& per_image);

// |estimated - truth| / truth: the width's, as in the paper's Table 1, and the ceiling height's. NaN
// when truth is not positive.
double RelativeError(double estimated, double truth);

}  // namespace corridor
