#include "ros/frame_processor.h"

namespace corridor {

Status FrameProcessor::Create(const RecoverDepthOptions& options, bool sequence,
                              std::unique_ptr<FrameProcessor>* processor) {
  std::unique_ptr<FrameProcessor> made(new FrameProcessor());
  Status status = DepthRecoverer::Create(options, &made->recoverer_);
  if (status.ok() && sequence) status = DepthSequence::Create(options, &made->sequence_);
  if (!status.ok()) return status;
  *processor = std::move(made);
  return Status::Ok();
}

Status FrameProcessor::Process(const cv::Mat& image, const Camera& camera,
                               RecoverDepthResult* result) {
  *result = RecoverDepthResult();
  if (sequence_) return sequence_->Process(image, camera, result);
  return recoverer_->Recover(image, camera, result);
}

void FrameProcessor::Reset() {
  if (sequence_) sequence_->Reset();
}

}  // namespace corridor
