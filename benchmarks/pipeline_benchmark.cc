// Sustained frames per second through the paper's two-thread FramePipeline against a one-thread
// loop (Detect then Reconstruct per frame, with the junction track and the previous geometry as
// the pipeline keeps them), the library default configuration, OpenCV on one thread per stage:
//   Pipeline/<two_threads|one_thread>/memory    200 frames cycled from 16 rendered 640x480 ones
//   Pipeline/<two_threads|one_thread>/dataset   every frame of $CORRIDOR_BENCH_DATASET (a dataset
//                                               root; its images are read inside the loop, as
//                                               corridor_depth does), when that is set
//   CORRIDOR_BENCH_DATASET=/tmp/seq500 build/benchmarks/pipeline_benchmark

#include <cstdlib>
#include <functional>

#include <benchmark/benchmark.h>
#include <opencv2/core.hpp>

#include "benchmarks/bench_frames.h"
#include "corridor_depth/dataset.h"
#include "corridor_depth/image_io.h"
#include "perception/junction_tracker.h"
#include "pipeline/frame_pipeline.h"
#include "pipeline/sequence_prior.h"

namespace corridor {
namespace {

// Frame i of a stream: fills the image (and read status), camera and name.
using FrameSource = std::function<void(int i, PipelineFrame* frame)>;

void Run(benchmark::State& state, bool two_threads, int frames, const FrameSource& fill) {
  cv::setNumThreads(1);
  std::unique_ptr<DepthRecoverer> recoverer;
  if (!DepthRecoverer::Create(RecoverDepthOptions(), &recoverer).ok()) {
    state.SkipWithError("cannot create the recoverer");
    return;
  }
  int64_t failed = 0;
  for (auto _ : state) {
    failed = 0;
    if (two_threads) {
      int next = 0;
      FramePipeline pipeline(*recoverer);
      pipeline.Run(
          [&](PipelineFrame* frame) {
            if (next >= frames) return false;
            fill(next++, frame);
            return true;
          },
          [&](PipelineFrame&& frame) {
            failed += !frame.result.status.ok();
            return true;
          });
    } else {
      JunctionTrack track;
      SequencePrior prior;
      for (int i = 0; i < frames; ++i) {
        PipelineFrame frame;
        fill(i, &frame);
        if (frame.read_status.ok()) {
          recoverer->Detect(frame.image, *frame.camera, &frame.result, &track);
        } else {
          frame.result.status = frame.read_status;
        }
        if (frame.result.ReadyToReconstruct()) {
          recoverer->Reconstruct(*frame.camera, &frame.result, prior.Previous());
          prior.Update(frame.result);
        }
        failed += !frame.result.status.ok();
      }
    }
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(frames) * state.iterations(),
                                             benchmark::Counter::kIsRate);
  state.counters["failed"] = static_cast<double>(failed);
}

void Memory(benchmark::State& state, bool two_threads) {
  constexpr int kDistinct = 16, kFrames = 200;
  std::vector<const bench::BenchFrame*> frames;
  for (int i = 0; i < kDistinct; ++i) frames.push_back(&bench::PaperLikeFrame(640, 480, i));
  Run(state, two_threads, kFrames, [&](int i, PipelineFrame* frame) {
    const bench::BenchFrame& f = *frames[i % kDistinct];
    frame->image = f.frame.bgr;
    frame->camera = &f.camera;
  });
}

void Dataset(benchmark::State& state, bool two_threads, const std::string& root) {
  std::vector<DatasetScene> scenes;
  if (!LoadDataset(root, &scenes).ok() || scenes.empty()) {
    state.SkipWithError("cannot load $CORRIDOR_BENCH_DATASET");
    return;
  }
  std::vector<std::pair<const Camera*, std::string>> paths;
  for (const auto& scene : scenes) {
    for (const auto& frame : scene.frames) paths.emplace_back(&scene.camera, frame.rgb_path);
  }
  Run(state, two_threads, static_cast<int>(paths.size()), [&](int i, PipelineFrame* frame) {
    frame->camera = paths[i].first;
    frame->read_status = ReadColorImage(paths[i].second, &frame->image);
  });
}

const bool registered = [] {
  for (const bool two : {true, false}) {
    const std::string name = two ? "Pipeline/two_threads" : "Pipeline/one_thread";
    benchmark::RegisterBenchmark((name + "/memory").c_str(), Memory, two)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    if (const char* root = std::getenv("CORRIDOR_BENCH_DATASET")) {
      benchmark::RegisterBenchmark((name + "/dataset").c_str(), Dataset, two, std::string(root))
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(1);
    }
  }
  return true;
}();

}  // namespace
}  // namespace corridor
