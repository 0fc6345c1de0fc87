// Time per frame of each stage of the pipeline on the corridor_benchmarks frames, at the three
// sizes: Stages/<stage>[/<variant>]/<width>x<height>.
//   detect      DetectJunctions (the edge-extraction thread's work)
//   segments    its first part: blur, colour gradient, Canny and Hough on the ROI
//   canny/NAME  Canny's suppression and hysteresis on the ROI's colour derivatives: `own`
//               (CannyFromGradients) or `opencv` (cv::Canny), the same edges
//   appearance  its floor-appearance cues: SampleFloor and the BoundaryScore of every merged line
//               of the ROI (Lab of the sampled pixels only)
//   ceiling     DetectCeiling on the frame's true walls
//   end_wall    DetectEndWall on the frame's true geometry
//   inner_line  CheckInnerLine on the true geometry with the right wall put at 60% of its distance
//               (as a line inside the floor puts it): the wide ceiling search that moves it back
//   solve/NAME  each solver on the detected junctions' points
//   rasterize/NAME  each rasteriser on the closed_form+lm geometry
// OpenCV runs on one thread.
//   build/benchmarks/stages_benchmark --benchmark_repetitions=5

#include <benchmark/benchmark.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "benchmarks/bench_frames.h"
#include "kernels/canny_edges.h"
#include "kernels/color_gradient.h"
#include "perception/appearance.h"
#include "perception/ceiling_detector.h"
#include "perception/end_wall_detector.h"
#include "perception/junction_tracker.h"
#include "perception/line_segments.h"
#include "pipeline/inner_line_check.h"
#include "pipeline/plausibility.h"
#include "pipeline/solver_evidence.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {
namespace {

void Detect(benchmark::State& state, int width, int height) {
  cv::setNumThreads(1);
  const bench::BenchFrame& input = bench::PaperLikeFrame(width, height);
  const JunctionDetectorOptions options;
  JunctionPair pair;
  for (auto _ : state) {
    const Status status = DetectJunctions(input.frame.bgr, options, &pair);
    benchmark::DoNotOptimize(status);
  }
  if (!pair.status.ok()) state.SkipWithError(pair.status.ToString().c_str());
}

// The junctions of the drive's frame 1 sought near frame 0's (TrackJunctions), as a sequence does
// between whole searches.
void Track(benchmark::State& state, int width, int height) {
  cv::setNumThreads(1);
  const JunctionDetectorOptions options;
  JunctionPair previous;
  if (!DetectJunctions(bench::PaperLikeFrame(width, height, 0).frame.bgr, options, &previous).ok()) {
    state.SkipWithError("no junctions in frame 0");
    return;
  }
  const cv::Mat& next = bench::PaperLikeFrame(width, height, 1).frame.bgr;
  const JunctionTrackerOptions tracker;
  JunctionPair tracked;
  bool found = false;
  for (auto _ : state) {
    found = TrackJunctions(next, previous, options, tracker, &tracked, nullptr);
    benchmark::DoNotOptimize(found);
  }
  if (!found) state.SkipWithError("frame 1's junctions not tracked");
}

void Segments(benchmark::State& state, int width, int height) {
  cv::setNumThreads(1);
  const bench::BenchFrame& input = bench::PaperLikeFrame(width, height);
  const JunctionDetectorOptions o;
  const SegmentOptions options = JunctionSegmentOptions(o, height, 1);
  for (auto _ : state) {
    const EdgeSegments found = DetectSegments(input.frame.bgr, height / 2, options);
    benchmark::DoNotOptimize(found.segments.data());
  }
}

void Canny(benchmark::State& state, bool own, int width, int height) {
  cv::setNumThreads(1);
  const bench::BenchFrame& input = bench::PaperLikeFrame(width, height);
  cv::Mat dx, dy, edges;
  ColorGradient(input.frame.bgr.rowRange(height / 2, height), &dx, &dy, nullptr);
  for (auto _ : state) {
    if (own) {
      CannyFromGradients(dx, dy, 40, 100, false, &edges);
    } else {
      cv::Canny(dx, dy, edges, 40, 100, false);
    }
    benchmark::DoNotOptimize(edges.data);
  }
}

void Appearance(benchmark::State& state, int width, int height) {
  cv::setNumThreads(1);
  const bench::BenchFrame& input = bench::PaperLikeFrame(width, height);
  const JunctionDetectorOptions o;
  const SegmentOptions options = JunctionSegmentOptions(o, height, 1);
  const int roi_top = height / 2;
  const std::vector<MergedLine> lines = MergeSegments(
      DetectSegments(input.frame.bgr, roi_top, options).segments, o.merge_angle_deg,
      o.merge_distance_px);
  const cv::Mat roi = input.frame.bgr.rowRange(roi_top, height);
  for (auto _ : state) {
    const FloorAppearance floor = SampleFloor(roi, roi_top);
    double total = 0;
    for (const MergedLine& line : lines) total += BoundaryScore(roi, floor, line, roi_top);
    benchmark::DoNotOptimize(total);
  }
  state.counters["lines"] = static_cast<double>(lines.size());
}

void Ceiling(benchmark::State& state, int width, int height) {
  cv::setNumThreads(1);
  const bench::BenchFrame& input = bench::PaperLikeFrame(width, height);
  const CeilingDetectorOptions options;
  CeilingEstimate estimate;
  for (auto _ : state) {
    const Status status =
        DetectCeiling(input.frame.bgr, input.camera, input.frame.truth, options, &estimate);
    benchmark::DoNotOptimize(status);
  }
  if (!estimate.found) {
    state.SkipWithError(estimate.reason.c_str());
    return;
  }
  state.counters["height_error_mm"] =
      1000 * std::abs(estimate.height - input.frame.truth.ceiling_height);
}

// The end-wall search on the frame's true geometry (the paper-like corridor goes on beyond range:
// this is the cost of looking and finding nothing, the usual case).
void EndWall(benchmark::State& state, int width, int height) {
  cv::setNumThreads(1);
  const bench::BenchFrame& input = bench::PaperLikeFrame(width, height);
  const EndWallDetectorOptions options;
  EndWallEstimate estimate;
  for (auto _ : state) {
    const Status status =
        DetectEndWall(input.frame.bgr, input.camera, input.frame.truth, options, &estimate);
    benchmark::DoNotOptimize(status);
  }
  state.counters["found"] = estimate.found;
}

// The inner-line check where it acts: the right wall too near, as a grout line or a box's edge
// taken for its junction puts it (the check's wide ceiling search, on the frame itself).
void InnerLine(benchmark::State& state, int width, int height) {
  cv::setNumThreads(1);
  const bench::BenchFrame& input = bench::PaperLikeFrame(width, height);
  const CorridorGeometry& truth = input.frame.truth;
  CorridorGeometry near = truth;
  near.SetWallDistances(truth.LeftDistance(), 0.6 * truth.RightDistance());
  const CeilingDetectorOptions ceiling;
  const InnerLineCheckOptions options;
  CorridorGeometry moved;
  InnerLineCheck check;
  for (auto _ : state) {
    moved = near;
    check = CheckInnerLine(input.frame.bgr, input.camera, ceiling, options, &moved);
    benchmark::DoNotOptimize(check);
  }
  state.counters["moved"] = check.moved;
  state.counters["width_error_mm"] = 1000 * std::abs(moved.width - truth.width);
}

// The solvers' input: the detected junctions of the frame.
bool DetectedObservation(const bench::BenchFrame& input, CorridorObservation* observation) {
  JunctionPair pair;
  const RecoverDepthOptions options;
  if (!DetectJunctions(input.frame.bgr, options.perception, &pair).ok() || !pair.status.ok()) {
    return false;
  }
  *observation = ObservationFromJunctions(pair, input.camera, options);
  return true;
}

void Solve(benchmark::State& state, const std::string& name, int width, int height) {
  const bench::BenchFrame& input = bench::PaperLikeFrame(width, height);
  CorridorObservation observation;
  std::unique_ptr<CorridorSolver> solver;
  if (!DetectedObservation(input, &observation) ||
      !CreateSolver(name, SolverOptions(), &solver).ok()) {
    state.SkipWithError("no junctions or no solver");
    return;
  }
  SolverSummary summary;
  for (auto _ : state) {
    const Status status = solver->Solve(observation, nullptr, &summary);
    benchmark::DoNotOptimize(status);
  }
  state.counters["evaluations"] = summary.evaluations;
  state.counters["width_error_mm"] = 1000 * std::abs(summary.estimate.width - input.frame.truth.width);
}

void Rasterize(benchmark::State& state, const std::string& name, int width, int height) {
  const bench::BenchFrame& input = bench::PaperLikeFrame(width, height);
  CorridorObservation observation;
  std::unique_ptr<CorridorSolver> solver;
  std::unique_ptr<DepthRasterizer> rasterizer;
  SolverSummary summary;
  if (!DetectedObservation(input, &observation) ||
      !CreateSolver("closed_form+lm", SolverOptions(), &solver).ok() ||
      !solver->Solve(observation, nullptr, &summary).ok() ||
      !CreateRasterizer(name, RasterizerOptions(), &rasterizer).ok()) {
    state.SkipWithError("no geometry or no rasterizer");
    return;
  }
  CorridorGeometry geometry = summary.estimate;
  geometry.camera_height = input.camera.mount_height;
  for (auto _ : state) {
    cv::Mat depth;  // A new image per frame, as RecoverDepth makes.
    const Status status = rasterizer->Render(geometry, input.camera, &depth);
    benchmark::DoNotOptimize(status);
  }
}

const bool registered = [] {
  for (const auto& size : bench::kSizes) {
    const int w = size[0], h = size[1];
    const std::string suffix = "/" + bench::SizeName(w, h);
    benchmark::RegisterBenchmark(("Stages/detect" + suffix).c_str(), Detect, w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("Stages/track" + suffix).c_str(), Track, w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("Stages/segments" + suffix).c_str(), Segments, w, h)
        ->Unit(benchmark::kMicrosecond);
    for (const bool own : {true, false}) {
      const std::string name = "Stages/canny/" + std::string(own ? "own" : "opencv") + suffix;
      benchmark::RegisterBenchmark(name.c_str(), Canny, own, w, h)->Unit(benchmark::kMicrosecond);
    }
    benchmark::RegisterBenchmark(("Stages/appearance" + suffix).c_str(), Appearance, w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("Stages/ceiling" + suffix).c_str(), Ceiling, w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("Stages/end_wall" + suffix).c_str(), EndWall, w, h)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("Stages/inner_line" + suffix).c_str(), InnerLine, w, h)
        ->Unit(benchmark::kMicrosecond);
    for (const char* solver : {"grid", "closed_form", "lm", "closed_form+lm", "joint"}) {
      benchmark::RegisterBenchmark(("Stages/solve/" + std::string(solver) + suffix).c_str(), Solve,
                                   std::string(solver), w, h)
          ->Unit(benchmark::kMicrosecond);
    }
    for (const char* rasterizer : {"exact", "paper"}) {
      benchmark::RegisterBenchmark(
          ("Stages/rasterize/" + std::string(rasterizer) + suffix).c_str(), Rasterize,
          std::string(rasterizer), w, h)
          ->Unit(benchmark::kMicrosecond);
    }
  }
  return true;
}();

}  // namespace
}  // namespace corridor
