#include "pipeline/frame_pipeline.h"

#include <atomic>
#include <thread>

#include "pipeline/bounded_queue.h"
#include "pipeline/sequence_prior.h"
#include "perception/junction_tracker.h"

namespace corridor {

int64_t FramePipeline::Run(const Source& source, const Sink& sink) {
  BoundedQueue<PipelineFrame> queue(static_cast<size_t>(queue_capacity_));
  std::thread extraction([&] {
    JunctionTrack track;
    for (int64_t index = 0;; ++index) {
      PipelineFrame frame;
      if (!source(&frame)) break;
      frame.index = index;
      if (!frame.read_status.ok()) {
        frame.result.status = frame.read_status;
      } else if (frame.camera == nullptr) {
        frame.result.status = Status::InvalidArgument("frame " + frame.name + " has no camera");
      } else {
        recoverer_.Detect(frame.image, *frame.camera, &frame.result, sequence_ ? &track : nullptr);
      }
      if (!queue.Push(std::move(frame))) break;  // The consumer stopped.
    }
    queue.Close();
  });
  int64_t delivered = 0;
  bool stopped = false;
  SequencePrior prior;  // The last frame's geometry, for a hidden junction or a held width.
  while (auto frame = queue.Pop()) {
    if (stopped) continue;  // Drain so that the extraction thread can finish.
    if (frame->result.ReadyToReconstruct() && frame->camera != nullptr) {
      recoverer_.Reconstruct(*frame->camera, &frame->result,
                             sequence_ ? prior.Previous() : nullptr);
      prior.Update(frame->result);
    }
    ++delivered;
    if (!sink(std::move(*frame))) {
      stopped = true;
      queue.Close();
    }
  }
  extraction.join();
  last_high_water_ = queue.high_water();
  return delivered;
}

}  // namespace corridor
