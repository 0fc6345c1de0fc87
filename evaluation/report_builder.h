#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/status.h"
#include "evaluation/depth_metrics.h"
#include "evaluation/frame_evaluator.h"

namespace corridor {

// "Unknown" in the summaries (written as null / empty / "-").
inline constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

// Corridor width of a scene or group (the paper's Table 1).
struct WidthSummary {
  double estimated = kUnknown;             // Mean estimated width (frames with an estimate), m.
  double truth = kUnknown;                 // Mean true width over frames with truth, m.
  double rel_error = kUnknown;             // Scene: |est - truth| / truth; group: mean of scenes'.
  double mean_frame_rel_error = kUnknown;  // Mean of |w_est - w_true| / w_true over frames.
  int num_estimated = 0;                   // Frames with an estimate.
  int num_truth = 0;                       // Frames with a true width.
  int num_gross = 0;                       // Frames whose width is more than kGrossWidthError off: the wrong line taken, not noise.
};

// A frame's width this far off (relative) counts as a gross error (WidthSummary::num_gross).
inline constexpr double kGrossWidthError = 0.05;

// Mean absolute errors of the estimated pose against truth.yaml.
struct PoseErrorSummary {
  double yaw = kUnknown;     // Mean |yaw_est - yaw_true|, rad.
  double pitch = kUnknown;   // Mean |pitch_est - pitch_true|, rad.
  double offset = kUnknown;  // Mean |offset_est - offset_true|, m.
  int num_frames = 0;        // Frames with both an estimate and truth.
};

// The ceiling height (beyond the paper) over the frames whose true ceiling junctions are in view.
struct CeilingSummary {
  double mean_rel_error = kUnknown;  // Mean |H_est - H_true| / H_true over the visible frames found.
  double max_rel_error = kUnknown;   // Largest of those errors.
  int num_visible = 0;               // Frames whose true ceiling junction is in view.
  int num_found = 0;                 // Of those, frames where the ceiling search found a height.
  int num_within = 0;                // Of those found, frames within kCeilingTolerance.
};

// The ceiling criterion: an estimate within 3% of the true height.
inline constexpr double kCeilingTolerance = 0.03;

// Median and 90th percentile of one stage's time, seconds.
struct TimeSummary {
  double median = kUnknown;  // Linear-interpolated 50th percentile.
  double p90 = kUnknown;     // Linear-interpolated 90th percentile.
};

// Per-stage times over the frames that ran the pipeline.
struct TimingSummary {
  TimeSummary perception;  // Junction-line detection.
  TimeSummary solve;       // Geometry estimation.
  TimeSummary rasterize;   // Dense depth.
  TimeSummary total;       // The whole Recover call.
  int num_frames = 0;      // Frames timed.
};

// One row of the tables: a scene, or a group of scenes ("all", "easy", "hard").
struct GroupSummary {
  std::string name;                 // Scene or group name.
  int num_frames = 0;               // Frames in it.
  int num_failed = 0;               // Frames with a non-ok status.
  int num_depth_truth = 0;          // Frames that have a ground-truth depth image.
  std::vector<DepthMetrics> depth;  // One per cap: AverageDepthMetrics of the per-image metrics.
  WidthSummary width;               // Table 1.
  PoseErrorSummary pose;            // Pose errors.
  CeilingSummary ceiling;           // Ceiling height where it is in view.
  TimingSummary timing;             // Per-stage times.
};

// AbsRel of all pixels whose true depth is in (start, end].
struct DepthBinSummary {
  double start = 0;           // Bin start, m.
  double end = 0;             // Bin end, m.
  double abs_rel = kUnknown;  // Pixel-weighted AbsRel; NaN when the bin is empty.
  int64_t pixels = 0;         // Pixels in the bin that have a prediction.
};

// A frame listed as failed, with its reason.
struct FailureEntry {
  std::string scene;   // Scene name.
  std::string frame;   // Frame name.
  std::string reason;  // Status::ToString() of the failure.
};

// One configuration's whole evaluation.
struct EvalReport {
  std::string solver;                       // Solver name.
  std::string rasterizer;                   // Rasteriser name.
  std::vector<double> caps;                 // Depth caps, m.
  std::vector<GroupSummary> scenes;         // In dataset order.
  GroupSummary all;                         // Every image of every scene.
  std::vector<GroupSummary> groups;         // "easy" and "hard" when scene names say so.
  std::vector<DepthBinSummary> depth_bins;  // AbsRel against true depth, 1 m bins.
  std::vector<FailureEntry> failures;       // Frames that failed, in dataset order.
  std::vector<FrameRecord> frames;          // Every frame, in dataset order.
  std::string ConfigName() const { return solver + ":" + rasterizer; }
};

// Aggregates the records (dataset order) into scenes, groups and the "all" row.
EvalReport BuildReport(const std::vector<FrameRecord>& frames, const std::vector<double>& caps,
                       const std::string& solver, const std::string& rasterizer);

// "easy" for names like Cord_E01 or E1 (an "E" at the start or after "_", then a digit),
// "hard" likewise with "H", "" otherwise.
std::string SceneDifficulty(const std::string& scene);

// The JSON/CSV key of a cap: 5 -> "lt5", 2.5 -> "lt2p5".
std::string CapKey(double cap);

// Parses --caps ("5,40"): positive finite numbers, distinct keys; InvalidArgument otherwise.
Status ParseCaps(const std::string& text, std::vector<double>* caps);

// The p-th percentile (p in [0, 100]) with linear interpolation; NaN for no values.
double Percentile(std::vector<double> values, double p);

}  // namespace corridor
