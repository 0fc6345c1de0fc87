#include "tools/eval/eval_runner.h"

#include <algorithm>
#include <atomic>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>

#include "tools/progress.h"

namespace corridor {

Status ResolveThreadCount(int flag, int* threads) {
  if (flag < 0) {
    return Status::InvalidArgument("--threads must be >= 0 (0 = one per core), got " +
                                   std::to_string(flag));
  }
  *threads = flag > 0 ? flag : std::max(1u, std::thread::hardware_concurrency());
  return Status::Ok();
}

Status EvaluateScenes(const std::vector<InputScene>& scenes, const DepthRecoverer& recoverer,
                      const FrameEvalOptions& frame_options, const EvalRunOptions& run_options,
                      std::vector<FrameRecord>* records) {
  std::vector<std::pair<size_t, size_t>> jobs;  // (scene, frame) in dataset order.
  for (size_t s = 0; s < scenes.size(); ++s) {
    for (size_t f = 0; f < scenes[s].frames.size(); ++f) jobs.emplace_back(s, f);
  }
  records->assign(jobs.size(), FrameRecord());
  const int total = static_cast<int>(jobs.size());
  std::unique_ptr<Progress> progress;
  if (!run_options.progress_label.empty()) {
    progress = std::make_unique<Progress>(run_options.progress_label, total);
  }

  std::atomic<size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;  // Guards done, first_error and progress.
  int done = 0;
  Status first_error = Status::Ok();
  auto work = [&]() {
    while (!stop.load()) {
      const size_t i = next.fetch_add(1);
      if (i >= jobs.size()) return;
      const Status status = EvaluateFrame(scenes[jobs[i].first], jobs[i].second, recoverer,
                                          frame_options, &(*records)[i]);
      std::lock_guard<std::mutex> lock(mutex);
      if (!status.ok() && first_error.ok()) {
        first_error = status;
        stop = true;
      }
      ++done;
      if (progress) progress->Tick(done);
    }
  };
  const int num_threads = std::max(1, std::min(run_options.threads, std::max(total, 1)));
  std::vector<std::thread> workers;
  for (int t = 1; t < num_threads; ++t) workers.emplace_back(work);
  work();
  for (auto& worker : workers) worker.join();
  if (progress) progress->Finish();
  return first_error;
}

}  // namespace corridor
