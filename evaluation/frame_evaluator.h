#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/corridor_geometry.h"
#include "core/status.h"
#include "evaluation/depth_metrics.h"
#include "evaluation/eval_scene.h"
#include "pipeline/recover_depth.h"
#include "pipeline/sequence_prior.h"

namespace corridor {

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

}  // namespace corridor
