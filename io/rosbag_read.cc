#include "io/rosbag_io.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>

#include "io/isolated_child.h"

namespace corridor {
namespace {

namespace fs = std::filesystem;

constexpr char kCameraInfoType[] = "sensor_msgs/CameraInfo";

// Opens a bag for reading; every rosbag exception becomes a status naming the bag.
Status OpenForReading(const std::string& path, rosbag::Bag* bag) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return Status::NotFound(path + ": no such bag file");
  if (fs::is_directory(path, ec)) return Status::InvalidArgument(path + ": is a folder, not a bag");
  try {
    bag->open(path, rosbag::bagmode::Read);
  } catch (const rosbag::BagUnindexedException&) {
    return Status::InvalidArgument(path +
                                   ": the bag is unindexed (truncated or not closed); "
                                   "repair it with `rosbag reindex`");
  } catch (const std::exception& e) {
    return Status::InvalidArgument(path +
                                   ": not a readable ROS 1 bag (truncated or another "
                                   "format): " +
                                   e.what());
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

// Fields packed into a record of the reader child's pipe, and read back: little host-order
// integers and doubles, strings with a 32-bit length.
struct Packer {
  std::string out;
  void U32(uint32_t v) { out.append(reinterpret_cast<const char*>(&v), sizeof(v)); }
  void F64(double v) { out.append(reinterpret_cast<const char*>(&v), sizeof(v)); }
  void Str(const std::string& v) {
    U32(static_cast<uint32_t>(v.size()));
    out += v;
  }
  void Bytes(const void* data, size_t size) {
    U32(static_cast<uint32_t>(size));
    out.append(static_cast<const char*>(data), size);
  }
};

class Unpacker {
 public:
  explicit Unpacker(const std::string& in) : in_(in) {}
  uint32_t U32() { return Take<uint32_t>(); }
  double F64() { return Take<double>(); }
  std::string Str() {
    const uint32_t n = U32();
    if (!ok_ || n > in_.size() - pos_) {
      ok_ = false;
      return "";
    }
    pos_ += n;
    return in_.substr(pos_ - n, n);
  }
  bool ok() const { return ok_; }

 private:
  template <typename T>
  T Take() {
    T v{};
    if (!ok_ || sizeof(T) > in_.size() - pos_) {
      ok_ = false;
      return v;
    }
    std::memcpy(&v, in_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  const std::string& in_;
  size_t pos_ = 0;
  bool ok_ = true;
};

void SendStatus(const Status& status, RecordWriter* out) {
  Packer p;
  p.U32(static_cast<uint32_t>(status.code()));
  p.Str(status.message());
  out->Write('E', p.out);
}

Status ReceiveStatus(Unpacker* u) {
  const uint32_t code = u->U32();
  const std::string message = u->Str();
  if (!u->ok() || code == 0 || code > static_cast<uint32_t>(StatusCode::kInternal)) {
    return Status::Internal("malformed status from the bag reader");
  }
  return Status(static_cast<StatusCode>(code), message);
}

// Kinds of the 'I' records.
constexpr uint32_t kRawImage = 0, kCompressedImage = 1, kOtherMessage = 2;

// In the child: one message of the image topic, deserialised by the ROS library.
std::string PackImage(const rosbag::MessageInstance& m) {
  Packer p;
  if (auto raw = m.instantiate<sensor_msgs::Image>()) {
    const ros::Time t = raw->header.stamp.isZero() ? m.getTime() : raw->header.stamp;
    p.U32(kRawImage);
    p.U32(t.sec);
    p.U32(t.nsec);
    p.Str(raw->header.frame_id);
    p.Str(raw->encoding);
    p.U32(raw->width);
    p.U32(raw->height);
    p.U32(raw->step);
    p.Bytes(raw->data.data(), raw->data.size());
  } else if (auto compressed = m.instantiate<sensor_msgs::CompressedImage>()) {
    const ros::Time t = compressed->header.stamp.isZero() ? m.getTime() : compressed->header.stamp;
    p.U32(kCompressedImage);
    p.U32(t.sec);
    p.U32(t.nsec);
    p.Str(compressed->header.frame_id);
    p.Str(compressed->format);
    p.Bytes(compressed->data.data(), compressed->data.size());
  } else {
    p.U32(kOtherMessage);
    p.U32(m.getTime().sec);
    p.U32(m.getTime().nsec);
    p.Str(m.getDataType());
  }
  return p.out;
}

// In the parent: decodes an 'I' record into image->bgr (OpenCV runs here, not in the child).
Status UnpackImage(Unpacker* u, BagImage* image) {
  const uint32_t kind = u->U32();
  image->stamp.sec = u->U32();
  image->stamp.nsec = u->U32();
  const std::string text = u->Str();
  if (kind == kOtherMessage) {
    return Status::InvalidArgument("a " + text + " message, not an image");
  }
  image->frame_id = text;
  const std::string encoding = u->Str();
  Status status;
  if (kind == kRawImage) {
    const uint32_t width = u->U32(), height = u->U32(), step = u->U32();
    const std::string data = u->Str();
    if (!u->ok() || width > (1u << 16) || height > (1u << 16) || step > (1u << 20)) {
      return Status::InvalidArgument("malformed image message");
    }
    return DecodeRawImage(encoding, static_cast<int>(width), static_cast<int>(height),
                          static_cast<int>(step), reinterpret_cast<const uint8_t*>(data.data()),
                          data.size(), &image->bgr);
  }
  const std::string data = u->Str();
  if (!u->ok()) return Status::InvalidArgument("malformed compressed image message");
  return DecodeCompressedImage(encoding, std::vector<uint8_t>(data.begin(), data.end()), &image->bgr);
}

// Starts a child that opens the bag and runs `read` on it; a bag that does not open, or an
// exception in `read` (prefixed by `what`), goes back as an 'E' record, the end as 'Z'.
Status StartBagChild(const std::string& bag_path, const std::string& what,
                     const std::function<bool(rosbag::Bag&, RecordWriter*)>& read,
                     std::unique_ptr<IsolatedChild>* child) {
  return IsolatedChild::Start(
      [&](RecordWriter* out) {
        rosbag::Bag bag;
        const Status opened = OpenForReading(bag_path, &bag);
        if (!opened.ok()) {
          SendStatus(opened, out);
          return;
        }
        try {
          if (!read(bag, out)) return;
        } catch (const std::exception& e) {
          SendStatus(Status::InvalidArgument(what + e.what()), out);
          return;
        }
        out->Write('Z', "");
      },
      child);
}

}  // namespace

Status ListBagTopics(const std::string& bag_path, std::vector<BagTopic>* topics) {
  topics->clear();
  std::unique_ptr<IsolatedChild> child;
  Status status = StartBagChild(
      bag_path, bag_path + ": cannot read the bag's index: ",
      [&](rosbag::Bag& bag, RecordWriter* out) {
        rosbag::View view(bag);
        std::map<std::string, std::string> types;
        for (const rosbag::ConnectionInfo* c : view.getConnections()) types[c->topic] = c->datatype;
        for (const auto& [name, type] : types) {
          Packer p;
          p.Str(name);
          p.Str(type);
          p.U32(rosbag::View(bag, rosbag::TopicQuery(name)).size());
          out->Write('T', p.out);
        }
        return true;
      },
      &child);
  if (!status.ok()) return status;
  char tag = 0;
  std::string record;
  bool complete = false;
  while (!complete && child->Read(&tag, &record)) {
    Unpacker u(record);
    if (tag == 'E') return ReceiveStatus(&u);
    if (tag == 'Z') complete = true;
    if (tag != 'T') continue;
    BagTopic t;
    t.name = u.Str();
    t.type = u.Str();
    t.messages = u.U32();
    topics->push_back(t);
  }
  status = child->Finish(bag_path +
                         ": the rosbag library crashed reading the bag's index: the "
                         "bag is corrupt");
  if (!status.ok()) return status;
  if (!complete) return Status::InvalidArgument(bag_path + ": the bag's index could not be read");
  return Status::Ok();
}

Status ChooseBagTopics(const std::string& bag_path, const std::string& requested_image,
                       const std::string& requested_info, std::string* image_topic,
                       std::string* info_topic, uint32_t* image_messages) {
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
          bag_path + (images.empty() ? ": has no sensor_msgs/Image or CompressedImage topic" : ": has several image topics; choose one with "
                                                                                               "--image_topic") +
          "; its topics: " + TopicList(topics));
    }
    *image_topic = images.front();
  }
  if (image_messages != nullptr) *image_messages = FindTopic(topics, *image_topic)->messages;
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
  std::unique_ptr<IsolatedChild> child;
  Status status = StartBagChild(
      bag_path, bag_path + ": cannot read " + info_topic + ": ",
      [&](rosbag::Bag& bag, RecordWriter* out) {
        for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(info_topic))) {
          const auto info = m.instantiate<sensor_msgs::CameraInfo>();
          if (!info) continue;
          Packer p;
          p.U32(info->width);
          p.U32(info->height);
          for (double k : info->K) p.F64(k);
          p.U32(static_cast<uint32_t>(info->D.size()));
          for (double d : info->D) p.F64(d);
          p.Str(info->distortion_model);
          p.Str(info->header.frame_id);
          out->Write('C', p.out);
          break;
        }
        return true;
      },
      &child);
  if (!status.ok()) return status;
  const std::string where = bag_path + " " + info_topic;
  char tag = 0;
  std::string record;
  bool found = false;
  Camera c;
  std::string model, id;
  std::vector<double> distortion;
  while (child->Read(&tag, &record)) {
    Unpacker u(record);
    if (tag == 'E') return ReceiveStatus(&u);
    if (tag != 'C') continue;
    found = true;
    c.image_width = static_cast<int>(u.U32());
    c.image_height = static_cast<int>(u.U32());
    double k[9];
    for (double& v : k) v = u.F64();
    c.fx = k[0];
    c.fy = k[4];
    c.cx = k[2];
    c.cy = k[5];
    const uint32_t n = u.U32();
    for (uint32_t i = 0; i < n && u.ok(); ++i) distortion.push_back(u.F64());
    model = u.Str();
    id = u.Str();
    if (!u.ok()) return Status::InvalidArgument(where + ": malformed CameraInfo");
  }
  status = child->Finish(where +
                         ": the rosbag library crashed reading the CameraInfo: the bag "
                         "is corrupt");
  if (!status.ok()) return status;
  if (!found) return Status::InvalidArgument(where + ": no sensor_msgs/CameraInfo message");
  const bool no_distortion = std::all_of(distortion.begin(), distortion.end(),
                                         [](double d) { return d == 0; });
  if (!no_distortion && model != "plumb_bob") {
    return Status::InvalidArgument(where + ": distortion model '" + model +
                                   "' is not supported (plumb_bob only)");
  }
  if (!no_distortion && distortion.size() != 5) {
    return Status::InvalidArgument(where + ": plumb_bob needs 5 coefficients, D has " +
                                   std::to_string(distortion.size()));
  }
  if (!no_distortion) std::copy(distortion.begin(), distortion.end(), c.distortion.begin());
  std::string why;
  if (!c.CheckIntrinsics(&why)) return Status::InvalidArgument(where + ": " + why);
  *camera = c;
  if (frame_id != nullptr) *frame_id = id;
  return Status::Ok();
}

struct BagImageReader::Impl {
  std::string path;
  std::string topic;
  std::unique_ptr<IsolatedChild> child;
  BagStamp last;       // The last message's stamp, for messages about what follows it.
  bool ended = false;  // The stream is over (its end, an error, or a crash already reported).
};

BagImageReader::BagImageReader(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
BagImageReader::~BagImageReader() = default;

Status BagImageReader::Open(const std::string& bag_path, const std::string& image_topic,
                            std::unique_ptr<BagImageReader>* reader) {
  auto impl = std::make_unique<Impl>();
  impl->path = bag_path;
  impl->topic = image_topic;
  // The child opens the bag, says whether it could ('O' or 'E'), then sends every message of the
  // topic as an 'I' record, and 'Z' at the end (or 'E' when a message cannot be read).
  Status status = StartBagChild(
      bag_path, bag_path + " " + image_topic + ": corrupt message: ",
      [&](rosbag::Bag& bag, RecordWriter* out) {
        rosbag::View view(bag, rosbag::TopicQuery(image_topic));
        if (!out->Write('O', "")) return false;
        for (const rosbag::MessageInstance& m : view) {
          if (!out->Write('I', PackImage(m))) return false;
        }
        return true;
      },
      &impl->child);
  if (!status.ok()) return status;
  char tag = 0;
  std::string record;
  if (!impl->child->Read(&tag, &record)) {
    status = impl->child->Finish(bag_path +
                                 ": the rosbag library crashed opening the bag: the "
                                 "bag is corrupt");
    return status.ok() ? Status::InvalidArgument(bag_path + ": the bag could not be read") : status;
  }
  if (tag == 'E') {
    Unpacker u(record);
    return ReceiveStatus(&u);
  }
  reader->reset(new BagImageReader(std::move(impl)));
  return Status::Ok();
}

bool BagImageReader::Next(BagImage* image) {
  *image = BagImage();
  if (impl_->ended) return false;
  const std::string where = impl_->path + " " + impl_->topic;
  char tag = 0;
  std::string record;
  if (!impl_->child->Read(&tag, &record)) {
    // The child died before saying the stream ended: report it on one last frame.
    impl_->ended = true;
    const bool first = impl_->last.sec == 0 && impl_->last.nsec == 0;
    const Status crashed = impl_->child->Finish(
        where + ": the rosbag library crashed reading the " +
        (first ? std::string("first message") : "message after " + impl_->last.ToString()) +
        ": the bag is corrupt there");
    if (crashed.ok()) return false;
    image->stamp = impl_->last;
    image->status = crashed;
    return true;
  }
  Unpacker u(record);
  if (tag == 'Z') {
    impl_->ended = true;
    return false;
  }
  if (tag == 'E') {
    impl_->ended = true;
    image->stamp = impl_->last;
    image->status = ReceiveStatus(&u);
    return true;
  }
  image->status = UnpackImage(&u, image);
  impl_->last = image->stamp;
  if (!image->status.ok()) {
    image->status = Status(image->status.code(), where + " at " + image->stamp.ToString() + ": " +
                                                     image->status.message());
    image->bgr.release();
  }
  return true;
}

}  // namespace corridor
