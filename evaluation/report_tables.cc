#include "corridor_depth/evaluation.h"

#include <cmath>
#include <cstdio>

namespace corridor {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

std::string Int(int64_t value) { return std::to_string(value); }

std::string Percent(double fraction, int decimals) {
  return std::isnan(fraction) ? "-" : FormatNumber(100.0 * fraction, decimals);
}

std::string Ms(double seconds) {
  return std::isnan(seconds) ? "-" : FormatNumber(seconds * 1e3, 2);
}

// Scenes, then the groups (easy, hard), then "all": the rows of every per-scene table.
std::vector<const GroupSummary*> Rows(const EvalReport& report) {
  std::vector<const GroupSummary*> rows;
  for (const auto& s : report.scenes) rows.push_back(&s);
  for (const auto& g : report.groups) rows.push_back(&g);
  rows.push_back(&report.all);
  return rows;
}

void AddRow(TextTable* table, std::vector<std::string> cells, bool summary) {
  table->rows.push_back(std::move(cells));
  table->summary.push_back(summary);
}

bool IsSummary(const EvalReport& report, const GroupSummary* row) {
  if (row == &report.all) return true;
  for (const auto& g : report.groups) {
    if (row == &g) return true;
  }
  return false;
}

std::vector<std::string> DepthCells(const DepthMetrics& m) {
  return {FormatNumber(m.abs_rel, 5), FormatNumber(m.log10, 5), FormatNumber(m.rmse, 5),
          FormatNumber(m.rmse_log10, 5), FormatNumber(m.rmse_log, 5), FormatNumber(m.sq_rel, 5),
          FormatNumber(m.delta1, 4), FormatNumber(m.delta2, 4), FormatNumber(m.delta3, 4),
          Percent(m.coverage, 2)};
}

const std::vector<std::string> kDepthHeader = {"AbsRel", "Log10", "RMSE", "RMSElog",
                                               "RMSElog (ln)", "SqRel", "δ<1.25", "δ<1.25²",
                                               "δ<1.25³", "coverage %"};

TextTable WidthTable(const EvalReport& r) {
  TextTable t;
  t.id = "table1";
  t.title = "Table 1: Accuracy of corridor width estimation";
  t.header = {"Scene",
              "Estimated(m)",
              "Groundtruth(m)",
              "relative error %",
              "mean per-frame error %",
              "frames (estimated / with truth)",
              "frames > " + FormatNumber(100 * kGrossWidthError, 0) + "% off"};
  for (const GroupSummary* g : Rows(r)) {
    AddRow(&t,
           {g->name, FormatNumber(g->width.estimated, 2), FormatNumber(g->width.truth, 2),
            Percent(g->width.rel_error, 4), Percent(g->width.mean_frame_rel_error, 4),
            Int(g->width.num_estimated) + " / " + Int(g->width.num_truth), Int(g->width.num_gross)},
           IsSummary(r, g));
  }
  t.note =
      "Scene rows: error of the mean estimated width against the mean true width. "
      "Group rows: mean of their scenes' relative errors.";
  return t;
}

TextTable DepthTable(const EvalReport& r, size_t cap_index) {
  TextTable t;
  t.id = "table" + std::to_string(2 + cap_index);
  t.title = "Table " + std::to_string(2 + cap_index) + ": Accuracy of depth estimation, " +
            CapLabel(r.caps[cap_index]);
  t.header = {"Scene"};
  t.header.insert(t.header.end(), kDepthHeader.begin(), kDepthHeader.end());
  t.header.push_back("images");
  for (const GroupSummary* g : Rows(r)) {
    std::vector<std::string> cells = {g->name};
    const std::vector<std::string> depth = DepthCells(g->depth[cap_index]);
    cells.insert(cells.end(), depth.begin(), depth.end());
    cells.push_back(Int(g->depth[cap_index].num_images));
    AddRow(&t, cells, IsSummary(r, g));
  }
  t.note =
      "Per-image metrics averaged over the images (docs/geometry.md section 7). RMSElog uses "
      "log10 as the paper prints it; RMSElog (ln) is the standard one. A failed image "
      "counts with coverage 0.";
  return t;
}

TextTable PoseTable(const EvalReport& r) {
  TextTable t;
  t.id = "pose";
  t.title = "Pose errors (mean absolute, against truth.yaml)";
  t.header = {"Scene", "yaw (deg)", "pitch (deg)", "offset (m)", "frames"};
  for (const GroupSummary* g : Rows(r)) {
    AddRow(&t,
           {g->name, FormatNumber(g->pose.yaw * kRadToDeg, 3),
            FormatNumber(g->pose.pitch * kRadToDeg, 3), FormatNumber(g->pose.offset, 4),
            Int(g->pose.num_frames)},
           IsSummary(r, g));
  }
  return t;
}

TextTable CeilingTable(const EvalReport& r) {
  TextTable t;
  t.id = "ceiling";
  t.title = "Ceiling height (beyond the paper), frames whose true ceiling junction is in view";
  t.header = {"Scene", "in view", "found", "within " + FormatNumber(100 * kCeilingTolerance, 0) + "%",
              "mean error %", "worst error %"};
  for (const GroupSummary* g : Rows(r)) {
    const CeilingSummary& c = g->ceiling;
    AddRow(&t,
           {g->name, Int(c.num_visible), Int(c.num_found), Int(c.num_within),
            Percent(c.mean_rel_error, 2), Percent(c.max_rel_error, 2)},
           IsSummary(r, g));
  }
  t.note =
      "In view: the true ceiling/wall junction, projected through the true geometry, spans at "
      "least 10% of the image's smaller side within 40 m. Errors are |H_est - H_true| / H_true "
      "over the frames found; a frame whose ceiling height was given, not searched, is not "
      "found.";
  return t;
}

TextTable TimingTable(const EvalReport& r) {
  TextTable t;
  t.id = "timing";
  t.title = "Time per frame (ms, median / 90th percentile)";
  t.header = {"Scene", "perception", "solve", "rasterize", "total", "frames"};
  for (const GroupSummary* g : Rows(r)) {
    const TimingSummary& s = g->timing;
    AddRow(&t,
           {g->name, Ms(s.perception.median) + " / " + Ms(s.perception.p90),
            Ms(s.solve.median) + " / " + Ms(s.solve.p90),
            Ms(s.rasterize.median) + " / " + Ms(s.rasterize.p90),
            Ms(s.total.median) + " / " + Ms(s.total.p90), Int(s.num_frames)},
           IsSummary(r, g));
  }
  return t;
}

TextTable CompareTable(const std::vector<EvalReport>& configs) {
  TextTable t;
  t.id = "table4";
  t.title = "Comparison of configurations on all images (as the paper's Table 4)";
  t.header = {"Method (solver:rasterizer)", "depth range"};
  t.header.insert(t.header.end(), kDepthHeader.begin(), kDepthHeader.end());
  t.header.push_back("width error %");
  t.header.push_back("total ms (median)");
  for (size_t c = 0; c < configs.front().caps.size(); ++c) {
    for (const EvalReport& r : configs) {
      std::vector<std::string> cells = {r.ConfigName(), CapLabel(r.caps[c])};
      const std::vector<std::string> depth = DepthCells(r.all.depth[c]);
      cells.insert(cells.end(), depth.begin(), depth.end());
      cells.push_back(Percent(r.all.width.rel_error, 4));
      cells.push_back(Ms(r.all.timing.total.median));
      AddRow(&t, cells, false);
    }
  }
  return t;
}

TextTable FailureTable(const EvalReport& r) {
  TextTable t;
  t.id = "failures";
  t.title = "Failed frames (" + std::to_string(r.failures.size()) + ")";
  t.header = {"Scene", "Frame", "Reason"};
  for (const auto& f : r.failures) AddRow(&t, {f.scene, f.frame, f.reason}, false);
  return t;
}

}  // namespace

std::string FormatNumber(double value, int decimals) {
  if (std::isnan(value)) return "-";
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  return text;
}

std::string CapLabel(double cap) {
  char text[64];
  std::snprintf(text, sizeof(text), "depth < %g m", cap);
  return text;
}

std::vector<TextTable> ReportTables(const std::vector<EvalReport>& configs) {
  std::vector<TextTable> tables;
  if (configs.empty()) return tables;
  const EvalReport& r = configs.front();
  tables.push_back(WidthTable(r));
  for (size_t c = 0; c < r.caps.size(); ++c) tables.push_back(DepthTable(r, c));
  if (configs.size() > 1) tables.push_back(CompareTable(configs));
  tables.push_back(PoseTable(r));
  if (r.all.ceiling.num_visible > 0) tables.push_back(CeilingTable(r));
  tables.push_back(TimingTable(r));
  if (!r.failures.empty()) tables.push_back(FailureTable(r));
  return tables;
}

}  // namespace corridor
