#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/status.h"

namespace corridor {

// ROS 1 bags, read and written with Debian's rosbag_storage library (never parsed by hand).
// rosbag_storage reads out of bounds on some corrupt bags, so every read runs in a forked child
// process that sends the deserialised messages through a pipe: a crash there is a status here.
// Every failure (a missing, truncated or unindexed bag, a topic that is not there, an encoding
// this library does not decode) is a Status whose message names the bag and what is wrong.

// A ROS time: seconds and nanoseconds since the epoch.
struct BagStamp {
  uint32_t sec = 0;   // Seconds.
  uint32_t nsec = 0;  // Nanoseconds, [0, 1e9).
  int64_t Nanoseconds() const { return static_cast<int64_t>(sec) * 1000000000 + nsec; }
  static BagStamp FromNanoseconds(int64_t ns);
  // "<sec>.<nsec>" with nine nanosecond digits, e.g. "1700000000.050000000": sorts by time.
  std::string ToString() const;
};

// One topic of a bag.
struct BagTopic {
  std::string name;       // e.g. "/zed2/left/image_rect_color".
  std::string type;       // e.g. "sensor_msgs/Image".
  uint32_t messages = 0;  // How many messages it has.
};

// The topics of a bag, sorted by name. NotFound for a missing file, InvalidArgument for a file
// that is not a readable ROS 1 bag (truncated, unindexed, another format).
Status ListBagTopics(const std::string& bag_path, std::vector<BagTopic>* topics);

// Is the topic an image topic this library reads (sensor_msgs/Image or CompressedImage)?
bool IsImageTopicType(const std::string& type);

// The image topic and its CameraInfo topic. `requested_image` empty: the only image topic (an
// error listing them all when there are several, or naming the bag when there is none).
// `requested_info` empty: "<namespace>/camera_info" beside the image topic (a trailing
// "/compressed" is dropped first), else the bag's only CameraInfo topic, else none (*info = "").
// A requested topic that is not in the bag, or has another type, is an error that lists the
// bag's topics. `image_messages` (may be null) gets the image topic's message count.
Status ChooseBagTopics(const std::string& bag_path, const std::string& requested_image,
                       const std::string& requested_info, std::string* image_topic,
                       std::string* info_topic, uint32_t* image_messages = nullptr);

// The camera of the first CameraInfo message on `info_topic`: K, the image size and plumb_bob
// distortion (an empty or all-zero D = none; another distortion model is an error naming it).
// mount_height stays 0. Also returns the message's frame_id (may be null).
Status ReadBagCameraInfo(const std::string& bag_path, const std::string& info_topic,
                         Camera* camera, std::string* frame_id);

// One image message, decoded.
struct BagImage {
  BagStamp stamp;        // header.stamp of the message.
  std::string frame_id;  // header.frame_id.
  cv::Mat bgr;           // 8-bit BGR; empty when decoding failed.
  Status status;         // Why the image could not be decoded (an unsupported encoding names it).
};

// Decodes a sensor_msgs/Image's pixels (rgb8, bgr8, mono8, bgra8, rgba8) into BGR; any other
// encoding is an InvalidArgument naming it, as is data too short for width, height and step.
Status DecodeRawImage(const std::string& encoding, int width, int height, int step,
                      const uint8_t* data, size_t size, cv::Mat* bgr);
// Decodes a sensor_msgs/CompressedImage's bytes (format containing jpeg or png) into BGR.
Status DecodeCompressedImage(const std::string& format, const std::vector<uint8_t>& data,
                             cv::Mat* bgr);

// The namespace a camera's depth goes under: the image topic's parent, after dropping a transport
// suffix (/compressed, /compressedDepth, /theora), e.g. "/cam/image_raw/compressed" -> "/cam";
// "/" for a topic at the root.
std::string DepthTopicPrefix(const std::string& image_topic);

// Reads the image messages of one topic in bag order (the order of their receive times).
class BagImageReader {
 public:
  ~BagImageReader();
  static Status Open(const std::string& bag_path, const std::string& image_topic,
                     std::unique_ptr<BagImageReader>* reader);
  // The next message; false at the end. A message that cannot be decoded comes back with a
  // status and no image; a bag that turns out corrupt mid-way ends the stream with a status.
  bool Next(BagImage* image);

 private:
  struct Impl;
  explicit BagImageReader(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// Writes depth maps as a ROS 1 bag: sensor_msgs/Image in the live node's encodings (32FC1 metres
// with NaN = none, or 16UC1 millimetres with 0 = none; io/ros_depth_message.h) plus the matching
// sensor_msgs/CameraInfo on the same stamps. The bag is written under "<path>.part" and renamed by
// Close(), so an interrupted run never leaves a half-written bag under the final name.
class BagDepthWriter {
 public:
  ~BagDepthWriter();
  // `encoding`: "32FC1" or "16UC1" (InvalidArgument otherwise).
  static Status Open(const std::string& bag_path, std::unique_ptr<BagDepthWriter>* writer,
                     const std::string& encoding = "32FC1");
  // `depth_m` is CV_32F metres (0, negative or non-finite = none), the camera's size.
  Status Write(const std::string& image_topic, const std::string& info_topic,
               const BagStamp& stamp, const std::string& frame_id, const cv::Mat& depth_m,
               const Camera& camera);
  Status Close();

 private:
  struct Impl;
  explicit BagDepthWriter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace corridor
