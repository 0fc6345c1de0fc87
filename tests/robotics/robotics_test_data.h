#pragma once

// Test material of the robotics input/output tests: generated corridor frames (the
// independent box ray caster of tests/depth/box_truth.h via
// tests/evaluation/eval_test_dataset.h), and ROS 1 bags written from them by the real rosbag
// library (Debian's python3-rosbag, driven by tests/robotics/write_test_bag.py), never by the
// code under test.

#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tests/evaluation/eval_test_dataset.h"
#include "tests/reliability/reliability_util.h"

namespace corridor {
namespace testing_util {

// Three views of one corridor, with their true depth (z, metres).
struct TestFrames {
  Camera camera;                // 320x240, fx 250, camera height 1.2 m.
  std::vector<cv::Mat> images;  // 8-bit BGR.
  std::vector<cv::Mat> depths;  // CV_32F metres from the ray caster (0 = beyond 60 m).
  std::vector<CorridorGeometry> poses;
};

inline TestFrames MakeTestFrames() {
  TestFrames frames;
  frames.camera = ReliabilityCamera();
  frames.poses = {ReliabilityGeometry(0.05, 0.10, 0.20, 2.4), ReliabilityGeometry(-0.04, 0.12, -0.15, 2.4),
                  ReliabilityGeometry(0.02, 0.09, 0.05, 2.4)};
  for (size_t i = 0; i < frames.poses.size(); ++i) {
    cv::Mat depth;
    frames.images.push_back(
        RenderTestCorridor(frames.camera, frames.poses[i], static_cast<int>(i) + 7, &depth));
    frames.depths.push_back(depth);
  }
  return frames;
}

// Stamp i of the test bags: sec 1700000000 + i, nsec 50 000 000 * (i + 1).
inline std::pair<uint32_t, uint32_t> TestStamp(size_t i) {
  return {1700000000u + static_cast<uint32_t>(i), 50000000u * static_cast<uint32_t>(i + 1)};
}
// The name corridor_depth gives the frame: "<sec>.<nsec>" with nine digits, written by hand here.
inline std::string TestStampName(size_t i) {
  char name[40];
  std::snprintf(name, sizeof(name), "%u.%09u", TestStamp(i).first, TestStamp(i).second);
  return name;
}

// Builds the JSON manifest of tests/robotics/write_test_bag.py, message by message.
class BagManifest {
 public:
  explicit BagManifest(const ScratchDir& dir) : dir_(dir) {}

  // A raw sensor_msgs/Image; `pixels` holds the bytes in the encoding's layout.
  void AddImage(const std::string& topic, size_t i, const std::string& encoding,
                const cv::Mat& pixels) {
    const std::string file = Data(pixels.data, pixels.total() * pixels.elemSize());
    Add("{\"topic\":\"" + topic + "\",\"kind\":\"image\"," + Stamp(i) + ",\"encoding\":\"" +
        encoding + "\",\"width\":" + std::to_string(pixels.cols) + ",\"height\":" +
        std::to_string(pixels.rows) + ",\"step\":" +
        std::to_string(pixels.cols * pixels.elemSize()) + ",\"data_file\":\"" + file + "\"}");
  }
  // A sensor_msgs/CompressedImage holding `bytes` (a JPEG or PNG file's content).
  void AddCompressed(const std::string& topic, size_t i, const std::string& format,
                     const std::vector<uchar>& bytes) {
    const std::string file = Data(bytes.data(), bytes.size());
    Add("{\"topic\":\"" + topic + "\",\"kind\":\"compressed\"," + Stamp(i) + ",\"format\":\"" +
        format + "\",\"data_file\":\"" + file + "\"}");
  }
  void AddCameraInfo(const std::string& topic, size_t i, const Camera& c) {
    char k[256];
    std::snprintf(k, sizeof(k), "[%.17g,0,%.17g,0,%.17g,%.17g,0,0,1]", c.fx, c.cx, c.fy, c.cy);
    Add("{\"topic\":\"" + topic + "\",\"kind\":\"camera_info\"," + Stamp(i) + ",\"width\":" +
        std::to_string(c.image_width) + ",\"height\":" + std::to_string(c.image_height) +
        ",\"K\":" + k + ",\"D\":[0,0,0,0,0]}");
  }

  // Writes the bag with the real rosbag library; returns its path.
  std::string WriteBag(const std::string& name) const {
    const std::string manifest = dir_.Write(name + ".json", "[" + items_ + "]");
    const std::string bag = dir_.Path(name);
    const ToolRun run = RunTool(CORRIDOR_ROSBAG_PYTHON, {kWriter, manifest, bag}, dir_);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(Exists(bag)) << run.err;
    return bag;
  }

 private:
  static constexpr const char* kWriter = CORRIDOR_SOURCE_DIR "/tests/robotics/write_test_bag.py";
  std::string Stamp(size_t i) const {
    return "\"stamp\":[" + std::to_string(TestStamp(i).first) + "," +
           std::to_string(TestStamp(i).second) + "],\"frame_id\":\"test_camera\"";
  }
  std::string Data(const void* bytes, size_t size) {
    const std::string name = "msg" + std::to_string(count_) + ".bin";
    dir_.Write(name, std::string(static_cast<const char*>(bytes), size));
    return name;
  }
  void Add(const std::string& item) {
    items_ += (count_++ ? "," : "") + item;
  }
  const ScratchDir& dir_;
  std::string items_;
  int count_ = 0;
};

// An 8-bit BGR image in a ROS raw encoding's byte layout.
inline cv::Mat ToEncoding(const cv::Mat& bgr, const std::string& encoding) {
  cv::Mat out;
  if (encoding == "rgb8") cv::cvtColor(bgr, out, cv::COLOR_BGR2RGB);
  if (encoding == "bgr8") out = bgr.clone();
  if (encoding == "mono8") cv::cvtColor(bgr, out, cv::COLOR_BGR2GRAY);
  if (encoding == "bgra8") cv::cvtColor(bgr, out, cv::COLOR_BGR2BGRA);
  return out;
}

// The depth PNG (16-bit mm) that corridor_depth wrote, read with OpenCV alone.
inline cv::Mat ReadDepthMm(const std::string& path) { return cv::imread(path, cv::IMREAD_UNCHANGED); }

}  // namespace testing_util
}  // namespace corridor
