// corridor_eval: batch evaluation against ground truth, reproducing the paper's Tables 1-4.
//   corridor_eval --dataset=DIR --output_dir=OUT [--solver=NAME] [--rasterizer=NAME]
//                 [--caps=5,40] [--threads=N] [--sequence] [--compare=solverA:rastA,solverB:rastB]
// Takes every option corridor_depth takes (tools/tool_flags.h). Writes OUT/report.{md,json,csv},
// OUT/index.html, OUT/plots/*.png, OUT/vis/<scene>/<frame>.png and OUT/depth/<scene>/<frame>.png
// (16-bit mm). Exit code 0: every frame evaluated; 1: some frames failed (listed in the report);
// 2: bad usage or configuration, an output that cannot be written, or nothing evaluated.

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <utility>

#include "corridor_depth/evaluation.h"
#include "corridor_depth/image_io.h"
#include "tools/eval/html_report.h"
#include "tools/eval/plots.h"
#include "tools/eval/report_writers.h"
#include "tools/input_source.h"
#include "tools/progress.h"
#include "tools/tool_flags.h"
#include "tools/tool_help.h"

DEFINE_string(dataset, "", "Dataset root (<scene>/rgb, <scene>/depth, truth.yaml), or images");
DEFINE_string(output_dir, "", "Where report.md/json/csv, index.html, plots/, vis/, depth/ go");
DEFINE_string(caps, "5,40", "Depth caps in metres, comma-separated (the paper: 5 and 40)");
DEFINE_int32(threads, 0, "Worker threads (0 = one per core)");
DEFINE_string(compare, "",
              "Configurations to compare, solver:rasterizer,...; the first one's numbers go "
              "at the top level of report.json and into the tables (overrides --solver and "
              "--rasterizer)");
DEFINE_bool(write_vis, true, "Write OUT/vis/<scene>/<frame>.png (first configuration)");
DEFINE_bool(write_depth, true, "Write OUT/depth/<scene>/<frame>.png (first configuration)");
DEFINE_double(vis_max_depth, 15.0, "Depth at the top of the colour scale in vis/, m");
DEFINE_double(vis_max_error, 1.0, "Absolute error at the top of its colour scale in vis/, m");

namespace corridor {
namespace {

namespace fs = std::filesystem;

constexpr size_t kMaxListedFailures = 20;  // Failures printed on stderr; all are in the report.

int Usage(const std::string& message) {
  std::fprintf(stderr, "corridor_eval: %s\n", message.c_str());
  return 2;
}

struct Config {
  std::string solver;      // Solver name or chain.
  std::string rasterizer;  // Rasteriser name.
};

// --compare=a:b,c:d, or the --solver/--rasterizer pair when it is empty.
Status ParseConfigs(const std::string& text, std::vector<Config>* configs) {
  configs->clear();
  if (text.empty()) {
    configs->push_back({FLAGS_solver, FLAGS_rasterizer});
    return Status::Ok();
  }
  std::set<std::string> seen;
  size_t begin = 0;
  while (true) {
    const size_t comma = text.find(',', begin);
    const std::string item = text.substr(begin, comma - begin);
    const size_t colon = item.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == item.size() ||
        item.find(':', colon + 1) != std::string::npos) {
      return Status::InvalidArgument("--compare: '" + item +
                                     "' is not solver:rasterizer (e.g. grid:paper)");
    }
    if (!seen.insert(item).second) {
      return Status::InvalidArgument("--compare: " + item + " is given twice");
    }
    configs->push_back({item.substr(0, colon), item.substr(colon + 1)});
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  return Status::Ok();
}

Status WriteReports(const std::vector<EvalReport>& reports, const std::string& out,
                    bool sequence) {
  ReportContext context;
  context.dataset = FLAGS_dataset;
  context.sequence = sequence;
  Status status = WritePlots(reports, out, &context.plot_files);
  if (!status.ok()) return status;
  const std::vector<std::pair<std::string, std::string>> files = {
      {"report.md", ReportMarkdown(reports, context)},
      {"report.json", ReportJson(reports, context)},
      {"report.csv", ReportCsv(reports)},
      {"index.html", ReportHtml(reports, context, FLAGS_write_vis)}};
  for (const auto& [name, text] : files) {
    status = WriteTextAtomic((fs::path(out) / name).string(), text);
    if (!status.ok()) return status;
  }
  return Status::Ok();
}

void PrintSummary(const EvalReport& r) {
  const GroupSummary& a = r.all;
  std::printf("%s: %d of %d frames ok; width error %s%%", r.ConfigName().c_str(),
              a.num_frames - a.num_failed, a.num_frames,
              FormatNumber(100 * a.width.rel_error, 3).c_str());
  std::printf(" (%d frames more than %s%% off)", a.width.num_gross,
              FormatNumber(100 * kGrossWidthError, 0).c_str());
  for (size_t c = 0; c < r.caps.size(); ++c) {
    const DepthMetrics& m = a.depth[c];
    std::printf("; %s: AbsRel %s RMSE %s coverage %s", CapLabel(r.caps[c]).c_str(),
                FormatNumber(m.abs_rel, 4).c_str(), FormatNumber(m.rmse, 3).c_str(),
                FormatNumber(m.coverage, 3).c_str());
  }
  if (a.ceiling.num_visible > 0) {
    std::printf("; ceiling within %s%% on %d of %d frames in view (%d found)",
                FormatNumber(100 * kCeilingTolerance, 0).c_str(), a.ceiling.num_within,
                a.ceiling.num_visible, a.ceiling.num_found);
  }
  std::printf("\n");
}

// The library's scenes for the tool's: a scene of image files keeps its frames and camera
// (with the per-image field of view); a bag or a video has no image files, so no frames.
std::vector<EvalScene> ToEvalScenes(const std::vector<InputScene>& inputs) {
  std::vector<EvalScene> scenes;
  for (const InputScene& input : inputs) {
    EvalScene scene;
    scene.name = input.name;
    scene.camera = input.camera;
    if (input.kind == InputKind::kImages) scene.frames = input.frames;
    scene.per_image_hfov_deg = input.per_image_hfov_deg;
    scenes.push_back(std::move(scene));
  }
  return scenes;
}

ToolInfo EvalToolInfo() {
  ToolInfo info;
  info.name = "corridor_eval";
  info.summary = "evaluate depth and geometry against ground truth, with a report";
  info.usage =
      "corridor_eval --dataset=DIR --output_dir=OUT [--solver=NAME] [--rasterizer=NAME]\n"
      "corridor_eval --dataset=DIR --output_dir=OUT --compare=joint:exact,grid:paper";
  info.notes =
      "Takes every option corridor_depth takes. Writes OUT/report.{md,json,csv}, OUT/index.html, "
      "OUT/plots/, OUT/vis/ and OUT/depth/ (16-bit millimetres). Exit code 0: every frame "
      "evaluated; 1: some frames failed (listed in the report); 2: bad usage, an output that "
      "cannot be written, or nothing evaluated.";
  info.flag_files = {"corridor_eval_main.cc", "tool_flags.cc"};
  info.groups = {{"threads", FlagGroup::kAdvanced}};
  return info;
}

int Main(int argc, char** argv) {
  RewriteBareSequenceFlag(argc, argv);
  int exit_code = 0;
  if (!ParseToolFlags(EvalToolInfo(), &argc, &argv, &exit_code)) return exit_code;
  if (argc > 1) return Usage(std::string("unexpected argument '") + argv[1] + "'");
  if (FLAGS_dataset.empty()) return Usage("--dataset is required (a dataset root)");
  // A dataset holds images: --sequence=auto runs each frame on its own.
  bool sequence = false;
  const Status sequence_status = ResolveSequence(false, &sequence);
  if (!sequence_status.ok()) return Usage(sequence_status.message());
  if (FLAGS_output_dir.empty()) return Usage("--output_dir is required");
  if (!(FLAGS_vis_max_depth > 0)) return Usage("--vis_max_depth must be positive");
  if (!(FLAGS_vis_max_error > 0)) return Usage("--vis_max_error must be positive");
  FrameEvalOptions frame_options;
  Status status = ParseCaps(FLAGS_caps, &frame_options.caps);
  if (!status.ok()) return Usage(status.message());
  EvalRunOptions run_options;
  status = ResolveThreadCount(FLAGS_threads, &run_options.threads);
  run_options.sequence = sequence;
  if (!status.ok()) return Usage(status.message());
  std::vector<Config> configs;
  status = ParseConfigs(FLAGS_compare, &configs);
  if (!status.ok()) return Usage(status.message());

  RecoverDepthOptions base;
  status = RecoverDepthOptionsFromFlags(&base);
  if (!status.ok()) return Usage(status.message());
  std::vector<std::unique_ptr<DepthRecoverer>> recoverers(configs.size());
  for (size_t c = 0; c < configs.size(); ++c) {
    RecoverDepthOptions options = base;
    options.solver = configs[c].solver;
    options.rasterizer = configs[c].rasterizer;
    status = DepthRecoverer::Create(options, &recoverers[c]);
    if (!status.ok()) return Usage(status.message());
  }
  std::vector<InputScene> inputs;
  status = ResolveInput(FLAGS_dataset, CameraOverridesFromFlags(), &inputs);
  if (!status.ok()) return Usage(status.message());
  if (FLAGS_focal == "auto") {
    for (const auto& scene : inputs) {
      std::printf("%s: scene %s: %s\n", "corridor_eval", scene.name.c_str(), scene.camera_source.c_str());
    }
  }
  const std::vector<EvalScene> scenes = ToEvalScenes(inputs);
  size_t total = 0;
  for (const auto& scene : scenes) total += scene.frames.size();
  if (total == 0) return Usage("no frames to evaluate in " + FLAGS_dataset);

  std::vector<EvalReport> reports;
  for (size_t c = 0; c < configs.size(); ++c) {
    FrameEvalOptions options = frame_options;
    if (c == 0) options.output_dir = FLAGS_output_dir;  // Pictures for the first one only.
    options.write_depth = FLAGS_write_depth;
    options.write_vis = FLAGS_write_vis;
    options.vis_max_depth = FLAGS_vis_max_depth;
    options.vis_max_error = FLAGS_vis_max_error;
    Progress progress(configs[c].solver + ":" + configs[c].rasterizer, static_cast<int>(total));
    run_options.progress = [&progress](size_t done, size_t) {
      progress.Tick(static_cast<int>(done));
    };
    std::vector<FrameRecord> records;
    status = EvaluateScenes(scenes, *recoverers[c], options, run_options, &records);
    progress.Finish();
    if (!status.ok()) return Usage("cannot write output: " + status.ToString());
    reports.push_back(
        BuildReport(records, frame_options.caps, configs[c].solver, configs[c].rasterizer));
  }
  status = WriteReports(reports, FLAGS_output_dir, sequence);
  if (!status.ok()) return Usage("cannot write the report: " + status.ToString());

  int failed = 0, evaluated = 0;
  for (const auto& r : reports) {
    PrintSummary(r);
    failed += r.all.num_failed;
    evaluated += r.all.num_frames - r.all.num_failed;
  }
  std::printf("corridor_eval: report in %s/index.html\n", FLAGS_output_dir.c_str());
  const auto& failures = reports.front().failures;
  for (size_t i = 0; i < failures.size() && i < kMaxListedFailures; ++i) {
    LOG(WARNING) << "corridor_eval: " << failures[i].scene << "/" << failures[i].frame
                 << " failed: " << failures[i].reason;
  }
  if (failures.size() > kMaxListedFailures) {
    LOG(WARNING) << "corridor_eval: ... and " << failures.size() - kMaxListedFailures
                 << " more failed frames (see report.md)";
  }
  if (evaluated == 0) {
    LOG(ERROR) << "corridor_eval: no frame could be evaluated";
    return 2;
  }
  return failed > 0 ? 1 : 0;
}

}  // namespace
}  // namespace corridor

int main(int argc, char** argv) { return corridor::Main(argc, argv); }
