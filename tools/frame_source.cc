#include "tools/frame_source.h"

#include <cmath>
#include <cstdio>

#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "corridor_depth/image_io.h"
#ifdef CORRIDOR_HAVE_ROSBAG
#include "io/rosbag_io.h"
#endif

namespace corridor {
namespace {

class ImageFileSource : public FrameSource {
 public:
  explicit ImageFileSource(const InputScene& scene) : scene_(scene) {}
  bool Next(PipelineFrame* frame) override {
    if (next_ >= scene_.frames.size()) return false;
    const DatasetFrame& input = scene_.frames[next_++];
    frame->name = input.name;
    frame->stamp_ns = -1;
    frame->read_status = ReadColorImage(input.rgb_path, &frame->image,
                                        scene_.per_image_hfov_deg > 0 ? ImageOrientation::kUpright
                                                                      : ImageOrientation::kAsStored);
    return true;
  }

 private:
  const InputScene& scene_;
  size_t next_ = 0;
};

// Frames of a video, named by their index ("000000", ...).
class VideoSource : public FrameSource {
 public:
  VideoSource(std::string path, std::unique_ptr<cv::VideoCapture> capture)
      : path_(std::move(path)), capture_(std::move(capture)) {}
  bool Next(PipelineFrame* frame) override {
    if (ended_) return false;
    cv::Mat image;
    bool read = false;
    try {
      read = capture_->read(image);
    } catch (const cv::Exception& e) {
      ended_ = true;
      frame->name = FrameName();
      frame->read_status = Status::InvalidArgument(path_ + ": frame " + frame->name +
                                                   " cannot be decoded: " + e.what());
      return true;
    }
    if (!read || image.empty()) return false;
    frame->name = FrameName();
    ++index_;
    frame->stamp_ns = -1;
    if (image.type() == CV_8UC1) cv::cvtColor(image, image, cv::COLOR_GRAY2BGR);
    if (image.type() != CV_8UC3) {
      frame->read_status = Status::InvalidArgument(path_ + ": frame " + frame->name + " is " +
                                                   cv::typeToString(image.type()) +
                                                   ", not 8-bit colour");
      return true;
    }
    frame->image = image;
    return true;
  }

 private:
  std::string FrameName() const {
    char name[32];
    std::snprintf(name, sizeof(name), "%06lld", static_cast<long long>(index_));
    return name;
  }
  std::string path_;
  std::unique_ptr<cv::VideoCapture> capture_;
  int64_t index_ = 0;
  bool ended_ = false;
};

#ifdef CORRIDOR_HAVE_ROSBAG
// Image messages of a bag topic, named by their stamps ("<sec>.<nsec>").
class BagSource : public FrameSource {
 public:
  explicit BagSource(std::unique_ptr<BagImageReader> reader) : reader_(std::move(reader)) {}
  bool Next(PipelineFrame* frame) override {
    BagImage message;
    if (!reader_->Next(&message)) return false;
    frame->name = message.stamp.ToString();
    frame->stamp_ns = message.stamp.Nanoseconds();
    frame->image = message.bgr;
    frame->read_status = message.status;
    return true;
  }

 private:
  std::unique_ptr<BagImageReader> reader_;
};
#endif

}  // namespace

Status OpenVideo(const std::string& path, std::unique_ptr<cv::VideoCapture>* capture) {
  auto opened = std::make_unique<cv::VideoCapture>();
  bool ok = false;
  // The file backends only (CAP_ANY would also probe cameras, and one of them leaks libusb's
  // device list). They log their own failures; the status names the file once.
  const auto level = cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
  std::string error;
  for (const int backend : {cv::CAP_FFMPEG, cv::CAP_GSTREAMER, cv::CAP_OPENCV_MJPEG}) {
    try {
      ok = opened->open(path, backend);
    } catch (const cv::Exception& e) {
      error = e.what();
    }
    if (ok && opened->isOpened()) break;
  }
  cv::utils::logging::setLogLevel(level);
  if (ok && opened->isOpened()) error.clear();
  if (!error.empty()) return Status::InvalidArgument(path + ": cannot open the video: " + error);
  if (!ok || !opened->isOpened()) {
    return Status::InvalidArgument(path +
                                   ": cannot open the video (no OpenCV backend reads it, "
                                   "or it is not a video)");
  }
  *capture = std::move(opened);
  return Status::Ok();
}

Status OpenFrameSource(const InputScene& scene, std::unique_ptr<FrameSource>* source) {
  switch (scene.kind) {
    case InputKind::kImages:
      *source = std::make_unique<ImageFileSource>(scene);
      return Status::Ok();
    case InputKind::kVideo: {
      std::unique_ptr<cv::VideoCapture> capture;
      const Status status = OpenVideo(scene.stream_path, &capture);
      if (!status.ok()) return status;
      *source = std::make_unique<VideoSource>(scene.stream_path, std::move(capture));
      return Status::Ok();
    }
    case InputKind::kRosBag: {
#ifdef CORRIDOR_HAVE_ROSBAG
      std::unique_ptr<BagImageReader> reader;
      const Status status = BagImageReader::Open(scene.stream_path, scene.image_topic, &reader);
      if (!status.ok()) return status;
      *source = std::make_unique<BagSource>(std::move(reader));
      return Status::Ok();
#else
      return Status::InvalidArgument(scene.stream_path +
                                     ": this build has no ROS bag support "
                                     "(configure with -DCORRIDOR_WITH_ROSBAG=ON)");
#endif
    }
  }
  return Status::Internal("unknown input kind");
}

Status ReadFirstFrame(const InputScene& scene, cv::Mat* image) {
  std::unique_ptr<FrameSource> source;
  const Status status = OpenFrameSource(scene, &source);
  if (!status.ok()) return status;
  PipelineFrame frame;
  if (!source->Next(&frame)) {
    return Status::InvalidArgument((scene.stream_path.empty() ? scene.name : scene.stream_path) +
                                   ": has no frames");
  }
  if (!frame.read_status.ok()) return frame.read_status;
  *image = frame.image;
  return Status::Ok();
}

}  // namespace corridor
