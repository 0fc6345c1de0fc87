#include "corridor_depth/depth_sequence.h"

#include "perception/junction_tracker.h"
#include "pipeline/sequence_prior.h"

namespace corridor {

struct DepthSequence::Carried {
  JunctionTrack track;
  SequencePrior prior;
};

DepthSequence::DepthSequence(std::unique_ptr<DepthRecoverer> recoverer,
                             std::unique_ptr<Carried> carried)
    : recoverer_(std::move(recoverer)), carried_(std::move(carried)) {}

DepthSequence::~DepthSequence() = default;

Status DepthSequence::Create(const RecoverDepthOptions& options,
                             std::unique_ptr<DepthSequence>* sequence) {
  std::unique_ptr<DepthRecoverer> recoverer;
  const Status status = DepthRecoverer::Create(options, &recoverer);
  if (!status.ok()) return status;
  sequence->reset(new DepthSequence(std::move(recoverer), std::make_unique<Carried>()));
  return Status::Ok();
}

Status DepthSequence::Process(const cv::Mat& image, const Camera& camera,
                              RecoverDepthResult* result) {
  recoverer_->Recover(image, camera, result, carried_->prior.Previous(), &carried_->track);
  carried_->prior.Update(*result);
  return result->status;
}

void DepthSequence::Reset() { *carried_ = Carried(); }

}  // namespace corridor
