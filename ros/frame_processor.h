#pragma once

#include <memory>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/status.h"
#include "perception/junction_tracker.h"
#include "pipeline/recover_depth.h"
#include "pipeline/sequence_prior.h"

namespace corridor {

// The node's frames through the library: one stream in order (~sequence true: the junction track
// and the width and ceiling holds carried from frame to frame, as corridor_depth does for a video)
// or independent frames. One thread at a time.
class FrameProcessor {
 public:
  static Status Create(const RecoverDepthOptions& options, bool sequence,
                       std::unique_ptr<FrameProcessor>* processor);
  // The next frame. Returns result->status.
  Status Process(const cv::Mat& image, const Camera& camera, RecoverDepthResult* result);
  // Forgets the stream: the next frame is processed as the first.
  void Reset();
  const RecoverDepthOptions& options() const { return recoverer_->options(); }

 private:
  FrameProcessor(std::unique_ptr<DepthRecoverer> recoverer, bool sequence)
      : recoverer_(std::move(recoverer)), sequence_(sequence) {}
  std::unique_ptr<DepthRecoverer> recoverer_;
  bool sequence_;
  JunctionTrack track_;
  SequencePrior prior_;
};

}  // namespace corridor
