#include "tools/eval/plots.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "corridor_depth/evaluation.h"
#include "corridor_depth/image_io.h"
#include "tools/eval/plot_canvas.h"

namespace corridor {
namespace {

constexpr int kWidth = 900, kHeight = 420;

// Distinct BGR colours for series.
cv::Scalar SeriesColor(size_t i) {
  static const cv::Scalar kColors[] = {{180, 119, 31}, {14, 127, 255}, {44, 160, 44}, {40, 39, 214}, {189, 103, 148}, {75, 86, 140}};
  return kColors[i % (sizeof(kColors) / sizeof(kColors[0]))];
}

// The top of a y axis that shows `max_value` with a little headroom.
double Headroom(double max_value) {
  return std::isfinite(max_value) && max_value > 0 ? max_value * 1.15 : 1.0;
}

}  // namespace

cv::Mat PlotAbsRelByDepth(const std::vector<EvalReport>& configs) {
  PlotCanvas plot(kWidth, kHeight, "AbsRel against true depth (1 m bins)", "true depth (m)",
                  "AbsRel");
  double x_max = 1, y_max = 0;
  for (const auto& r : configs) {
    for (const auto& b : r.depth_bins) {
      x_max = std::max(x_max, b.end);
      if (b.pixels > 0) y_max = std::max(y_max, b.abs_rel);
    }
  }
  plot.SetRange(0, x_max, 0, Headroom(y_max));
  plot.DrawAxes();
  std::vector<std::pair<std::string, cv::Scalar>> legend;
  for (size_t c = 0; c < configs.size(); ++c) {
    std::vector<cv::Point2d> points;
    for (const auto& b : configs[c].depth_bins) {
      if (b.pixels > 0) points.emplace_back(0.5 * (b.start + b.end), b.abs_rel);
    }
    plot.Polyline(points, SeriesColor(c));
    legend.emplace_back(configs[c].ConfigName(), SeriesColor(c));
  }
  if (y_max == 0) plot.Message("no pixels with both ground truth and a prediction");
  plot.Legend(legend);
  return plot.image().clone();
}

cv::Mat PlotWidthErrorHistogram(const EvalReport& report) {
  std::vector<double> errors;  // Percent.
  for (const auto& f : report.frames) {
    if (f.has_estimate && f.has_truth && f.truth.width > 0) {
      errors.push_back(100.0 * (f.estimate.width - f.truth.width) / f.truth.width);
    }
  }
  PlotCanvas plot(kWidth, kHeight, "Corridor width error per frame",
                  "(w_est - w_true) / w_true (%)", "frames");
  double limit = 1.0;
  for (double e : errors) limit = std::max(limit, std::abs(e));
  const std::vector<double> ticks = NiceTicks(0, limit, 4);  // Round the range up to a tick.
  if (ticks.size() > 1) limit = std::ceil(limit / (ticks[1] - ticks[0])) * (ticks[1] - ticks[0]);
  const int num_bins = 20;
  const double bin = 2 * limit / num_bins;
  std::vector<int> counts(num_bins, 0);
  for (double e : errors)
    counts[std::clamp(static_cast<int>((e + limit) / bin), 0, num_bins - 1)]++;
  const int most = counts.empty() ? 0 : *std::max_element(counts.begin(), counts.end());
  plot.SetRange(-limit, limit, 0, std::max(5.0, std::ceil(most * 1.15)));  // Whole-frame ticks.
  plot.DrawAxes();
  for (int k = 0; k < num_bins; ++k) {
    if (counts[k] > 0)
      plot.Bar(-limit + k * bin, -limit + (k + 1) * bin, counts[k], SeriesColor(0));
  }
  if (errors.empty()) plot.Message("no frames with both an estimate and a true width");
  return plot.image().clone();
}

cv::Mat PlotSceneAbsRel(const EvalReport& report) {
  PlotCanvas plot(kWidth, kHeight, "AbsRel per scene", "scene", "AbsRel");
  const size_t n = report.scenes.size(), caps = report.caps.size();
  double y_max = 0;
  for (const auto& s : report.scenes) {
    for (const auto& m : s.depth) {
      if (std::isfinite(m.abs_rel)) y_max = std::max(y_max, m.abs_rel);
    }
  }
  plot.SetRange(-0.5, std::max<double>(n, 1) - 0.5, 0, Headroom(y_max));
  plot.DrawAxes(false);
  std::vector<std::string> names;
  const double width = 0.8 / std::max<size_t>(caps, 1);
  for (size_t i = 0; i < n; ++i) {
    names.push_back(report.scenes[i].name);
    for (size_t c = 0; c < caps && c < report.scenes[i].depth.size(); ++c) {
      const double value = report.scenes[i].depth[c].abs_rel;
      if (!std::isfinite(value)) continue;
      const double x0 = i - 0.4 + c * width;
      plot.Bar(x0, x0 + width, value, SeriesColor(c));
    }
  }
  plot.CategoryLabels(names);
  std::vector<std::pair<std::string, cv::Scalar>> legend;
  for (size_t c = 0; c < caps; ++c) legend.emplace_back(CapLabel(report.caps[c]), SeriesColor(c));
  plot.Legend(legend);
  if (y_max == 0) plot.Message("no scene with depth ground truth");
  return plot.image().clone();
}

Status WritePlots(const std::vector<EvalReport>& configs, const std::string& out_dir,
                  std::vector<std::string>* files) {
  files->clear();
  if (configs.empty()) return Status::Ok();
  const std::vector<std::pair<std::string, cv::Mat>> plots = {
      {"plots/abs_rel_by_depth.png", PlotAbsRelByDepth(configs)},
      {"plots/width_error_hist.png", PlotWidthErrorHistogram(configs.front())},
      {"plots/scene_abs_rel.png", PlotSceneAbsRel(configs.front())}};
  for (const auto& [name, image] : plots) {
    const Status status = WriteImageAtomic((std::filesystem::path(out_dir) / name).string(), image);
    if (!status.ok()) return status;
    files->push_back(name);
  }
  return Status::Ok();
}

}  // namespace corridor
