#include "pipeline/depth_sequence.h"

namespace corridor {

Status DepthSequence::Create(const RecoverDepthOptions& options,
                             std::unique_ptr<DepthSequence>* sequence) {
  std::unique_ptr<DepthRecoverer> recoverer;
  const Status status = DepthRecoverer::Create(options, &recoverer);
  if (!status.ok()) return status;
  sequence->reset(new DepthSequence(std::move(recoverer)));
  return Status::Ok();
}

Status DepthSequence::Process(const cv::Mat& image, const Camera& camera,
                              RecoverDepthResult* result) {
  recoverer_->Recover(image, camera, result, prior_.Previous(), &track_);
  prior_.Update(*result);
  return result->status;
}

void DepthSequence::Reset() {
  track_ = JunctionTrack();
  prior_ = SequencePrior();
}

}  // namespace corridor
