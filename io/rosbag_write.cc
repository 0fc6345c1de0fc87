// BagDepthWriter: depth maps and CameraInfo into a ROS 1 bag, with rosbag_storage.

#include <filesystem>

#include <rosbag/bag.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include "io/ros_depth_message.h"
#include "io/rosbag_io.h"

namespace corridor {

namespace fs = std::filesystem;

struct BagDepthWriter::Impl {
  std::string path;
  std::string part_path;
  std::string encoding;  // 32FC1 or 16UC1.
  rosbag::Bag bag;
  bool open = false;
};

BagDepthWriter::BagDepthWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

BagDepthWriter::~BagDepthWriter() {
  if (impl_ && impl_->open) (void)Close();
}

Status BagDepthWriter::Open(const std::string& bag_path, std::unique_ptr<BagDepthWriter>* writer,
                            const std::string& encoding) {
  if (!IsDepthEncoding(encoding)) {
    return Status::InvalidArgument("depth encoding '" + encoding + "' (supported: 32FC1, 16UC1)");
  }
  auto impl = std::make_unique<Impl>();
  impl->encoding = encoding;
  impl->path = bag_path;
  impl->part_path = bag_path + ".part";
  std::error_code ec;
  const fs::path parent = fs::path(bag_path).parent_path();
  if (!parent.empty()) fs::create_directories(parent, ec);
  try {
    impl->bag.open(impl->part_path, rosbag::bagmode::Write);
  } catch (const std::exception& e) {
    return Status::IoError(bag_path + ": cannot open the output bag for writing: " + e.what());
  }
  impl->open = true;
  writer->reset(new BagDepthWriter(std::move(impl)));
  return Status::Ok();
}

Status BagDepthWriter::Write(const std::string& image_topic, const std::string& info_topic,
                             const BagStamp& stamp, const std::string& frame_id,
                             const cv::Mat& depth_m, const Camera& camera) {
  if (!impl_->open) return Status::IoError(impl_->path + ": the output bag is closed");
  if (depth_m.type() != CV_32FC1 || depth_m.cols != camera.image_width ||
      depth_m.rows != camera.image_height) {
    return Status::InvalidArgument(impl_->path + ": depth to write must be 32FC1 of the camera's " +
                                   "size");
  }
  const ros::Time time(stamp.sec, stamp.nsec);
  if (time < ros::TIME_MIN) {
    return Status::InvalidArgument(impl_->path + ": stamp " + stamp.ToString() +
                                   " is before ROS's earliest time");
  }
  sensor_msgs::Image image;
  image.header.stamp = time;
  image.header.frame_id = frame_id;
  const Status filled = FillDepthImage(depth_m, impl_->encoding, &image);
  if (!filled.ok()) return Status::InvalidArgument(impl_->path + ": " + filled.message());
  sensor_msgs::CameraInfo info;
  info.header = image.header;
  FillCameraInfo(camera, &info);
  try {
    impl_->bag.write(image_topic, time, image);
    impl_->bag.write(info_topic, time, info);
  } catch (const std::exception& e) {
    return Status::IoError(impl_->path + ": cannot write to the output bag: " + e.what());
  }
  return Status::Ok();
}

Status BagDepthWriter::Close() {
  if (!impl_->open) return Status::Ok();
  impl_->open = false;
  try {
    impl_->bag.close();
  } catch (const std::exception& e) {
    return Status::IoError(impl_->path + ": cannot finish the output bag: " + e.what());
  }
  std::error_code ec;
  fs::rename(impl_->part_path, impl_->path, ec);
  if (ec) {
    return Status::IoError(impl_->path + ": cannot rename " + impl_->part_path + ": " +
                           ec.message());
  }
  return Status::Ok();
}

}  // namespace corridor
