#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "corridor_depth/status.h"

namespace corridor {

// How a photo with an EXIF orientation tag is read.
enum class ImageOrientation {
  kAsStored,  // The pixels as stored (a calibration is for these).
  kUpright,   // Turned as the tag says, as photo viewers show it.
};

// Reads any colour, grey, 16-bit or alpha image as 8-bit BGR. A missing, empty, truncated or
// non-image file gets a status that names the path.
Status ReadColorImage(const std::string& path, cv::Mat* bgr,
                      ImageOrientation orientation = ImageOrientation::kAsStored);

// Reads a 16-bit millimetre depth PNG into CV_32F metres (0 = invalid).
Status ReadDepthPng(const std::string& path, cv::Mat* depth_m);

// CV_32F metres -> CV_16U millimetres: rounded; 0, negative and non-finite -> 0; clamped to 65535.
cv::Mat DepthToMillimetres(const cv::Mat& depth_m);

// Writes CV_32F metres as a 16-bit millimetre PNG (rounded; 0 and non-finite -> 0; clamped to
// 65535). Atomic.
Status WriteDepthPng(const std::string& path, const cv::Mat& depth_m);

// Writes any image OpenCV can encode, to a temporary name first and then renamed, so that an
// interrupted run never leaves a half-written file under the final name. Creates parent folders.
Status WriteImageAtomic(const std::string& path, const cv::Mat& image);

// Writes a text file atomically. Creates parent folders.
Status WriteTextAtomic(const std::string& path, const std::string& text);

}  // namespace corridor
