#include "corridor_depth/evaluation.h"
#include "perception/junction_tracker.h"
#include "pipeline/sequence_prior.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <string>
#include <thread>

namespace corridor {

Status ResolveThreadCount(int flag, int* threads) {
  if (flag < 0) {
    return Status::InvalidArgument("--threads must be >= 0 (0 = one per core), got " +
                                   std::to_string(flag));
  }
  *threads = flag > 0 ? flag : std::max(1u, std::thread::hardware_concurrency());
  return Status::Ok();
}

Status EvaluateScenes(const std::vector<EvalScene>& scenes, const DepthRecoverer& recoverer,
                      const FrameEvalOptions& frame_options, const EvalRunOptions& run_options,
                      std::vector<FrameRecord>* records) {
  // Jobs: (scene, first frame, end frame, first record), in dataset order; one frame each, or
  // one whole scene each in a sequence.
  struct Job {
    size_t scene, begin, end, record;
  };
  std::vector<Job> jobs;
  size_t count = 0;
  for (size_t s = 0; s < scenes.size(); ++s) {
    const size_t n = scenes[s].frames.size();
    if (run_options.sequence) {
      if (n > 0) jobs.push_back({s, 0, n, count});
    } else {
      for (size_t f = 0; f < n; ++f) jobs.push_back({s, f, f + 1, count + f});
    }
    count += n;
  }
  records->assign(count, FrameRecord());

  std::atomic<size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;  // Guards done, first_error and the progress calls.
  size_t done = 0;
  Status first_error = Status::Ok();
  auto work = [&]() {
    while (!stop.load()) {
      const size_t i = next.fetch_add(1);
      if (i >= jobs.size()) return;
      const Job& job = jobs[i];
      SequencePrior prior;
      JunctionTrack track;
      for (size_t f = job.begin; f < job.end && !stop.load(); ++f) {
        const Status status =
            EvaluateFrame(scenes[job.scene], f, recoverer, frame_options,
                          &(*records)[job.record + f - job.begin],
                          run_options.sequence ? &prior : nullptr,
                          run_options.sequence ? &track : nullptr);
        std::lock_guard<std::mutex> lock(mutex);
        if (!status.ok() && first_error.ok()) {
          first_error = status;
          stop = true;
        }
        ++done;
        if (run_options.progress) run_options.progress(done, count);
      }
    }
  };
  const int num_threads =
      std::max(1, std::min(run_options.threads, std::max(static_cast<int>(jobs.size()), 1)));
  std::vector<std::thread> workers;
  for (int t = 1; t < num_threads; ++t) workers.emplace_back(work);
  work();
  for (auto& worker : workers) worker.join();
  return first_error;
}

}  // namespace corridor
