// solver_compare: the same inputs, every solver, one table.
//   solver_compare --output_dir=OUT [--solvers=grid,lm,...] [--noise=0,0.5,1,2,4]
//                  [--outliers=0,0.1,0.3] [--trials=40] [--dataset=DIR]
// Noise sweeps run on exact junction points of random corridors; --dataset adds a run on real
// detections (lines from perception, truth from truth.yaml).

#include <cstdio>
#include <random>
#include <sstream>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "corridor_depth/image_io.h"
#include "pipeline/plausibility.h"
#include "pipeline/solver_evidence.h"
#include "corridor_depth/recover_depth.h"
#include "tools/compare/compare_report.h"
#include "tools/compare/synthetic_junctions.h"
#include "tools/input_source.h"
#include "tools/progress.h"
#include "tools/tool_flags.h"
#include "tools/tool_help.h"

DEFINE_string(output_dir, "", "Where solver_compare.{csv,md} and the plot go");
DEFINE_string(solvers, "grid,closed_form,lm,joint,closed_form+lm",
              "Comma-separated solver names or chains");
DEFINE_string(noise, "0,0.5,1,2,4", "Pixel noise levels (Gaussian sigma, px)");
DEFINE_string(outliers, "0,0.1,0.3", "Outlier fractions in [0, 1)");
DEFINE_int32(trials, 40, "Random corridors per noise level and outlier fraction");
DEFINE_uint32(seed, 1, "Random seed (the same seed gives the same corridors)");
DEFINE_string(dataset, "", "Optional dataset root: also compare on detected junction lines");
DEFINE_string(loss, "huber", "Robust loss for every solver: none, huber or cauchy");
DEFINE_double(loss_scale, 2.0, "Robust loss scale, px");

namespace corridor {
namespace {

int Usage(const std::string& message) {
  std::fprintf(stderr, "solver_compare: %s\n", message.c_str());
  return 2;
}

bool ParseList(const std::string& text, std::vector<std::string>* items) {
  items->clear();
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    if (item.empty()) return false;
    items->push_back(item);
  }
  return !items->empty();
}

bool ParseNumbers(const std::string& text, double lo, double hi, std::vector<double>* values) {
  std::vector<std::string> items;
  if (!ParseList(text, &items)) return false;
  values->clear();
  for (const auto& item : items) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || *end != '\0' || !(v >= lo && v < hi)) return false;
    values->push_back(v);
  }
  return true;
}

std::string CaseName(double noise, double outliers) {
  char name[64];
  std::snprintf(name, sizeof(name), "noise %gpx, outliers %g%%", noise, 100 * outliers);
  return name;
}

// Noise sweeps: every solver sees the same corridors and points.
std::vector<SolverCaseStats> RunSweeps(const std::vector<std::string>& names,
                                       const std::vector<std::unique_ptr<CorridorSolver>>& solvers,
                                       const std::vector<double>& noise,
                                       const std::vector<double>& outliers) {
  std::vector<SolverCaseStats> rows;
  Progress progress("sweeps", static_cast<int>(noise.size() * outliers.size()), "cases");
  int done = 0;
  for (double f : outliers) {
    for (double sigma : noise) {
      std::mt19937 rng(FLAGS_seed);
      std::vector<SolverCaseAccumulator> acc(solvers.size());
      for (int t = 0; t < FLAGS_trials; ++t) {
        const CorridorGeometry truth = RandomCorridor(&rng);
        const CorridorObservation obs = ObserveJunctions(truth, {sigma, f, 30}, &rng);
        for (size_t s = 0; s < solvers.size(); ++s) {
          SolverSummary summary;
          const Status status = solvers[s]->Solve(obs, nullptr, &summary);
          acc[s].Add(status, summary, truth);
        }
      }
      for (size_t s = 0; s < solvers.size(); ++s) {
        rows.push_back(acc[s].Finish(names[s], CaseName(sigma, f), sigma, f));
      }
      progress.Tick(++done);
    }
  }
  progress.Finish();
  return rows;
}

// Real runs: junctions from perception on every frame with truth; each solver on the same lines.
Status RunDataset(const std::vector<std::string>& names,
                  const std::vector<std::unique_ptr<CorridorSolver>>& solvers,
                  std::vector<SolverCaseStats>* rows) {
  RecoverDepthOptions options;
  Status status = RecoverDepthOptionsFromFlags(&options);
  if (!status.ok()) return status;
  std::unique_ptr<DepthRecoverer> detector;
  status = DepthRecoverer::Create(options, &detector);
  if (!status.ok()) return status;
  std::vector<InputScene> scenes;
  status = ResolveInput(FLAGS_dataset, CameraOverridesFromFlags(), &scenes);
  if (!status.ok()) return status;
  int total = 0;
  for (const auto& scene : scenes) total += static_cast<int>(scene.frames.size());
  Progress progress("dataset", total);
  std::vector<SolverCaseAccumulator> acc(solvers.size());
  int done = 0;
  for (const auto& scene : scenes) {
    for (const auto& frame : scene.frames) {
      progress.Tick(++done);
      if (!frame.has_truth) continue;
      cv::Mat image;
      RecoverDepthResult detection;
      Status frame_status = ReadColorImage(frame.rgb_path, &image);
      if (frame_status.ok()) frame_status = detector->Detect(image, scene.camera, &detection);
      // With --solver_evidence=edges, the junctions' edge points measured on the frame.
      if (frame_status.ok()) MeasureSolverEvidence(image, options, &detection.junctions);
      const CorridorObservation obs =
          ObservationFromJunctions(detection.junctions, scene.camera, options);
      for (size_t s = 0; s < solvers.size(); ++s) {
        SolverSummary summary;
        const Status solve = frame_status.ok() ? solvers[s]->Solve(obs, nullptr, &summary)
                                               : frame_status;
        acc[s].Add(solve, summary, frame.truth.geometry);
      }
    }
  }
  progress.Finish();
  for (size_t s = 0; s < solvers.size(); ++s) {
    rows->push_back(acc[s].Finish(names[s], "dataset " + FLAGS_dataset, NAN, NAN));
  }
  return Status::Ok();
}

ToolInfo CompareToolInfo() {
  ToolInfo info;
  info.name = "solver_compare";
  info.summary = "every solver on the same junction points: noise sweeps and dataset runs";
  info.usage =
      "solver_compare --output_dir=OUT [--solvers=grid,lm,...] [--noise=0,0.5,1,2,4]\n"
      "solver_compare --output_dir=OUT --dataset=DIR --camera_height=M";
  info.notes =
      "Noise sweeps run on exact junction points of random corridors; --dataset adds a run on "
      "detected junction lines (truth from truth.yaml), which takes corridor_depth's camera and "
      "detection flags. Writes OUT/solver_compare.{csv,md} and OUT/width_error_vs_noise.png.";
  info.flag_files = {"solver_compare_main.cc", "tool_flags.cc"};
  info.groups = {{"noise", FlagGroup::kInput},
                 {"outliers", FlagGroup::kInput},
                 {"trials", FlagGroup::kInput},
                 {"seed", FlagGroup::kInput}};
  return info;
}

int Main(int argc, char** argv) {
  int exit_code = 0;
  if (!ParseToolFlags(CompareToolInfo(), &argc, &argv, &exit_code)) return exit_code;
  if (argc > 1) return Usage(std::string("unexpected argument '") + argv[1] + "'");
  if (FLAGS_output_dir.empty()) return Usage("--output_dir is required");
  if (FLAGS_trials <= 0) return Usage("--trials must be positive");
  std::vector<std::string> names;
  if (!ParseList(FLAGS_solvers, &names)) return Usage("--solvers must be a comma-separated list");
  std::vector<double> noise, outliers;
  if (!ParseNumbers(FLAGS_noise, 0, 100, &noise)) {
    return Usage("--noise must be comma-separated numbers in [0, 100) px");
  }
  if (!ParseNumbers(FLAGS_outliers, 0, 1, &outliers)) {
    return Usage("--outliers must be comma-separated fractions in [0, 1)");
  }
  SolverOptions options;
  options.loss = FLAGS_loss;
  options.loss_scale = FLAGS_loss_scale;
  std::vector<std::unique_ptr<CorridorSolver>> solvers;
  for (const auto& name : names) {
    std::unique_ptr<CorridorSolver> solver;
    const Status status = CreateSolver(name, options, &solver);
    if (!status.ok()) return Usage(status.message());
    solvers.push_back(std::move(solver));
  }
  std::vector<SolverCaseStats> rows = RunSweeps(names, solvers, noise, outliers);
  if (!FLAGS_dataset.empty()) {
    const Status status = RunDataset(names, solvers, &rows);
    if (!status.ok()) return Usage(status.message());
  }
  const Status status = WriteCompareReport(rows, FLAGS_output_dir);
  if (!status.ok()) return Usage(status.ToString());
  std::printf(
      "%s\nsolver_compare: outputs in %s (solver_compare.csv, solver_compare.md, "
      "width_error_vs_noise.png)\n",
      CompareMarkdown(rows).c_str(), FLAGS_output_dir.c_str());
  return 0;
}

}  // namespace
}  // namespace corridor

int main(int argc, char** argv) { return corridor::Main(argc, argv); }
