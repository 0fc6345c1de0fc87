#include "pipeline/image_input.h"

#include <mutex>
#include <sstream>
#include <string>

#include <opencv2/imgproc.hpp>

namespace corridor {

Status ToBgr(const cv::Mat& image, const Camera& camera, cv::Mat* bgr) {
  if (image.empty()) return Status::InvalidArgument("image is empty");
  if (image.cols != camera.image_width || image.rows != camera.image_height) {
    std::ostringstream msg;
    msg << "image is " << image.cols << "x" << image.rows << " but the calibration is for "
        << camera.image_width << "x" << camera.image_height;
    return Status::InvalidArgument(msg.str());
  }
  cv::Mat eight_bit = image;
  if (image.depth() == CV_16U) {
    image.convertTo(eight_bit, CV_8U, 1.0 / 257.0);  // 65535 -> 255, as ReadColorImage does.
  } else if (image.depth() != CV_8U) {
    return Status::InvalidArgument("image must be 8- or 16-bit unsigned, but it is " +
                                   cv::typeToString(image.type()));
  }
  if (eight_bit.channels() == 3) {
    *bgr = eight_bit;
  } else if (eight_bit.channels() == 1) {
    cv::cvtColor(eight_bit, *bgr, cv::COLOR_GRAY2BGR);
  } else if (eight_bit.channels() == 2) {  // Grey + alpha: keep the grey.
    cv::Mat grey;
    cv::extractChannel(eight_bit, grey, 0);
    cv::cvtColor(grey, *bgr, cv::COLOR_GRAY2BGR);
  } else if (eight_bit.channels() == 4) {
    cv::cvtColor(eight_bit, *bgr, cv::COLOR_BGRA2BGR);
  } else {
    return Status::InvalidArgument("image must have 1, 2, 3 or 4 channels, but it has " +
                                   std::to_string(eight_bit.channels()));
  }
  return Status::Ok();
}

// OpenCV 4.6 builds its BGR->Lab tables lazily and without a lock (color_lab.cpp, initLabTabs):
// two threads converting their first image at once both build them, and one copy leaks (found by
// LeakSanitizer in corridor_eval --threads=2). Building them once, before any Recover, keeps
// concurrent Recover calls clean. (Perception converts to Lab: the junction detector's floor
// appearance.)
void BuildOpenCvTablesOnce() {
  static std::once_flag once;
  std::call_once(once, [] {
    cv::Mat lab;
    cv::cvtColor(cv::Mat(1, 1, CV_8UC3, cv::Scalar::all(128)), lab, cv::COLOR_BGR2Lab);
  });
}

}  // namespace corridor
