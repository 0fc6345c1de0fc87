#pragma once

#include <memory>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/status.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {

// The frames of one camera stream, fed in order: owns what a sequence carries from frame to frame
// (the junction track and the width and ceiling holds), so that a caller gets each frame's result
// as corridor_depth computes it for a video. One thread at a time.
class DepthSequence {
 public:
  // Checks the options and creates the recoverer; InvalidArgument on a bad option.
  static Status Create(const RecoverDepthOptions& options, std::unique_ptr<DepthSequence>* sequence);
  ~DepthSequence();

  // The next frame of the stream. Returns result->status.
  Status Process(const cv::Mat& image, const Camera& camera, RecoverDepthResult* result);

  // Forgets the stream (a new scene, a jump): the next frame is processed as the first.
  void Reset();

  const RecoverDepthOptions& options() const { return recoverer_->options(); }

 private:
  struct Carried;  // The junction track and the sequence prior (depth_sequence.cc).
  DepthSequence(std::unique_ptr<DepthRecoverer> recoverer, std::unique_ptr<Carried> carried);

  std::unique_ptr<DepthRecoverer> recoverer_;
  std::unique_ptr<Carried> carried_;
};

}  // namespace corridor
