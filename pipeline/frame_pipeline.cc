#include "pipeline/frame_pipeline.h"

#include <atomic>
#include <thread>

#include "pipeline/bounded_queue.h"

namespace corridor {

int64_t FramePipeline::Run(const Source& source, const Sink& sink) {
  BoundedQueue<PipelineFrame> queue(static_cast<size_t>(queue_capacity_));
  std::thread extraction([&] {
    for (int64_t index = 0;; ++index) {
      PipelineFrame frame;
      if (!source(&frame)) break;
      frame.index = index;
      if (!frame.read_status.ok()) {
        frame.result.status = frame.read_status;
      } else if (frame.camera == nullptr) {
        frame.result.status = Status::InvalidArgument("frame " + frame.name + " has no camera");
      } else {
        recoverer_.Detect(frame.image, *frame.camera, &frame.result);
      }
      if (!queue.Push(std::move(frame))) break;  // The consumer stopped.
    }
    queue.Close();
  });
  int64_t delivered = 0;
  bool stopped = false;
  // The last frame's geometry: when one junction is hidden, its width stands in.
  CorridorGeometry previous;
  bool has_previous = false;
  while (auto frame = queue.Pop()) {
    if (stopped) continue;  // Drain so that the extraction thread can finish.
    if (frame->result.ReadyToReconstruct() && frame->camera != nullptr) {
      recoverer_.Reconstruct(*frame->camera, &frame->result, has_previous ? &previous : nullptr);
      if (frame->result.status.ok()) {
        previous = frame->result.geometry;
        has_previous = true;
      }
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
