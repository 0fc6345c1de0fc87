#pragma once

#include <opencv2/core.hpp>

#include "perception/working_image.h"

namespace corridor {

// What DepthRecoverer::Detect hands to Reconstruct beside the junctions
// (RecoverDepthResult::handover): internal state, not an output.
struct FrameHandover {
  cv::Mat image;         // The frame as 8-bit BGR.
  WorkingImage search;   // The frame halved to search_max_width, when Detect halved it for the
                         // junction search too (from that halving; else empty).
  cv::Mat depth_memory;  // The previous frame's depth matrix, when nothing else held it: the
                         // memory Reconstruct renders into.
};

}  // namespace corridor
