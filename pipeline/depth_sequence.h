#pragma once

#include <memory>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/status.h"
#include "perception/junction_tracker.h"
#include "pipeline/recover_depth.h"
#include "pipeline/sequence_prior.h"

namespace corridor {

// The frames of one camera stream, fed in order: owns what a sequence carries from frame to frame
// (the junction track and the width and ceiling holds), so that a caller gets each frame's result
// as corridor_depth computes it for a video. One thread at a time.
class DepthSequence {
 public:
  // Checks the options and creates the recoverer; InvalidArgument on a bad option.
  static Status Create(const RecoverDepthOptions& options, std::unique_ptr<DepthSequence>* sequence);

  // The next frame of the stream. Returns result->status.
  Status Process(const cv::Mat& image, const Camera& camera, RecoverDepthResult* result);

  // Forgets the stream (a new scene, a jump): the next frame is processed as the first.
  void Reset();

  const RecoverDepthOptions& options() const { return recoverer_->options(); }

 private:
  explicit DepthSequence(std::unique_ptr<DepthRecoverer> recoverer)
      : recoverer_(std::move(recoverer)) {}

  std::unique_ptr<DepthRecoverer> recoverer_;
  JunctionTrack track_;
  SequencePrior prior_;
};

}  // namespace corridor
