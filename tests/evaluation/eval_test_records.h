#pragma once

// Hand-made frame records with round numbers, for the aggregation and report tests.

#include <limits>
#include <string>
#include <vector>

#include "corridor_depth/evaluation.h"

namespace corridor {
namespace testing_util {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Per-image metrics with the given AbsRel, RMSE and coverage for every cap.
inline DepthMetrics Metrics(double abs_rel, double rmse, double coverage) {
  DepthMetrics m;
  m.abs_rel = abs_rel;
  m.rmse = rmse;
  m.sq_rel = m.rmse_log = m.rmse_log10 = m.log10 = abs_rel / 2;
  m.delta1 = m.delta2 = m.delta3 = 1 - abs_rel;
  m.coverage = coverage;
  m.num_gt = 100;
  m.num_evaluated = static_cast<int64_t>(coverage * 100);
  return m;
}

inline FrameRecord Ok(const std::string& scene, const std::string& frame, double est_width,
                      double true_width, double est_yaw, double true_yaw, double abs_rel,
                      double coverage, double total_s) {
  FrameRecord f;
  f.scene = scene;
  f.frame = frame;
  f.ran = f.has_estimate = f.has_truth = f.has_depth_truth = true;
  f.estimate.width = est_width;
  f.truth.width = true_width;
  f.estimate.yaw = est_yaw;
  f.truth.yaw = true_yaw;
  f.estimate.pitch = 0.05;
  f.truth.pitch = 0.04;
  f.estimate.offset = 0.1;
  f.truth.offset = -0.1;
  f.metrics = {Metrics(abs_rel, 2 * abs_rel, coverage), Metrics(abs_rel, 3 * abs_rel, coverage)};
  f.times.total = total_s;
  f.times.perception = total_s / 2;
  return f;
}

// For caps {1.5, 2}. Scene Cord_E01: two good frames; Cord_H01: a good one and a failed one.
inline std::vector<FrameRecord> Frames() {
  std::vector<FrameRecord> frames;
  frames.push_back(Ok("Cord_E01", "000", 2.0, 2.1, 0.10, 0.12, 0.1, 0.8, 0.010));
  frames.push_back(Ok("Cord_E01", "001", 2.3, 2.1, 0.20, 0.12, 0.2, 0.6, 0.030));
  frames.push_back(Ok("Cord_H01", "000", 3.3, 3.0, 0.00, 0.02, 0.4, 0.5, 0.020));
  FrameRecord failed;
  failed.scene = "Cord_H01";
  failed.frame = "001";
  failed.status = Status::NoCorridorFound("no lines");
  failed.ran = true;
  failed.has_truth = failed.has_depth_truth = true;
  failed.truth.width = 3.0;
  DepthMetrics none = Metrics(kNaN, kNaN, 0.0);
  none.num_evaluated = 0;
  failed.metrics = {none, none};
  failed.times.total = 0.040;
  frames.push_back(failed);
  frames[0].depth_bins = {{1.0, 10}, {0.0, 0}};
  frames[1].depth_bins = {{2.0, 10}, {3.0, 10}};
  return frames;
}

}  // namespace testing_util
}  // namespace corridor
