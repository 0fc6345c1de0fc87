#pragma once

#include <memory>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/status.h"
#include "corridor_depth/depth_sequence.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {

// The node's frames through the library: one stream in order (~sequence true: a DepthSequence,
// which carries the junction track and the width and ceiling holds from frame to frame, as
// corridor_depth does for a video) or independent frames (DepthRecoverer::Recover). One thread at
// a time.
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
  FrameProcessor() = default;
  std::unique_ptr<DepthRecoverer> recoverer_;  // Independent frames; also holds the options.
  std::unique_ptr<DepthSequence> sequence_;    // Null for independent frames.
};

}  // namespace corridor
