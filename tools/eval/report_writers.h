#pragma once

#include <string>
#include <vector>

#include "corridor_depth/evaluation.h"

namespace corridor {

// What the reports say about the run besides the numbers.
struct ReportContext {
  std::string dataset;                  // The --dataset path.
  bool sequence = false;                // --sequence: each scene's frames in order, with the previous frame's geometry.
  std::vector<std::string> plot_files;  // Plot PNGs, relative to the output folder.
};

// report.md: the tables (report_tables.h) in Markdown, then the plots.
std::string ReportMarkdown(const std::vector<EvalReport>& configs, const ReportContext& context);

// report.json: every number of the first configuration at the top level (scenes.<scene>.<cap
// key>.<metric>, all.<cap key>.<metric>, easy/hard, width, pose, timing, failures, per-frame
// records) and, with several configurations, each under configs.<solver>:<rasterizer>.
// NaN and infinities are written as null.
std::string ReportJson(const std::vector<EvalReport>& configs, const ReportContext& context);

// report.csv: a header, then one row per frame (per configuration): config, scene, frame,
// status, reason, the estimate, the truth, every metric per cap, and the stage times.
std::string ReportCsv(const std::vector<EvalReport>& configs);

// A JSON string literal: quotes, backslashes and control characters escaped.
std::string JsonString(const std::string& text);

// A JSON number (15 significant digits), or null when not finite.
std::string JsonNumber(double value);

}  // namespace corridor
