#pragma once

#include <memory>

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "corridor_depth/status.h"
#include "pipeline/frame_pipeline.h"
#include "tools/input_source.h"

namespace corridor {

// The frames of one scene in input order, whatever holds them: image files, a ROS bag or a video.
class FrameSource {
 public:
  virtual ~FrameSource() = default;
  // Fills the next frame's name, image (or read_status) and stamp_ns; false at the end. The
  // camera pointer is left to the caller.
  virtual bool Next(PipelineFrame* frame) = 0;
};

// Opens the scene's frames: InvalidArgument/NotFound naming the bag or video when it cannot be
// opened (a file list always opens; its unreadable files fail one by one).
Status OpenFrameSource(const InputScene& scene, std::unique_ptr<FrameSource>* source);

// Opens a video file with OpenCV's file backends (FFmpeg, GStreamer, its own MJPEG reader);
// InvalidArgument naming the file when none reads it.
Status OpenVideo(const std::string& path, std::unique_ptr<cv::VideoCapture>* capture);

// The scene's first image, e.g. to size a camera from flags or to check a calibration; the status
// of the first frame when it cannot be read.
Status ReadFirstFrame(const InputScene& scene, cv::Mat* image);

}  // namespace corridor
