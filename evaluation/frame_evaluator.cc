#include "corridor_depth/evaluation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "evaluation/ceiling_visibility.h"
#include "evaluation/frame_panel.h"
#include "corridor_depth/dataset.h"
#include "corridor_depth/image_io.h"
#include "perception/junction_tracker.h"
#include "pipeline/sequence_prior.h"

namespace corridor {
namespace {

namespace fs = std::filesystem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Metrics without usable ground truth: every field NaN, so that the image drops out of the
// averages; `coverage` 0 makes an image that should have had ground truth count against it.
DepthMetrics NoTruthMetrics(double coverage) {
  DepthMetrics m;
  m.abs_rel = m.sq_rel = m.rmse = m.rmse_log = m.rmse_log10 = m.log10 = kNaN;
  m.delta1 = m.delta2 = m.delta3 = kNaN;
  m.coverage = coverage;
  return m;
}

std::string Caption(const FrameRecord& record) {
  char text[200];
  if (record.has_estimate) {
    std::snprintf(text, sizeof(text), "%s/%s\nw=%.2fm off=%.2fm yaw=%.1fdeg pitch=%.1fdeg",
                  record.scene.c_str(), record.frame.c_str(), record.estimate.width,
                  record.estimate.offset, record.estimate.yaw * 180 / M_PI,
                  record.estimate.pitch * 180 / M_PI);
    return text;
  }
  return record.scene + "/" + record.frame + "\n" + record.status.ToString();
}

}  // namespace

std::string VisRelativePath(const std::string& scene, const std::string& frame) {
  return "vis/" + scene + "/" + frame + ".png";
}

std::string DepthRelativePath(const std::string& scene, const std::string& frame) {
  return "depth/" + scene + "/" + frame + ".png";
}

void AccumulateDepthBins(const cv::Mat& pred, const cv::Mat& gt, double max_depth,
                         std::vector<DepthBin>* bins) {
  const int num_bins = static_cast<int>(std::ceil(max_depth));
  if (static_cast<int>(bins->size()) < num_bins) bins->resize(num_bins);
  if (pred.size() != gt.size() || pred.type() != CV_32F || gt.type() != CV_32F) return;
  for (int k = 0; k < num_bins; ++k) {
    const double upper = std::min<double>(k + 1, max_depth);
    const cv::Mat in_bin = (gt > k) & (gt <= upper) & (pred > 0);
    if (cv::countNonZero(in_bin) == 0) continue;
    cv::Mat gt_bin = cv::Mat::zeros(gt.size(), CV_32F);
    gt.copyTo(gt_bin, in_bin);
    const DepthMetrics m = ComputeDepthMetrics(pred, gt_bin, upper);
    if (m.num_evaluated == 0 || std::isnan(m.abs_rel)) continue;
    (*bins)[k].abs_rel_sum += m.abs_rel * static_cast<double>(m.num_evaluated);
    (*bins)[k].pixels += m.num_evaluated;
  }
}

Status EvaluateFrame(const EvalScene& scene, size_t index, const DepthRecoverer& recoverer,
                     const FrameEvalOptions& options, FrameRecord* record, SequencePrior* prior,
                     JunctionTrack* track) {
  const DatasetFrame& frame = scene.frames[index];
  *record = FrameRecord();
  record->scene = scene.name;
  record->frame = frame.name;
  record->has_depth_truth = !frame.depth_path.empty();

  cv::Mat image, gt;
  Status status = ReadColorImage(frame.rgb_path, &image,
                                 scene.per_image_hfov_deg > 0 ? ImageOrientation::kUpright
                                                              : ImageOrientation::kAsStored);
  const Camera camera = image.empty() ? scene.camera : FrameCamera(scene, image.size());
  record->has_truth = frame.has_truth;
  if (frame.has_truth) {
    record->truth = frame.truth.geometry;
    record->ceiling_visible = CeilingJunctionVisible(record->truth, camera);
  }
  Status gt_status = Status::Ok();
  if (record->has_depth_truth) {
    gt_status = ReadDepthPng(frame.depth_path, &gt);
    if (gt_status.ok() && !image.empty()) {
      gt_status = CheckDepthMatchesImage(frame.depth_path, image.size(), gt);
    }
  }
  if (status.ok()) status = gt_status;

  RecoverDepthResult result;
  if (status.ok()) {
    record->ran = true;
    status = recoverer.Recover(image, camera, &result,
                               prior != nullptr ? prior->Previous() : nullptr, track);
    if (prior != nullptr) prior->Update(result);
    record->times = result.times;
    record->junctions_tracked = result.junctions_tracked;
    record->confidence = result.confidence;
    record->evidence = result.evidence;
  }
  record->status = status;
  record->has_estimate = status.ok() && result.has_geometry;
  if (record->has_estimate) record->estimate = result.geometry;
  record->ceiling_estimated = record->has_estimate &&
                              (result.ceiling.found || result.ceiling_held) &&
                              result.geometry.HasCeiling();

  // Ground truth that was read is evaluated, also when the frame failed (then nothing is
  // predicted, so coverage is 0); a status ok implies the sizes match.
  const bool gt_usable = !gt.empty();
  cv::Mat pred;
  if (status.ok() && !result.depth.empty()) {
    pred = result.depth;
  } else if (gt_usable) {
    pred = cv::Mat::zeros(gt.size(), CV_32F);
  }
  double max_cap = 0;
  for (double cap : options.caps) {
    max_cap = std::max(max_cap, cap);
    if (gt_usable) {
      record->metrics.push_back(ComputeDepthMetrics(pred, gt, cap));
    } else {
      record->metrics.push_back(NoTruthMetrics(record->has_depth_truth ? 0.0 : kNaN));
    }
  }
  if (gt_usable) AccumulateDepthBins(pred, gt, max_cap, &record->depth_bins);

  if (options.output_dir.empty()) return Status::Ok();
  const fs::path out(options.output_dir);
  if (options.write_depth && status.ok() && !result.depth.empty()) {
    const Status write =
        WriteDepthPng((out / DepthRelativePath(scene.name, frame.name)).string(), result.depth);
    if (!write.ok()) return write;
  }
  if (options.write_vis && !image.empty()) {
    EvalPanelScales scales;
    scales.max_depth = options.vis_max_depth;
    scales.max_error = options.vis_max_error;
    const cv::Mat panel = MakeEvalPanel(image, result, status.ok() ? result.depth : cv::Mat(), gt,
                                        scales, Caption(*record));
    const Status write =
        WriteImageAtomic((out / VisRelativePath(scene.name, frame.name)).string(), panel);
    if (!write.ok()) return write;
  }
  return Status::Ok();
}

}  // namespace corridor
