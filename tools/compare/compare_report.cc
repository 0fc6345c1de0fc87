#include "tools/compare/compare_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "corridor_depth/image_io.h"
#include "corridor_depth/visualization.h"
#include "tools/eval/plot_canvas.h"

namespace corridor {
namespace {

std::string Format(const char* format, double value) {
  if (!std::isfinite(value)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

std::string CsvText(const std::vector<SolverCaseStats>& rows) {
  std::string text =
      "solver,case,noise_px,outlier_fraction,trials,failures,yaw_median,yaw_p90,pitch_median,"
      "pitch_p90,offset_median,offset_p90,width_rel_median,width_rel_p90,seconds_median,"
      "evaluations_median\n";
  for (const auto& r : rows) {
    char line[512];
    std::snprintf(line, sizeof(line),
                  "%s,%s,%g,%g,%d,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n",
                  r.solver.c_str(), r.case_name.c_str(), r.noise_px, r.outlier_fraction, r.trials,
                  r.failures, r.yaw_median, r.yaw_p90, r.pitch_median, r.pitch_p90,
                  r.offset_median, r.offset_p90, r.width_median, r.width_p90, r.seconds_median,
                  r.evaluations_median);
    text += line;
  }
  return text;
}

const cv::Scalar kPalette[] = {{200, 80, 30}, {40, 160, 40}, {30, 30, 200}, {160, 40, 160}, {0, 140, 200}, {120, 120, 0}, {90, 90, 90}, {200, 0, 120}};

cv::Mat WidthErrorPlot(const std::vector<SolverCaseStats>& rows, double outliers) {
  std::map<std::string, std::vector<cv::Point2d>> lines;
  std::vector<std::string> order;
  double y_max = 0, x_max = 0;
  for (const auto& r : rows) {
    if (!(std::abs(r.outlier_fraction - outliers) < 1e-9) || !std::isfinite(r.width_median)) {
      continue;
    }
    if (!lines.count(r.solver)) order.push_back(r.solver);
    lines[r.solver].push_back({r.noise_px, 100 * r.width_median});
    y_max = std::max(y_max, 100 * r.width_median);
    x_max = std::max(x_max, r.noise_px);
  }
  char title[96];
  std::snprintf(title, sizeof(title), "median width error, %.0f%% outliers", 100 * outliers);
  PlotCanvas canvas(520, 360, title, "pixel noise (px)", "width error (%)");
  canvas.SetRange(0, std::max(x_max, 1.0), 0, std::max(y_max * 1.1, 0.1));
  canvas.DrawAxes();
  std::vector<std::pair<std::string, cv::Scalar>> legend;
  for (size_t i = 0; i < order.size(); ++i) {
    const cv::Scalar color = kPalette[i % 8];
    canvas.Polyline(lines[order[i]], color);
    legend.emplace_back(order[i], color);
  }
  canvas.Legend(legend);
  if (order.empty()) canvas.Message("no data");
  return canvas.image();
}

}  // namespace

std::string CompareMarkdown(const std::vector<SolverCaseStats>& rows) {
  std::string text;
  std::string current;
  for (const auto& r : rows) {
    if (r.case_name != current) {
      current = r.case_name;
      text += "\n### " + current + "\n\n";
      text +=
          "| solver | fail % | yaw med / p90 (mrad) | pitch med / p90 (mrad) | offset med / p90 "
          "(mm) | width med / p90 (%) | time med (us) | evals med |\n";
      text += "|---|---|---|---|---|---|---|---|\n";
    }
    const double fail = r.trials > 0 ? 100.0 * r.failures / r.trials : NAN;
    text += "| " + r.solver + " | " + Format("%.1f", fail) + " | " +
            Format("%.3f", 1e3 * r.yaw_median) + " / " + Format("%.3f", 1e3 * r.yaw_p90) + " | " +
            Format("%.3f", 1e3 * r.pitch_median) + " / " + Format("%.3f", 1e3 * r.pitch_p90) +
            " | " + Format("%.2f", 1e3 * r.offset_median) + " / " +
            Format("%.2f", 1e3 * r.offset_p90) + " | " + Format("%.3f", 100 * r.width_median) +
            " / " + Format("%.3f", 100 * r.width_p90) + " | " +
            Format("%.1f", 1e6 * r.seconds_median) + " | " +
            Format("%.0f", r.evaluations_median) + " |\n";
  }
  return text;
}

Status WriteCompareReport(const std::vector<SolverCaseStats>& rows, const std::string& dir) {
  const std::filesystem::path out(dir);
  Status status = WriteTextAtomic((out / "solver_compare.csv").string(), CsvText(rows));
  if (!status.ok()) return status;
  status = WriteTextAtomic((out / "solver_compare.md").string(),
                           "# Solver comparison\n" + CompareMarkdown(rows));
  if (!status.ok()) return status;
  std::set<double> outlier_levels;
  for (const auto& r : rows) {
    if (std::isfinite(r.outlier_fraction)) outlier_levels.insert(r.outlier_fraction);
  }
  if (outlier_levels.empty()) return Status::Ok();
  std::vector<cv::Mat> panels;
  for (double f : outlier_levels) panels.push_back(WidthErrorPlot(rows, f));
  return WriteImageAtomic((out / "width_error_vs_noise.png").string(), HorizontalConcat(panels));
}

}  // namespace corridor
