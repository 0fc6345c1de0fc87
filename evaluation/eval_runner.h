#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "core/status.h"
#include "evaluation/eval_scene.h"
#include "evaluation/frame_evaluator.h"
#include "pipeline/recover_depth.h"

namespace corridor {

// How EvaluateScenes spreads the work.
struct EvalRunOptions {
  int threads = 1;        // Worker threads, >= 1.
  bool sequence = false;  // Each scene is a sequence: its frames in order on one thread, with the previous frame's geometry.
  // Called after each frame with the frames done so far and the total, one call at a time (from
  // any worker thread); empty = none.
  std::function<void(size_t done, size_t total)> progress;
};

// The thread count for --threads: 0 -> hardware concurrency (at least 1); negative ->
// InvalidArgument.
Status ResolveThreadCount(int flag, int* threads);

// Evaluates every frame of every scene, in parallel, and stores the records in dataset order
// (scene by scene, frame by frame), so the result does not depend on the thread count. Returns
// non-ok (and stops early) only when an output cannot be written.
Status EvaluateScenes(const std::vector<EvalScene>& scenes, const DepthRecoverer& recoverer,
                      const FrameEvalOptions& frame_options, const EvalRunOptions& run_options,
                      std::vector<FrameRecord>* records);

}  // namespace corridor
