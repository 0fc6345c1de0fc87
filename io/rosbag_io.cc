#include "io/rosbag_io.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>

#include "io/image_io.h"

namespace corridor {
namespace {

namespace fs = std::filesystem;

constexpr char kImageType[] = "sensor_msgs/Image";
constexpr char kCompressedType[] = "sensor_msgs/CompressedImage";
constexpr char kCameraInfoType[] = "sensor_msgs/CameraInfo";

// Opens a bag for reading; every rosbag exception becomes a status naming the bag.
Status OpenForReading(const std::string& path, rosbag::Bag* bag) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return Status::NotFound(path + ": no such bag file");
  if (fs::is_directory(path, ec)) return Status::InvalidArgument(path + ": is a folder, not a bag");
  try {
    bag->open(path, rosbag::bagmode::Read);
  } catch (const rosbag::BagUnindexedException&) {
    return Status::InvalidArgument(path + ": the bag is unindexed (truncated or not closed); "
                                   "repair it with `rosbag reindex`");
  } catch (const std::exception& e) {
    return Status::InvalidArgument(path + ": not a readable ROS 1 bag (truncated or another "
                                   "format): " + e.what());
  }
  return Status::Ok();
}

// "a, b, c" of the topics, with their types, for error messages.
std::string TopicList(const std::vector<BagTopic>& topics) {
  std::string text;
  for (const auto& t : topics) {
    text += (text.empty() ? "" : ", ") + t.name + " (" + t.type + ")";
  }
  return text.empty() ? "none" : text;
}

// The namespace of a topic: "/a/b/image_raw" -> "/a/b"; a trailing "/compressed" goes first.
std::string TopicNamespace(std::string topic) {
  const std::string compressed = "/compressed";
  if (topic.size() > compressed.size() &&
      topic.compare(topic.size() - compressed.size(), compressed.size(), compressed) == 0) {
    topic.resize(topic.size() - compressed.size());
  }
  const size_t slash = topic.rfind('/');
  return slash == std::string::npos ? "" : topic.substr(0, slash);
}

const BagTopic* FindTopic(const std::vector<BagTopic>& topics, const std::string& name) {
  for (const auto& t : topics) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

Status DecodeCompressed(const std::string& format, const std::vector<uint8_t>& data,
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

}  // namespace

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

bool IsImageTopicType(const std::string& type) {
  return type == kImageType || type == kCompressedType;
}

Status ListBagTopics(const std::string& bag_path, std::vector<BagTopic>* topics) {
  topics->clear();
  rosbag::Bag bag;
  const Status status = OpenForReading(bag_path, &bag);
  if (!status.ok()) return status;
  try {
    rosbag::View view(bag);
    std::map<std::string, BagTopic> by_name;
    for (const rosbag::ConnectionInfo* c : view.getConnections()) {
      BagTopic& t = by_name[c->topic];
      t.name = c->topic;
      t.type = c->datatype;
    }
    for (auto& [name, topic] : by_name) {
      topic.messages = rosbag::View(bag, rosbag::TopicQuery(name)).size();
      topics->push_back(topic);
    }
  } catch (const std::exception& e) {
    return Status::InvalidArgument(bag_path + ": cannot read the bag's index: " + e.what());
  }
  return Status::Ok();
}

Status ChooseBagTopics(const std::string& bag_path, const std::string& requested_image,
                       const std::string& requested_info, std::string* image_topic,
                       std::string* info_topic) {
  std::vector<BagTopic> topics;
  Status status = ListBagTopics(bag_path, &topics);
  if (!status.ok()) return status;
  if (!requested_image.empty()) {
    const BagTopic* t = FindTopic(topics, requested_image);
    if (t == nullptr || !IsImageTopicType(t->type)) {
      return Status::InvalidArgument(bag_path + ": --image_topic=" + requested_image + " is " +
                                     (t == nullptr ? "not in the bag" : "a " + t->type) +
                                     "; its topics: " + TopicList(topics));
    }
    *image_topic = requested_image;
  } else {
    std::vector<std::string> images;
    for (const auto& t : topics) {
      if (IsImageTopicType(t.type)) images.push_back(t.name);
    }
    if (images.size() != 1) {
      return Status::InvalidArgument(
          bag_path + (images.empty() ? ": has no sensor_msgs/Image or CompressedImage topic"
                                     : ": has several image topics; choose one with "
                                       "--image_topic") +
          "; its topics: " + TopicList(topics));
    }
    *image_topic = images.front();
  }
  info_topic->clear();
  if (!requested_info.empty()) {
    const BagTopic* t = FindTopic(topics, requested_info);
    if (t == nullptr || t->type != kCameraInfoType) {
      return Status::InvalidArgument(bag_path + ": --camera_info_topic=" + requested_info + " is " +
                                     (t == nullptr ? "not in the bag" : "a " + t->type) +
                                     "; its topics: " + TopicList(topics));
    }
    *info_topic = requested_info;
    return Status::Ok();
  }
  const BagTopic* beside = FindTopic(topics, TopicNamespace(*image_topic) + "/camera_info");
  if (beside != nullptr && beside->type == kCameraInfoType) {
    *info_topic = beside->name;
    return Status::Ok();
  }
  std::vector<std::string> infos;
  for (const auto& t : topics) {
    if (t.type == kCameraInfoType) infos.push_back(t.name);
  }
  if (infos.size() == 1) *info_topic = infos.front();
  return Status::Ok();
}

Status ReadBagCameraInfo(const std::string& bag_path, const std::string& info_topic,
                         Camera* camera, std::string* frame_id) {
  rosbag::Bag bag;
  const Status status = OpenForReading(bag_path, &bag);
  if (!status.ok()) return status;
  sensor_msgs::CameraInfo::ConstPtr info;
  try {
    rosbag::View view(bag, rosbag::TopicQuery(info_topic));
    for (const rosbag::MessageInstance& m : view) {
      info = m.instantiate<sensor_msgs::CameraInfo>();
      if (info) break;
    }
  } catch (const std::exception& e) {
    return Status::InvalidArgument(bag_path + ": cannot read " + info_topic + ": " + e.what());
  }
  const std::string where = bag_path + " " + info_topic;
  if (!info) return Status::InvalidArgument(where + ": no sensor_msgs/CameraInfo message");
  const bool no_distortion =
      info->D.empty() || std::all_of(info->D.begin(), info->D.end(), [](double d) { return d == 0; });
  if (!no_distortion && info->distortion_model != "plumb_bob") {
    return Status::InvalidArgument(where + ": distortion model '" + info->distortion_model +
                                   "' is not supported (plumb_bob only)");
  }
  if (!no_distortion && info->D.size() != 5) {
    return Status::InvalidArgument(where + ": plumb_bob needs 5 coefficients, D has " +
                                   std::to_string(info->D.size()));
  }
  Camera c;
  c.image_width = static_cast<int>(info->width);
  c.image_height = static_cast<int>(info->height);
  c.fx = info->K[0];
  c.fy = info->K[4];
  c.cx = info->K[2];
  c.cy = info->K[5];
  if (!no_distortion) std::copy(info->D.begin(), info->D.end(), c.distortion.begin());
  std::string why;
  if (!c.CheckIntrinsics(&why)) return Status::InvalidArgument(where + ": " + why);
  *camera = c;
  if (frame_id != nullptr) *frame_id = info->header.frame_id;
  return Status::Ok();
}

Status DecodeRawImage(const std::string& encoding, int width, int height, int step,
                      const uint8_t* data, size_t size, cv::Mat* bgr) {
  static const std::map<std::string, std::pair<int, int>> kTypes = {
      {"rgb8", {CV_8UC3, cv::COLOR_RGB2BGR}},  {"bgr8", {CV_8UC3, -1}},
      {"mono8", {CV_8UC1, cv::COLOR_GRAY2BGR}}, {"bgra8", {CV_8UC4, cv::COLOR_BGRA2BGR}},
      {"rgba8", {CV_8UC4, cv::COLOR_RGBA2BGR}}};
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

struct BagImageReader::Impl {
  std::string path;
  std::string topic;
  rosbag::Bag bag;
  std::unique_ptr<rosbag::View> view;
  rosbag::View::iterator next;
  bool broken = false;
};

BagImageReader::BagImageReader(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
BagImageReader::~BagImageReader() = default;

Status BagImageReader::Open(const std::string& bag_path, const std::string& image_topic,
                            std::unique_ptr<BagImageReader>* reader) {
  auto impl = std::make_unique<Impl>();
  impl->path = bag_path;
  impl->topic = image_topic;
  const Status status = OpenForReading(bag_path, &impl->bag);
  if (!status.ok()) return status;
  try {
    impl->view = std::make_unique<rosbag::View>(impl->bag, rosbag::TopicQuery(image_topic));
    impl->next = impl->view->begin();
  } catch (const std::exception& e) {
    return Status::InvalidArgument(bag_path + ": cannot read " + image_topic + ": " + e.what());
  }
  reader->reset(new BagImageReader(std::move(impl)));
  return Status::Ok();
}

size_t BagImageReader::size() const { return impl_->view->size(); }

bool BagImageReader::Next(BagImage* image) {
  *image = BagImage();
  if (impl_->broken) return false;
  const std::string where = impl_->path + " " + impl_->topic;
  try {
    if (impl_->next == impl_->view->end()) return false;
    const rosbag::MessageInstance& m = *impl_->next;
    image->stamp.sec = m.getTime().sec;  // Replaced by header.stamp below when it is set.
    image->stamp.nsec = m.getTime().nsec;
    if (auto raw = m.instantiate<sensor_msgs::Image>()) {
      if (!raw->header.stamp.isZero()) {
        image->stamp = {raw->header.stamp.sec, raw->header.stamp.nsec};
      }
      image->frame_id = raw->header.frame_id;
      image->status = DecodeRawImage(raw->encoding, static_cast<int>(raw->width),
                                     static_cast<int>(raw->height), static_cast<int>(raw->step),
                                     raw->data.data(), raw->data.size(), &image->bgr);
    } else if (auto compressed = m.instantiate<sensor_msgs::CompressedImage>()) {
      if (!compressed->header.stamp.isZero()) {
        image->stamp = {compressed->header.stamp.sec, compressed->header.stamp.nsec};
      }
      image->frame_id = compressed->header.frame_id;
      image->status = DecodeCompressed(compressed->format, compressed->data, &image->bgr);
    } else {
      image->status = Status::InvalidArgument("a " + m.getDataType() + " message, not an image");
    }
    ++impl_->next;
  } catch (const std::exception& e) {
    // A corrupt chunk: report it on this frame and end the stream (the bag cannot be trusted on).
    impl_->broken = true;
    image->status = Status::InvalidArgument(where + ": corrupt message: " + e.what());
    image->bgr.release();
    return true;
  }
  if (!image->status.ok()) {
    image->status = Status(image->status.code(), where + " at " + image->stamp.ToString() + ": " +
                                                     image->status.message());
    image->bgr.release();
  }
  return true;
}

struct BagDepthWriter::Impl {
  std::string path;
  std::string part_path;
  rosbag::Bag bag;
  bool open = false;
};

BagDepthWriter::BagDepthWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

BagDepthWriter::~BagDepthWriter() {
  if (impl_ && impl_->open) (void)Close();
}

Status BagDepthWriter::Open(const std::string& bag_path, std::unique_ptr<BagDepthWriter>* writer) {
  auto impl = std::make_unique<Impl>();
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
  image.height = static_cast<uint32_t>(depth_m.rows);
  image.width = static_cast<uint32_t>(depth_m.cols);
  image.encoding = "16UC1";
  image.is_bigendian = 0;  // uint16 little-endian, as on every ROS host.
  image.step = image.width * 2;
  const cv::Mat mm = DepthToMillimetres(depth_m);
  image.data.resize(static_cast<size_t>(image.step) * image.height);
  for (int r = 0; r < mm.rows; ++r) {
    const uint16_t* src = mm.ptr<uint16_t>(r);
    uint8_t* dst = image.data.data() + static_cast<size_t>(r) * image.step;
    for (int c = 0; c < mm.cols; ++c) {
      dst[2 * c] = static_cast<uint8_t>(src[c] & 0xFF);
      dst[2 * c + 1] = static_cast<uint8_t>(src[c] >> 8);
    }
  }
  sensor_msgs::CameraInfo info;
  info.header = image.header;
  info.width = image.width;
  info.height = image.height;
  info.distortion_model = "plumb_bob";
  info.D.assign(camera.distortion.begin(), camera.distortion.end());
  info.K = {camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1};
  info.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.P = {camera.fx, 0, camera.cx, 0, 0, camera.fy, camera.cy, 0, 0, 0, 1, 0};
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
