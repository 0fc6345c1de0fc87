// End-to-end time per frame, EndToEnd/<config>/<width>x<height>:
//   paper  the paper's method: grid-search solver and depth-plane rasteriser, no ceiling or end
//          wall (the paper has neither);
//   best   the fastest accurate configuration: closed_form+lm and the exact rasteriser, with the
//          default ceiling and end-wall searches;
//   floor  the least work any method must do: one Canny over the lower half and one depth image;
// plus best_joint (the joint solver with the exact rasteriser), the runner-up for `best`.
// Frames are rendered once, outside the timing loops; OpenCV runs on one thread, so each figure
// is the cost on one core. scripts/run_benchmarks.sh runs this binary and prints the table.
//   build/benchmarks/corridor_benchmarks --benchmark_repetitions=5 --benchmark_out=e2e.json
// Instructions per frame (machine-independent): divide the Ir of Recover by its calls in
//   valgrind --tool=callgrind --toggle-collect='corridor::DepthRecoverer::Recover*'
//     build/benchmarks/corridor_benchmarks --benchmark_filter='EndToEnd/best/640x480$'
//     --benchmark_min_time=0.0001

#include <benchmark/benchmark.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "benchmarks/bench_frames.h"
#include "pipeline/recover_depth.h"

namespace corridor {
namespace {

// `paper_only`: the paper's method alone, without this project's ceiling and end-wall searches
// (and so without the ceiling's baseboard check), which the paper does not have.
void EndToEnd(benchmark::State& state, const std::string& solver, const std::string& rasterizer,
              bool paper_only, int width, int height) {
  cv::setNumThreads(1);
  const bench::BenchFrame& input = bench::PaperLikeFrame(width, height);
  RecoverDepthOptions options;
  options.solver = solver;
  options.rasterizer = rasterizer;
  options.estimate_ceiling = !paper_only;
  options.estimate_end_wall = !paper_only;
  std::unique_ptr<DepthRecoverer> recoverer;
  if (!DepthRecoverer::Create(options, &recoverer).ok()) {
    state.SkipWithError("cannot create the recoverer");
    return;
  }
  // A warm-up frame, outside the loop: OpenCV builds its Lab tables on the first conversion.
  // (Through Detect + Reconstruct, so that callgrind --toggle-collect=*Recover* sees only the
  // timed frames.)
  RecoverDepthResult result;
  if (recoverer->Detect(input.frame.bgr, input.camera, &result).ok()) {
    recoverer->Reconstruct(input.camera, &result);
  }
  for (auto _ : state) {
    recoverer->Recover(input.frame.bgr, input.camera, &result);
    benchmark::DoNotOptimize(result.depth.data);
  }
  if (!result.status.ok()) {
    state.SkipWithError(result.status.ToString().c_str());
    return;
  }
  const CorridorGeometry& truth = input.frame.truth;
  state.counters["width_error_mm"] = 1000 * std::abs(result.geometry.width - truth.width);
  state.counters["yaw_error_mrad"] = 1000 * std::abs(result.geometry.yaw - truth.yaw);
  state.counters["pitch_error_mrad"] = 1000 * std::abs(result.geometry.pitch - truth.pitch);
}

// The floor: what every method must at least do per frame.
void Floor(benchmark::State& state, int width, int height) {
  cv::setNumThreads(1);
  const bench::BenchFrame& input = bench::PaperLikeFrame(width, height);
  const cv::Mat roi = input.frame.bgr.rowRange(height / 2, height);
  for (auto _ : state) {
    cv::Mat edges;
    cv::Canny(roi, edges, 40, 100);
    cv::Mat depth(height, width, CV_32F, cv::Scalar(1.0f));
    benchmark::DoNotOptimize(edges.data);
    benchmark::DoNotOptimize(depth.data);
  }
}

const bool registered = [] {
  for (const auto& size : bench::kSizes) {
    const int w = size[0], h = size[1];
    const std::string suffix = "/" + bench::SizeName(w, h);
    benchmark::RegisterBenchmark(("EndToEnd/paper" + suffix).c_str(), EndToEnd, "grid", "paper",
                                 true, w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("EndToEnd/best" + suffix).c_str(), EndToEnd, "closed_form+lm",
                                 "exact", false, w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("EndToEnd/floor" + suffix).c_str(), Floor, w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("EndToEnd/best_joint" + suffix).c_str(), EndToEnd, "joint",
                                 "exact", false, w, h)
        ->Unit(benchmark::kMicrosecond);
  }
  return true;
}();

}  // namespace
}  // namespace corridor
