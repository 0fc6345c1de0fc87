#include "pipeline/frame_pipeline.h"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "pipeline/bounded_queue.h"
#include "pipeline/sequence_holds.h"
#include "pipeline/sequence_prior.h"
#include "perception/junction_tracker.h"

namespace corridor {

int64_t FramePipeline::Run(const Source& source, const Sink& sink) {
  BoundedQueue<PipelineFrame> queue(static_cast<size_t>(queue_capacity_));
  // Whether a frame searched whole confirms the junction track is known only once it is
  // reconstructed (TrackConfirmedBy): the extraction thread waits for that frame's answer before
  // it detects the next one, so that a stream gives what Recover gives frame by frame.
  std::mutex mutex;
  std::condition_variable answered;
  int64_t last_answered = -1;     // The last frame the depth-recovery thread finished.
  int64_t last_unconfirmed = -1;  // The last detected frame that did not confirm the track.
  bool recovery_done = false;
  std::thread extraction([&] {
    JunctionTrack track;
    int64_t searched = -1;  // The last frame whose junctions were searched whole.
    for (int64_t index = 0;; ++index) {
      PipelineFrame frame;
      if (!source(&frame)) break;
      frame.index = index;
      if (sequence_ && track.JustAgreed()) {
        std::unique_lock<std::mutex> lock(mutex);
        answered.wait(lock, [&] { return last_answered >= searched || recovery_done; });
        if (last_unconfirmed == searched) track.Unconfirmed();
      }
      if (!frame.read_status.ok()) {
        frame.result.status = frame.read_status;
      } else if (frame.camera == nullptr) {
        frame.result.status = Status::InvalidArgument("frame " + frame.name + " has no camera");
      } else {
        recoverer_.Detect(frame.image, *frame.camera, &frame.result, sequence_ ? &track : nullptr);
        if (!frame.result.junctions_tracked) searched = index;
      }
      if (!queue.Push(std::move(frame))) break;  // The consumer stopped.
    }
    queue.Close();
  });
  int64_t delivered = 0;
  bool stopped = false;
  SequencePrior prior;  // The last frame's geometry, for a hidden junction or a held width.
  const auto answer = [&](int64_t index, bool confirmed) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      last_answered = index;
      if (!confirmed) last_unconfirmed = index;
    }
    answered.notify_one();
  };
  while (auto frame = queue.Pop()) {
    if (stopped) {  // Drain so that the extraction thread can finish.
      answer(frame->index, true);
      continue;
    }
    if (frame->result.ReadyToReconstruct() && frame->camera != nullptr) {
      recoverer_.Reconstruct(*frame->camera, &frame->result,
                             sequence_ ? prior.Previous() : nullptr);
      prior.Update(frame->result);
    }
    const bool detected = frame->read_status.ok() && frame->camera != nullptr;
    answer(frame->index, !detected || TrackConfirmedBy(recoverer_.options(), frame->result));
    ++delivered;
    if (!sink(std::move(*frame))) {
      stopped = true;
      queue.Close();
    }
  }
  {
    std::lock_guard<std::mutex> lock(mutex);
    recovery_done = true;
  }
  answered.notify_one();
  extraction.join();
  last_high_water_ = queue.high_water();
  return delivered;
}

}  // namespace corridor
