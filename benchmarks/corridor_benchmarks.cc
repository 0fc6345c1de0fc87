// End-to-end time per frame, EndToEnd/<config>/<width>x<height>:
//   default    RecoverDepthOptions as they are (whatever solver, rasteriser and searches they
//              name): what a caller who sets nothing gets;
//   paper  the paper's method: grid-search solver and depth-plane rasteriser, no ceiling or end
//          wall (the paper has neither), fitting points on the junction lines;
//   best   the fastest accurate configuration: closed_form+lm and the exact rasteriser, with the
//          default ceiling and end-wall searches, on the junction lines' points;
//   floor  one colour Canny over the lower half and one depth image (cv::Canny on BGR runs on
//          the three channels, about three times a grey Canny's work, so it flatters ratios);
//   floor_grey  the honest floor: a grey conversion, one grey Canny over the default junction
//          search's region of interest (its rows, at full resolution), and one float depth image
//          filled;
// plus best_joint (the joint solver with the exact rasteriser), the runner-up for `best`,
//   best_paper_scope  `best`'s solver and rasteriser on the paper's scope (floor and walls: no
//                  ceiling or end-wall search, as `paper`), to compare with `paper` like for like,
//   best_sequence  `best` on a drive (frames 0-15 of PaperLikePose and back, over and over) as a
//                  sequence runs it (the previous frame's geometry passed on), every frame's
//                  junctions searched in the whole region;
//   best_tracked   the same with the junctions tracked from the previous frame's, the whole
//                  region searched again every redetect_interval frames and when a track is lost.
// The drives' times are means over the drive's frames, whole searches included.
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
#include "perception/junction_tracker.h"
#include "corridor_depth/recover_depth.h"
#include "pipeline/sequence_prior.h"

namespace corridor {
namespace {

// `paper_only`: the paper's method alone, without this project's ceiling and end-wall searches
// (and so without the ceiling's baseboard check), which the paper does not have.
void EndToEndWith(benchmark::State& state, const RecoverDepthOptions& options, int width,
                  int height) {
  cv::setNumThreads(1);
  const bench::BenchFrame& input = bench::PaperLikeFrame(width, height);
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

void EndToEnd(benchmark::State& state, const std::string& solver, const std::string& rasterizer,
              bool paper_only, int width, int height) {
  RecoverDepthOptions options;
  options.solver = solver;
  options.rasterizer = rasterizer;
  // The named configurations fit points on the junction lines, as the paper does (the default's
  // measured edge points cost `grid` and `lm` in proportion to their number).
  options.solver_evidence = "lines";
  options.estimate_ceiling = !paper_only;
  options.estimate_end_wall = !paper_only;
  EndToEndWith(state, options, width, height);
}

// The default options, untouched.
void EndToEndDefault(benchmark::State& state, int width, int height) {
  EndToEndWith(state, RecoverDepthOptions(), width, height);
}

// `best` on a drive, frame after frame, as a sequence is run (SequencePrior; JunctionTrack when
// `tracking`).
void EndToEndDrive(benchmark::State& state, bool tracking, int width, int height) {
  cv::setNumThreads(1);
  constexpr int kDriveFrames = 16;
  std::vector<const bench::BenchFrame*> drive;  // 0 .. 15 .. 1: the drive there and back.
  for (int i = 0; i < kDriveFrames; ++i) drive.push_back(&bench::PaperLikeFrame(width, height, i));
  for (int i = kDriveFrames - 2; i > 0; --i) drive.push_back(drive[i]);
  RecoverDepthOptions options;
  options.solver = "closed_form+lm";
  options.rasterizer = "exact";
  options.track_junctions = tracking;
  std::unique_ptr<DepthRecoverer> recoverer;
  if (!DepthRecoverer::Create(options, &recoverer).ok()) {
    state.SkipWithError("cannot create the recoverer");
    return;
  }
  const Camera& camera = drive[0]->camera;
  RecoverDepthResult result;
  if (recoverer->Detect(drive[0]->frame.bgr, camera, &result).ok()) {
    recoverer->Reconstruct(camera, &result);  // Warm-up, outside callgrind's toggle (see above).
  }
  SequencePrior prior;
  JunctionTrack track;
  size_t next = 0;
  int64_t frames = 0, tracked = 0, failed = 0;
  double worst_width_error = 0;
  for (auto _ : state) {
    const bench::BenchFrame& input = *drive[next];
    next = (next + 1) % drive.size();
    recoverer->Recover(input.frame.bgr, camera, &result, prior.Previous(), &track);
    prior.Update(result);
    benchmark::DoNotOptimize(result.depth.data);
    ++frames;
    tracked += result.junctions_tracked;
    if (!result.status.ok()) {
      ++failed;
    } else {
      worst_width_error =
          std::max(worst_width_error, std::abs(result.geometry.width - input.frame.truth.width));
    }
  }
  state.counters["tracked_fraction"] = frames > 0 ? static_cast<double>(tracked) / frames : 0;
  state.counters["failed_frames"] = static_cast<double>(failed);
  state.counters["worst_width_error_mm"] = 1000 * worst_width_error;
}

}  // namespace

// The floors' per-frame work, outside the anonymous namespace and never inlined, so that
// callgrind can count them by name (scripts/count_instructions.py, --toggle-collect).
namespace bench {

// The old floor: one colour Canny over the lower half, one depth image.
__attribute__((noinline)) void FloorFrame(const cv::Mat& bgr, cv::Mat* edges, cv::Mat* depth) {
  const int height = bgr.rows;
  cv::Canny(bgr.rowRange(height / 2, height), *edges, 40, 100);
  *depth = cv::Mat(height, bgr.cols, CV_32F, cv::Scalar(1.0f));
}

// The honest floor: a grey conversion, one grey Canny over the default junction search's region
// of interest (rows from roi_top_fraction of the height down), one float depth image filled.
__attribute__((noinline)) void FloorGreyFrame(const cv::Mat& bgr, int roi_top, cv::Mat* grey,
                                              cv::Mat* edges, cv::Mat* depth) {
  cv::cvtColor(bgr, *grey, cv::COLOR_BGR2GRAY);
  cv::Canny(grey->rowRange(roi_top, bgr.rows), *edges, 40, 100);
  depth->create(bgr.rows, bgr.cols, CV_32F);
  depth->setTo(cv::Scalar(1.0f));
}

}  // namespace bench

namespace {

void Floor(benchmark::State& state, int width, int height) {
  cv::setNumThreads(1);
  const bench::BenchFrame& input = bench::PaperLikeFrame(width, height);
  for (auto _ : state) {
    cv::Mat edges, depth;
    bench::FloorFrame(input.frame.bgr, &edges, &depth);
    benchmark::DoNotOptimize(edges.data);
    benchmark::DoNotOptimize(depth.data);
  }
}

void FloorGrey(benchmark::State& state, int width, int height) {
  cv::setNumThreads(1);
  const bench::BenchFrame& input = bench::PaperLikeFrame(width, height);
  const int roi_top =
      static_cast<int>(RecoverDepthOptions().perception.roi_top_fraction * height);
  cv::Mat grey, edges, depth;
  for (auto _ : state) {
    bench::FloorGreyFrame(input.frame.bgr, roi_top, &grey, &edges, &depth);
    benchmark::DoNotOptimize(edges.data);
    benchmark::DoNotOptimize(depth.data);
    benchmark::ClobberMemory();
  }
}

const bool registered = [] {
  for (const auto& size : bench::kSizes) {
    const int w = size[0], h = size[1];
    const std::string suffix = "/" + bench::SizeName(w, h);
    benchmark::RegisterBenchmark(("EndToEnd/default" + suffix).c_str(), EndToEndDefault, w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("EndToEnd/paper" + suffix).c_str(), EndToEnd, "grid", "paper",
                                 true, w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("EndToEnd/best" + suffix).c_str(), EndToEnd, "closed_form+lm",
                                 "exact", false, w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("EndToEnd/best_sequence" + suffix).c_str(), EndToEndDrive,
                                 false, w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("EndToEnd/best_tracked" + suffix).c_str(), EndToEndDrive, true,
                                 w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("EndToEnd/floor" + suffix).c_str(), Floor, w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("EndToEnd/floor_grey" + suffix).c_str(), FloorGrey, w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("EndToEnd/best_joint" + suffix).c_str(), EndToEnd, "joint",
                                 "exact", false, w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("EndToEnd/best_paper_scope" + suffix).c_str(), EndToEnd,
                                 "closed_form+lm", "exact", true, w, h)
        ->Unit(benchmark::kMicrosecond);
  }
  return true;
}();

}  // namespace
}  // namespace corridor
