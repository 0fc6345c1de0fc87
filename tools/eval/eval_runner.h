#pragma once

#include <string>
#include <vector>

#include "core/status.h"
#include "pipeline/recover_depth.h"
#include "tools/eval/frame_evaluator.h"
#include "tools/input_source.h"

namespace corridor {

// How EvaluateScenes spreads the work.
struct EvalRunOptions {
  int threads = 1;             // Worker threads, >= 1.
  std::string progress_label;  // Shown before the progress bar; "" shows none.
  bool sequence = false;       // Each scene is a sequence: its frames in order on one thread, with the previous frame's geometry.
};

// The thread count for --threads: 0 -> hardware concurrency (at least 1); negative ->
// InvalidArgument.
Status ResolveThreadCount(int flag, int* threads);

// Evaluates every frame of every scene, in parallel, and stores the records in dataset order
// (scene by scene, frame by frame), so the result does not depend on the thread count. Returns
// non-ok (and stops early) only when an output cannot be written.
Status EvaluateScenes(const std::vector<InputScene>& scenes, const DepthRecoverer& recoverer,
                      const FrameEvalOptions& frame_options, const EvalRunOptions& run_options,
                      std::vector<FrameRecord>* records);

}  // namespace corridor
