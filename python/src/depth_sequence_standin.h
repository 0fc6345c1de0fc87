#pragma once

// Stand-in for corridor::DepthSequence (pipeline/depth_sequence.h, on its way to main) with the
// same API, as FramePipeline runs a sequence on one thread. Deleted once main has the class.

#include <memory>

#include "pipeline/recover_depth.h"
#include "pipeline/sequence_prior.h"

namespace corridor {

class DepthSequence {
 public:
  static Status Create(const RecoverDepthOptions& options,
                       std::unique_ptr<DepthSequence>* sequence) {
    std::unique_ptr<DepthRecoverer> recoverer;
    const Status status = DepthRecoverer::Create(options, &recoverer);
    if (!status.ok()) return status;
    sequence->reset(new DepthSequence(std::move(recoverer)));
    return Status::Ok();
  }

  Status Process(const cv::Mat& image, const Camera& camera, RecoverDepthResult* result) {
    recoverer_->Detect(image, camera, result, &track_);
    if (result->ReadyToReconstruct()) {
      recoverer_->Reconstruct(camera, result, prior_.Previous());
      prior_.Update(*result);
    }
    return result->status;
  }

  void Reset() {
    track_ = JunctionTrack();
    prior_ = SequencePrior();
  }

 private:
  explicit DepthSequence(std::unique_ptr<DepthRecoverer> recoverer)
      : recoverer_(std::move(recoverer)) {}

  std::unique_ptr<DepthRecoverer> recoverer_;
  JunctionTrack track_;
  SequencePrior prior_;
};

}  // namespace corridor
