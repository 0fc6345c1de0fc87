#pragma once

#include <functional>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "corridor_depth/recover_depth.h"

namespace corridor {

// One frame flowing through the pipeline.
struct PipelineFrame {
  int64_t index = 0;                           // Position in the input order (set by the pipeline).
  std::string name;                            // The frame's name, for outputs and messages.
  int64_t stamp_ns = -1;                       // Capture time, ns since the epoch (a ROS bag message's); -1 = none.
  const Camera* camera = nullptr;              // Its camera; must outlive the run (or be owned_camera).
  std::shared_ptr<const Camera> owned_camera;  // A camera made for this frame alone (its size's).
  cv::Mat image;                               // The image; may be empty when reading failed.
  Status read_status;                          // Why the image could not be read (the frame then fails).
  RecoverDepthResult result;                   // Filled by the pipeline.
};

// The paper's two threads (section III-A, Fig. 1): an edge-extraction thread reads frames and
// detects the junction lines; it hands them through a bounded queue to the depth-recovery
// thread (the caller's), which estimates the geometry, rasterises the depth and passes each
// frame to the sink in input order. A failed frame is passed on with its status; the stream goes
// on. Memory stays bounded by the queue's capacity. As a sequence, each frame is found and
// reconstructed with what the previous ones left (the junction track, the holds); otherwise each
// frame is on its own, with the result it gets alone.
class FramePipeline {
 public:
  // Fills the next frame (name, camera, image or read_status); returns false at the end.
  using Source = std::function<bool(PipelineFrame*)>;
  // Receives every frame, in order, on the calling thread. Returns false to stop the stream.
  using Sink = std::function<bool(PipelineFrame&&)>;

  FramePipeline(const DepthRecoverer& recoverer, int queue_capacity = 4, bool sequence = true)
      : recoverer_(recoverer), queue_capacity_(queue_capacity), sequence_(sequence) {}

  // Runs until the source ends or the sink stops it. Returns the number of frames delivered.
  int64_t Run(const Source& source, const Sink& sink);

  // The most frames that waited in the queue at once during the last run.
  size_t last_high_water() const { return last_high_water_; }

 private:
  const DepthRecoverer& recoverer_;
  const int queue_capacity_;
  const bool sequence_;
  size_t last_high_water_ = 0;
};

}  // namespace corridor
