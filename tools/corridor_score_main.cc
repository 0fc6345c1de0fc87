// corridor_score: scores the recovered junctions of labelled photos against their hand labels.
//   corridor_score --labels=DIR/junctions.csv --output_dir=OUT [--hfov=60] [recovery flags]
// Each photo is recovered on its own, with the label's intrinsics where it gives them and a
// pinhole of --hfov degrees (default 60) otherwise. Writes OUT/scores.csv, OUT/summary.md and
// OUT/contact_sheet.png, and prints the summary. Exit code 0 when no corridor photo is ok but
// wrong, 1 otherwise, 2 on bad usage.

#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include <gflags/gflags.h>

#include "evaluation/junction_labels.h"
#include "io/csv_row.h"
#include "corridor_depth/image_io.h"
#include "corridor_depth/recover_depth.h"
#include "tools/geometry_csv.h"
#include "tools/label_sheet.h"
#include "tools/progress.h"
#include "tools/tool_help.h"
#include "tools/tool_flags.h"

DEFINE_string(labels, "", "junctions.csv of the labelled photos (the photos lie beside it)");
DEFINE_string(output_dir, "", "Where scores.csv, summary.md and contact_sheet.png go");
DEFINE_int32(tile_width, 320, "Width of each photo on the contact sheet, px");

namespace corridor {
namespace {

namespace fs = std::filesystem;

int Usage(const std::string& message) {
  std::fprintf(stderr, "corridor_score: %s\n", message.c_str());
  return 2;
}

std::string Percent(double fraction) {
  if (fraction < 0) return "";
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f%%", 100 * fraction);
  return text;
}

// What the frame's confidence rests on, as scores.csv columns.
std::string EvidenceColumns(const FrameEvidence& e) {
  char text[200];
  std::snprintf(text, sizeof(text), "%.3f,%.3f,%.3f,%d,%d,%d,%d,%.3f", e.junction[0],
                e.junction[1], e.ceiling_disagreement, e.crossings[0].crossing,
                e.crossings[0].reaching, e.crossings[1].crossing, e.crossings[1].reaching,
                e.ceiling_split);
  return text;
}

// Verdict counts of one group of photos.
struct Tally {
  int photos = 0;
  std::map<LabelVerdict, int> verdicts;
};

ToolInfo ScoreToolInfo() {
  ToolInfo info;
  info.name = "corridor_score";
  info.summary = "score recovered floor/wall junctions against hand labels of photos";
  info.usage =
      "corridor_score --labels=tests/data/real-corridors/junctions.csv --output_dir=OUT\n"
      "corridor_score --labels=DIR/junctions.csv --output_dir=OUT --min_confidence=0.5";
  info.notes =
      "Each photo is recovered on its own, with the label's intrinsics where it gives them and a "
      "pinhole of --hfov degrees (default 60) otherwise. A side's error is the largest distance "
      "over its labelled segment to the reported junction, over the image height: right <= 2%, "
      "ok but wrong > 5%, rough between. Writes OUT/scores.csv, OUT/summary.md and "
      "OUT/contact_sheet.png. Exit code 0: no corridor photo is ok but wrong; 1: some are; 2: bad "
      "usage.";
  info.flag_files = {"corridor_score_main.cc", "tool_flags.cc"};
  return info;
}

int Main(int argc, char** argv) {
  int exit_code = 0;
  if (!ParseToolFlags(ScoreToolInfo(), &argc, &argv, &exit_code)) return exit_code;
  if (argc > 1) return Usage(std::string("unexpected argument '") + argv[1] + "'");
  if (FLAGS_labels.empty()) return Usage("--labels is required (a junctions.csv)");
  if (FLAGS_output_dir.empty()) return Usage("--output_dir is required");
  if (FLAGS_tile_width < 64) return Usage("--tile_width must be at least 64");
  const double hfov = FLAGS_hfov > 0 ? FLAGS_hfov : 60.0;
  if (!(hfov < 180)) return Usage("--hfov must be in (0, 180) degrees");
  // The junction lines a geometry projects do not depend on the camera height: any will do.
  const double height = FLAGS_camera_height > 0 ? FLAGS_camera_height : 1.0;
  RecoverDepthOptions options;
  Status status = RecoverDepthOptionsFromFlags(&options);
  if (!status.ok()) return Usage(status.message());
  std::unique_ptr<DepthRecoverer> recoverer;
  status = DepthRecoverer::Create(options, &recoverer);
  if (!status.ok()) return Usage(status.message());
  std::vector<JunctionLabel> labels;
  status = ReadJunctionLabels(FLAGS_labels, &labels);
  if (!status.ok()) return Usage(status.ToString());
  const fs::path folder = fs::path(FLAGS_labels).parent_path();

  std::string csv =
      "file,kind,quality,status,note,confidence,verdict,left_error,right_error,left_junction,"
      "right_junction,ceiling_disagreement,left_crossing,left_reaching,right_crossing,"
      "right_reaching,ceiling_split\n";
  std::map<std::string, Tally> tallies;  // By group: "corridor, sure", "corridor, approx", ...
  std::vector<cv::Mat> tiles;
  std::ostringstream table;
  table << "| photo | kind | quality | status | confidence | left | right | verdict |\n"
        << "|---|---|---|---|---:|---:|---:|---|\n";
  Progress progress("corridor_score", static_cast<int>(labels.size()));
  int wrong = 0;
  for (size_t i = 0; i < labels.size(); ++i) {
    const JunctionLabel& label = labels[i];
    cv::Mat bgr;
    RecoverDepthResult result;
    Camera camera = Camera::FromHorizontalFov(label.width, label.height, hfov * M_PI / 180, height);
    if (label.has_camera) {
      camera.fx = label.fx, camera.fy = label.fy, camera.cx = label.cx, camera.cy = label.cy;
    }
    status = ReadColorImage((folder / label.file).string(), &bgr);
    if (status.ok() && (bgr.cols != label.width || bgr.rows != label.height)) {
      status = Status::InvalidArgument(label.file + " is " + std::to_string(bgr.cols) + "x" +
                                       std::to_string(bgr.rows) + ", the label says " +
                                       std::to_string(label.width) + "x" +
                                       std::to_string(label.height));
    }
    if (status.ok()) {
      recoverer->Recover(bgr, camera, &result);
    } else {
      result.status = status;
    }
    const bool ok = result.status.ok() && result.has_geometry;
    const LabelScore score = ScoreAgainstLabel(label, ok, result.geometry, camera, result.roll);
    const auto [code, note] = StatusColumns(result.status);
    const std::string group = label.kind + ", " + label.quality;
    ++tallies[group].photos;
    ++tallies[group].verdicts[score.verdict];
    if (label.kind == "corridor" && score.verdict == LabelVerdict::kOkButWrong) ++wrong;
    char confidence[16];
    std::snprintf(confidence, sizeof(confidence), "%.3f", result.confidence);
    csv += CsvField(label.file) + "," + label.kind + "," + label.quality + "," + code + "," +
           CsvField(result.status.ok() ? result.fallback : note) + "," + confidence + "," +
           LabelVerdictName(score.verdict) + "," + Percent(score.side_error[0]) + "," +
           Percent(score.side_error[1]) + "," + EvidenceColumns(result.evidence) + "\n";
    table << "| " << label.file << " | " << label.kind << " | " << label.quality << " | "
          << (ok ? "ok" : code + ": " + note.substr(0, 60)) << " | " << confidence << " | "
          << Percent(score.side_error[0]) << " | " << Percent(score.side_error[1]) << " | "
          << LabelVerdictName(score.verdict) << " |\n";
    if (!bgr.empty()) {
      const std::string caption = label.file + ": " + LabelVerdictName(score.verdict) + " (" +
                                  confidence + ")";
      tiles.push_back(
          LabelTile(bgr, label, ok, result.geometry, result.roll, camera, caption,
                    FLAGS_tile_width));
    }
    progress.Tick(static_cast<int>(i + 1));
  }
  progress.Finish();

  std::ostringstream summary;
  summary << "# Junctions against hand labels\n\n"
          << "Labels: " << FLAGS_labels << "; unknown cameras: " << hfov
          << " degrees horizontal field of view; solver " << options.solver
          << ", min_confidence " << options.min_confidence << ".\n"
          << "A side's error is the largest distance over its labelled segment to the reported "
             "junction, over the image height: right <= 2%, ok but wrong > 5%, rough between.\n\n"
          << "| group | photos | right | rough | ok but wrong | refused |\n"
          << "|---|---:|---:|---:|---:|---:|\n";
  for (auto& [group, tally] : tallies) {
    summary << "| " << group << " | " << tally.photos << " | "
            << tally.verdicts[LabelVerdict::kRight] << " | "
            << tally.verdicts[LabelVerdict::kRough] << " | "
            << tally.verdicts[LabelVerdict::kOkButWrong] << " | "
            << tally.verdicts[LabelVerdict::kRefused] << " |\n";
  }
  summary << "\n(A view of another kind than `corridor` is right when refused.)\n\n"
          << table.str();
  const fs::path out(FLAGS_output_dir);
  status = WriteTextAtomic((out / "scores.csv").string(), csv);
  if (status.ok()) status = WriteTextAtomic((out / "summary.md").string(), summary.str());
  if (status.ok() && !tiles.empty()) {
    status = WriteImageAtomic((out / "contact_sheet.png").string(), ContactSheet(tiles, 4));
  }
  if (!status.ok()) {
    std::fprintf(stderr, "corridor_score: cannot write output: %s\n", status.ToString().c_str());
    return 2;
  }
  std::printf("%s\ncorridor_score: outputs in %s\n", summary.str().c_str(), FLAGS_output_dir.c_str());
  return wrong > 0 ? 1 : 0;
}

}  // namespace
}  // namespace corridor

int main(int argc, char** argv) { return corridor::Main(argc, argv); }
