#include "ros/frame_processor.h"

namespace corridor {

Status FrameProcessor::Create(const RecoverDepthOptions& options, bool sequence,
                              std::unique_ptr<FrameProcessor>* processor) {
  std::unique_ptr<DepthRecoverer> recoverer;
  const Status status = DepthRecoverer::Create(options, &recoverer);
  if (!status.ok()) return status;
  processor->reset(new FrameProcessor(std::move(recoverer), sequence));
  return Status::Ok();
}

Status FrameProcessor::Process(const cv::Mat& image, const Camera& camera,
                               RecoverDepthResult* result) {
  *result = RecoverDepthResult();
  if (!sequence_) return recoverer_->Recover(image, camera, result);
  // As corridor_depth's pipeline does for a stream: detect along the track, reconstruct with the
  // previous frame's geometry, then remember this one.
  recoverer_->Detect(image, camera, result, &track_);
  if (result->ReadyToReconstruct()) recoverer_->Reconstruct(camera, result, prior_.Previous());
  prior_.Update(*result);
  return result->status;
}

void FrameProcessor::Reset() {
  track_ = JunctionTrack();
  prior_ = SequencePrior();
}

}  // namespace corridor
