// Decoding of image messages and ROS times: no ROS library needed.
#include <algorithm>
#include <cstdio>
#include <map>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "io/rosbag_io.h"

namespace corridor {

BagStamp BagStamp::FromNanoseconds(int64_t ns) {
  BagStamp stamp;
  if (ns < 0) ns = 0;
  stamp.sec = static_cast<uint32_t>(ns / 1000000000);
  stamp.nsec = static_cast<uint32_t>(ns % 1000000000);
  return stamp;
}

std::string BagStamp::ToString() const {
  char text[32];
  std::snprintf(text, sizeof(text), "%u.%09u", sec, nsec);
  return text;
}

std::string DepthTopicPrefix(const std::string& image_topic) {
  std::string topic = image_topic;
  while (topic.size() > 1 && topic.back() == '/') topic.pop_back();
  for (const char* transport : {"/compressed", "/compressedDepth", "/theora"}) {
    const std::string suffix = transport;
    if (topic.size() > suffix.size() &&
        topic.compare(topic.size() - suffix.size(), suffix.size(), suffix) == 0) {
      topic.resize(topic.size() - suffix.size());
      break;
    }
  }
  const size_t slash = topic.rfind('/');
  if (slash == std::string::npos || slash == 0) return "/";
  return topic.substr(0, slash);
}

bool IsImageTopicType(const std::string& type) {
  return type == "sensor_msgs/Image" || type == "sensor_msgs/CompressedImage";
}

Status DecodeRawImage(const std::string& encoding, int width, int height, int step,
                      const uint8_t* data, size_t size, cv::Mat* bgr) {
  static const std::map<std::string, std::pair<int, int>> kTypes = {
      {"rgb8", {CV_8UC3, cv::COLOR_RGB2BGR}}, {"bgr8", {CV_8UC3, -1}}, {"mono8", {CV_8UC1, cv::COLOR_GRAY2BGR}}, {"bgra8", {CV_8UC4, cv::COLOR_BGRA2BGR}}, {"rgba8", {CV_8UC4, cv::COLOR_RGBA2BGR}}};
  const auto type = kTypes.find(encoding);
  if (type == kTypes.end()) {
    return Status::InvalidArgument("unsupported image encoding '" + encoding +
                                   "' (supported: rgb8, bgr8, mono8, bgra8, rgba8, and "
                                   "compressed jpeg or png)");
  }
  const int channels = CV_MAT_CN(type->second.first);
  if (width <= 0 || height <= 0 || step < width * channels ||
      size < static_cast<size_t>(step) * static_cast<size_t>(height)) {
    return Status::InvalidArgument("image message of " + std::to_string(width) + "x" +
                                   std::to_string(height) + " " + encoding + " with step " +
                                   std::to_string(step) + " holds only " + std::to_string(size) +
                                   " bytes");
  }
  const cv::Mat view(height, width, type->second.first, const_cast<uint8_t*>(data),
                     static_cast<size_t>(step));
  if (type->second.second < 0) {
    *bgr = view.clone();
  } else {
    cv::cvtColor(view, *bgr, type->second.second);
  }
  return Status::Ok();
}

Status DecodeCompressedImage(const std::string& format, const std::vector<uint8_t>& data,
                             cv::Mat* bgr) {
  std::string lower = format;
  std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
  if (lower.find("jpeg") == std::string::npos && lower.find("jpg") == std::string::npos &&
      lower.find("png") == std::string::npos) {
    return Status::InvalidArgument("unsupported compressed image format '" + format +
                                   "' (supported: jpeg, png)");
  }
  cv::Mat decoded;
  try {
    decoded = cv::imdecode(data, cv::IMREAD_COLOR);
  } catch (const cv::Exception&) {
    decoded.release();
  }
  if (decoded.empty()) {
    return Status::InvalidArgument("compressed image (format '" + format + ", " +
                                   std::to_string(data.size()) + " bytes) does not decode");
  }
  *bgr = decoded;
  return Status::Ok();
}

}  // namespace corridor
