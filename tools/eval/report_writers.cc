#include "tools/eval/report_writers.h"

#include <cmath>
#include <cstdio>

#include "corridor_depth/evaluation.h"
#include "tools/geometry_csv.h"

namespace corridor {
namespace {

// A Markdown table cell: pipes escaped, newlines flattened.
std::string MdCell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') {
      out += "\\|";
    } else if (c == '\n' || c == '\r') {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out;
}

std::string MdTable(const TextTable& table) {
  std::string out = "## " + table.title + "\n\n|";
  for (const auto& h : table.header) out += " " + MdCell(h) + " |";
  out += "\n|";
  for (size_t i = 0; i < table.header.size(); ++i) out += i == 0 ? ":---|" : "---:|";
  out += "\n";
  for (size_t r = 0; r < table.rows.size(); ++r) {
    const bool bold = r < table.summary.size() && table.summary[r];
    out += "|";
    for (size_t c = 0; c < table.rows[r].size(); ++c) {
      const std::string cell = MdCell(table.rows[r][c]);
      out += " " + (bold && c == 0 ? "**" + cell + "**" : cell) + " |";
    }
    out += "\n";
  }
  if (!table.note.empty()) out += "\n" + table.note + "\n";
  return out + "\n";
}

// A CSV number: 10 significant digits, empty when unknown.
std::string CsvNumber(double value) {
  if (!std::isfinite(value)) return "";
  char text[40];
  std::snprintf(text, sizeof(text), "%.10g", value);
  return text;
}

const char* const kMetricNames[] = {"abs_rel", "log10", "rmse", "rmse_log10", "rmse_log",
                                    "sq_rel", "delta1", "delta2", "delta3", "coverage"};

std::vector<double> MetricValues(const DepthMetrics& m) {
  return {m.abs_rel, m.log10, m.rmse, m.rmse_log10, m.rmse_log,
          m.sq_rel, m.delta1, m.delta2, m.delta3, m.coverage};
}

void AddGeometry(bool valid, const CorridorGeometry& g, std::vector<std::string>* row) {
  for (double v : {g.yaw, g.pitch, g.offset, g.width}) row->push_back(valid ? CsvNumber(v) : "");
}

std::string Join(const std::vector<std::string>& cells) {
  std::string out;
  for (size_t i = 0; i < cells.size(); ++i) out += (i > 0 ? "," : "") + CsvField(cells[i]);
  return out + "\n";
}

}  // namespace

std::string ReportMarkdown(const std::vector<EvalReport>& configs, const ReportContext& context) {
  std::string out = "# corridor_eval report\n\n";
  if (configs.empty()) return out + "Nothing was evaluated.\n";
  const EvalReport& r = configs.front();
  out += "- dataset: `" + context.dataset + "`\n";
  out += "- configuration: solver `" + r.solver + "`, rasterizer `" + r.rasterizer + "`";
  if (configs.size() > 1) out += " (first of " + std::to_string(configs.size()) + " compared)";
  out += "\n- frames: " + std::to_string(r.all.num_frames) + " in " +
         std::to_string(r.scenes.size()) + " scenes, " + std::to_string(r.all.num_failed) +
         " failed, " + std::to_string(r.all.num_depth_truth) + " with ground-truth depth, " +
         (context.sequence ? "each scene a sequence (--sequence)" : "each frame on its own") +
         "\n\n";
  for (const TextTable& table : ReportTables(configs)) out += MdTable(table);
  if (!context.plot_files.empty()) {
    out += "## Plots\n\n";
    for (const auto& plot : context.plot_files) out += "![" + plot + "](" + plot + ")\n\n";
  }
  return out;
}

std::string ReportCsv(const std::vector<EvalReport>& configs) {
  std::vector<std::string> header = {"config", "scene", "frame", "status",
                                     "reason", "est_yaw", "est_pitch", "est_offset",
                                     "est_width", "true_yaw", "true_pitch", "true_offset",
                                     "true_width", "width_rel_error", "est_ceiling_height",
                                     "true_ceiling_height", "ceiling_visible", "junctions_tracked",
                                     "confidence", "left_junction", "right_junction",
                                     "left_crossing",
                                     "left_reaching", "right_crossing", "right_reaching",
                                     "ceiling_disagreement", "moved_side", "ceiling_split",
                                     "left_floor_across", "right_floor_across"};
  const std::vector<double> caps = configs.empty() ? std::vector<double>() : configs[0].caps;
  for (double cap : caps) {
    for (const char* name : kMetricNames) header.push_back(CapKey(cap) + "_" + name);
    header.push_back(CapKey(cap) + "_num_gt");
    header.push_back(CapKey(cap) + "_num_evaluated");
  }
  for (const char* t : {"t_perception_s", "t_solve_s", "t_rasterize_s", "t_total_s"}) {
    header.push_back(t);
  }
  std::string out = Join(header);
  for (const EvalReport& r : configs) {
    for (const FrameRecord& f : r.frames) {
      std::vector<std::string> row = {r.ConfigName(), f.scene, f.frame,
                                      StatusClass(f.status.code()),
                                      f.status.ok() ? "" : f.status.ToString()};
      AddGeometry(f.has_estimate, f.estimate, &row);
      AddGeometry(f.has_truth, f.truth, &row);
      row.push_back(f.has_estimate && f.has_truth
                        ? CsvNumber(RelativeError(f.estimate.width, f.truth.width))
                        : "");
      row.push_back(f.ceiling_estimated ? CsvNumber(f.estimate.ceiling_height) : "");
      row.push_back(f.has_truth && f.truth.HasCeiling() ? CsvNumber(f.truth.ceiling_height) : "");
      row.push_back(f.has_truth ? (f.ceiling_visible ? "1" : "0") : "");
      row.push_back(f.junctions_tracked ? "1" : "0");
      const FrameEvidence& e = f.evidence;
      for (double v : {f.confidence, e.junction[0], e.junction[1]}) {
        row.push_back(f.ran ? CsvNumber(v) : "");
      }
      for (int v : {e.crossings[0].crossing, e.crossings[0].reaching, e.crossings[1].crossing,
                    e.crossings[1].reaching}) {
        row.push_back(f.ran ? std::to_string(v) : "");
      }
      row.push_back(f.ran ? CsvNumber(e.ceiling_disagreement) : "");
      row.push_back(f.ran ? std::to_string(e.moved_side) : "");
      row.push_back(f.ran ? CsvNumber(e.ceiling_split) : "");
      for (double v : {e.floor_across[0], e.floor_across[1]}) row.push_back(f.ran ? CsvNumber(v) : "");
      for (size_t c = 0; c < caps.size(); ++c) {
        const DepthMetrics m = c < f.metrics.size() ? f.metrics[c] : DepthMetrics();
        const bool known = c < f.metrics.size();
        for (double v : MetricValues(m)) row.push_back(known ? CsvNumber(v) : "");
        row.push_back(known ? std::to_string(m.num_gt) : "");
        row.push_back(known ? std::to_string(m.num_evaluated) : "");
      }
      for (double t : {f.times.perception, f.times.solve, f.times.rasterize, f.times.total}) {
        row.push_back(f.ran ? CsvNumber(t) : "");
      }
      out += Join(row);
    }
  }
  return out;
}

}  // namespace corridor
