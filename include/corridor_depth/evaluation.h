#pragma once

// The evaluation engine of corridor_eval, for research code: scenes of images with ground
// truth -> per-frame records (EvaluateScenes) -> a report (BuildReport) -> the paper's tables
// (ReportTables).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/dataset.h"
#include "corridor_depth/depth_metrics.h"
#include "corridor_depth/recover_depth.h"
#include "corridor_depth/status.h"

namespace corridor {

class JunctionTrack;
class SequencePrior;

// One scene of image files to evaluate: the frames of a dataset scene (io/dataset.h) or of a
// folder, with the camera they were taken with.
struct EvalScene {
  std::string name;                  // Scene name: the output folder and the report's row.
  Camera camera;                     // Checked, with a positive mount height.
  std::vector<DatasetFrame> frames;  // In order; depth/truth paths where the dataset has them.
  // > 0: each image gets a pinhole of its own size with this horizontal field of view (degrees)
  // and is read upright (EXIF orientation), as a photo viewer shows it; `camera` then serves only
  // for its mount height and for frames that cannot be read. 0: `camera` serves every frame and
  // images are read as stored (a calibration is for the image as stored).
  double per_image_hfov_deg = 0;
};

// The camera of one image: `scene_camera`, or, when per_image_hfov_deg > 0, a pinhole of the
// image's own size with that field of view and scene_camera's mount height.
Camera PerImageCamera(const Camera& scene_camera, double per_image_hfov_deg,
                      const cv::Size& image_size);

// PerImageCamera for a frame of `scene`.
Camera FrameCamera(const EvalScene& scene, const cv::Size& image_size);

// A dataset scene (LoadDataset) as an EvalScene: its name, camera and frames.
EvalScene EvalSceneFromDataset(const DatasetScene& scene);

// Pixel sums of AbsRel for the true depths in [k, k + 1) metres, bin k.
struct DepthBin {
  double abs_rel_sum = 0;  // Sum over the bin's pixels of |gt - pred| / gt.
  int64_t pixels = 0;      // Pixels with both ground truth in the bin and a prediction.
};

// Everything the evaluation learns about one frame: one row of corridor_eval's report.csv.
struct FrameRecord {
  std::string scene;                  // Scene name.
  std::string frame;                  // Frame name (the file name without extension).
  Status status;                      // ok, or why the frame failed (bad file, no lines, ...).
  bool ran = false;                   // True when the pipeline ran (times are then valid).
  bool has_estimate = false;          // True when status is ok: `estimate` is valid.
  CorridorGeometry estimate;          // The estimated geometry.
  bool has_truth = false;             // True when truth.yaml lists the frame.
  CorridorGeometry truth;             // The true geometry (valid when has_truth).
  bool ceiling_visible = false;       // The true ceiling/wall junctions are in view (ceiling_visibility.h).
  bool ceiling_estimated = false;     // The ceiling search found the ceiling (or a sequence held it): estimate.ceiling_height is its height.
  bool junctions_tracked = false;     // A sequence found the junctions near the previous frame's (RecoverDepthResult::junctions_tracked).
  double confidence = 0;              // RecoverDepthResult::confidence.
  FrameEvidence evidence;             // What the confidence rests on.
  bool has_depth_truth = false;       // True when the dataset has a ground-truth depth image.
  std::vector<DepthMetrics> metrics;  // One per cap; a failed frame with gt has coverage 0.
  std::vector<DepthBin> depth_bins;   // AbsRel by true depth, 1 m bins up to the largest cap.
  StageTimes times;                   // Per-stage wall time (valid when ran).
};

// What EvaluateFrame computes and writes.
struct FrameEvalOptions {
  std::vector<double> caps = {5.0, 40.0};  // Depth caps, m (the paper's Tables 2 and 3).
  std::string output_dir;                  // Where depth/ and vis/ go; "" writes nothing.
  bool write_depth = true;                 // Write <out>/depth/<scene>/<frame>.png (16-bit mm).
  bool write_vis = true;                   // Write <out>/vis/<scene>/<frame>.png.
  double vis_max_depth = 15.0;             // Top of the depth colour scale in vis/, m.
  double vis_max_error = 1.0;              // Top of the error colour scale in vis/, m.
};

// Relative output paths of a frame's pictures, "vis/<scene>/<frame>.png" and the depth PNG.
std::string VisRelativePath(const std::string& scene, const std::string& frame);
std::string DepthRelativePath(const std::string& scene, const std::string& frame);

// Evaluates scene.frames[index]: reads the image and its ground truth, recovers depth with the
// frame's camera (FrameCamera, eval_scene.h), and fills `record`. A frame that fails (unreadable
// file, no corridor, depth/colour size mismatch) is a record with a non-ok status, not an error.
// Returns non-ok only when an output cannot be written. With a `prior` (a sequence; may be null)
// the frame is reconstructed with the previous frame's geometry (hidden junction, held width),
// and the prior is updated. With a `track` (may be null) the junctions are sought near the
// previous frame's first (JunctionTrack).
Status EvaluateFrame(const EvalScene& scene, size_t index, const DepthRecoverer& recoverer,
                     const FrameEvalOptions& options, FrameRecord* record,
                     SequencePrior* prior = nullptr, JunctionTrack* track = nullptr);

// Adds the AbsRel of pred against gt in 1 m bins of gt, for gt in (0, max_depth], to `bins`
// (resized to ceil(max_depth) bins when smaller). Uses ComputeDepthMetrics per bin.
void AccumulateDepthBins(const cv::Mat& pred, const cv::Mat& gt, double max_depth,
                         std::vector<DepthBin>* bins);

// How EvaluateScenes spreads the work.
struct EvalRunOptions {
  int threads = 1;        // Worker threads, >= 1.
  bool sequence = false;  // Each scene is a sequence: its frames in order on one thread, with the previous frame's geometry.
  // Called after each frame with the frames done so far and the total, one call at a time (from
  // any worker thread); empty = none.
  std::function<void(size_t done, size_t total)> progress;
};

// The thread count for --threads: 0 -> hardware concurrency (at least 1); negative ->
// InvalidArgument.
Status ResolveThreadCount(int flag, int* threads);

// Evaluates every frame of every scene, in parallel, and stores the records in dataset order
// (scene by scene, frame by frame), so the result does not depend on the thread count. Returns
// non-ok (and stops early) only when an output cannot be written.
Status EvaluateScenes(const std::vector<EvalScene>& scenes, const DepthRecoverer& recoverer,
                      const FrameEvalOptions& frame_options, const EvalRunOptions& run_options,
                      std::vector<FrameRecord>* records);

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

// A table as text cells, rendered as Markdown or HTML.
struct TextTable {
  std::string id;                              // Anchor name, e.g. "table1".
  std::string title;                           // Caption, e.g. "Table 1: ...".
  std::vector<std::string> header;             // Column titles.
  std::vector<std::vector<std::string>> rows;  // Cells, row by row.
  std::vector<bool> summary;                   // Per row: a group row (all/easy/hard), in bold.
  std::string note;                            // A footnote ("" for none).
};

// The report's tables for the first configuration, in the paper's layout: Table 1 (width),
// one depth table per cap (Tables 2, 3: AbsRel, Log10, RMSE, RMSElog first), pose errors,
// timing, and, with more than one configuration, a Table 4-style comparison on the "all" row;
// failures last when there are any.
std::vector<TextTable> ReportTables(const std::vector<EvalReport>& configs);

// A number with `decimals` decimals, "-" for NaN.
std::string FormatNumber(double value, int decimals);

// "depth < 5 m" for a cap.
std::string CapLabel(double cap);

}  // namespace corridor
