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
  // Whether a frame confirms the junction track is known only once it is reconstructed
  // (TrackConfirmedBy): while the track may stand for the next frame, the extraction thread waits
  // for the last detected frame's answer before it detects the next one, so that a stream gives
  // what Recover gives frame by frame.
  const RecoverDepthOptions& options = recoverer_.options();
  const bool confirm = sequence_ && options.track_junctions && options.ceiling_height <= 0 &&
                       options.estimate_ceiling;
  std::mutex mutex;
  std::condition_variable answered;
  int64_t last_answered = -1;     // The last frame the depth-recovery thread finished.
  int64_t last_unconfirmed = -1;  // The last detected frame that did not confirm the track.
  int64_t last_researched = -1;   // The last tracked frame searched whole again, with its pair:
  JunctionPair researched;
  bool researched_agrees = false;  // Whether that search found the tracked pair (its own kept).
  cv::Size researched_size;
  bool recovery_done = false;
  std::thread extraction([&] {
    JunctionTrack track;
    int64_t detected = -1;  // The last frame whose junctions were detected.
    for (int64_t index = 0;; ++index) {
      PipelineFrame frame;
      if (!source(&frame)) break;
      frame.index = index;
      // Trusted whatever the redetect interval: the last frame was tracked, or searched and agreed.
      if (confirm && track.Trusted(0)) {
        std::unique_lock<std::mutex> lock(mutex);
        answered.wait(lock, [&] { return last_answered >= detected || recovery_done; });
        if (last_researched == detected) {
          track.Searched(researched, researched_size, researched_agrees);
        } else if (last_unconfirmed == detected) {
          track.Unconfirmed();
        }
      }
      if (!frame.read_status.ok()) {
        frame.result.status = frame.read_status;
      } else if (frame.camera == nullptr) {
        frame.result.status = Status::InvalidArgument("frame " + frame.name + " has no camera");
      } else {
        recoverer_.Detect(frame.image, *frame.camera, &frame.result, sequence_ ? &track : nullptr);
        detected = index;
      }
      if (!queue.Push(std::move(frame))) break;  // The consumer stopped.
    }
    queue.Close();
  });
  int64_t delivered = 0;
  bool stopped = false;
  SequencePrior prior;  // The last frame's geometry, for a hidden junction or a held width.
  const auto answer = [&](int64_t index, bool confirmed, const PipelineFrame* searched_again,
                          bool agrees) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      last_answered = index;
      if (!confirmed) last_unconfirmed = index;
      if (searched_again != nullptr) {
        last_researched = index;
        researched = searched_again->result.junctions;
        researched_size = searched_again->image.size();
        researched_agrees = agrees;
      }
    }
    answered.notify_one();
  };
  while (auto frame = queue.Pop()) {
    if (stopped) {  // Drain so that the extraction thread can finish.
      answer(frame->index, true, nullptr, false);
      continue;
    }
    bool searched_again = false;
    bool agrees = false;  // The frame's own search kept found the tracked pair.
    if (frame->result.ReadyToReconstruct() && frame->camera != nullptr) {
      recoverer_.Reconstruct(*frame->camera, &frame->result,
                             sequence_ ? prior.Previous() : nullptr);
      if (confirm && frame->result.junctions_tracked && !TrackConfirmedBy(options, frame->result)) {
        // As Recover does: tracked lines the ceiling does not confirm, the frame searched whole.
        recoverer_.Recover(frame->image, *frame->camera, &frame->result, prior.Previous());
        searched_again = true;
      } else if (confirm && frame->result.junctions_tracked) {
        // As Recover does: the frame's own whole search kept when its ceiling confirms it.
        RecoverDepthResult own;
        recoverer_.Recover(frame->image, *frame->camera, &own, prior.Previous());
        if (OwnSearchKept(options, own)) {
          agrees = SameJunctions(frame->result.junctions, own.junctions,
                                 options.tracker.agreement_px);
          frame->result = std::move(own);
          searched_again = true;
        }
      }
      prior.Update(frame->result);
    }
    const bool detected = frame->read_status.ok() && frame->camera != nullptr;
    answer(frame->index, !detected || TrackConfirmedBy(options, frame->result),
           searched_again ? &*frame : nullptr, agrees);
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
