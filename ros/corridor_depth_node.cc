#include "ros/corridor_depth_node.h"

#include <cmath>
#include <exception>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <sensor_msgs/PointCloud2.h>

#include "io/ros_depth_message.h"
#include "io/rosbag_io.h"
#include "ros/camera_info.h"
#include "ros/corridor_markers.h"
#include "ros/depth_points.h"
#include "ros/geometry_message.h"

namespace corridor {
namespace {

std::string StampText(const ros::Time& stamp) {
  BagStamp bag_stamp;
  bag_stamp.sec = stamp.sec;
  bag_stamp.nsec = stamp.nsec;
  return bag_stamp.ToString();
}

bool SameCamera(const Camera& a, const Camera& b) {
  return a.image_width == b.image_width && a.image_height == b.image_height && a.fx == b.fx &&
         a.fy == b.fy && a.cx == b.cx && a.cy == b.cy && a.distortion == b.distortion;
}

}  // namespace

CorridorDepthNode::CorridorDepthNode(ros::NodeHandle nh, ros::NodeHandle private_nh,
                                     const NodeConfig& config,
                                     std::unique_ptr<FrameProcessor> processor)
    : nh_(nh), config_(config), processor_(std::move(processor)), transport_(nh) {
  (void)private_nh;
  if (!config_.base_frame.empty()) {
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(tf_buffer_, nh_);
  }
  depth_publisher_ = transport_.advertiseCamera("depth/image", 1);
  if (config_.publish_points) {
    points_publisher_ = nh_.advertise<sensor_msgs::PointCloud2>("depth/points", 1);
  }
  markers_publisher_ = nh_.advertise<visualization_msgs::MarkerArray>("corridor/markers", 1);
  geometry_publisher_ = nh_.advertise<diagnostic_msgs::DiagnosticStatus>("corridor/geometry", 10);
  diagnostics_publisher_ = nh_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
  last_report_ = ros::WallTime::now();
  diagnostics_timer_ = nh_.createWallTimer(ros::WallDuration(config_.diagnostics_period),
                                           &CorridorDepthNode::PublishDiagnostics, this);
  worker_ = std::thread(&CorridorDepthNode::Work, this);
  // Subscribe last: a frame may arrive at once.
  subscriber_ = transport_.subscribeCamera("image", 1, &CorridorDepthNode::OnImage, this);
}

CorridorDepthNode::~CorridorDepthNode() {
  subscriber_.shutdown();
  mailbox_.Close();
  if (worker_.joinable()) worker_.join();
}

void CorridorDepthNode::OnImage(const sensor_msgs::ImageConstPtr& image,
                                const sensor_msgs::CameraInfoConstPtr& info) {
  stats_.Received(mailbox_.Put(Input{image, info}));
}

void CorridorDepthNode::Work() {
  Input input;
  while (mailbox_.Take(&input)) {
    try {
      Process(input);
    } catch (const std::exception& e) {
      Report(input.image->header, Status::Internal(std::string("exception: ") + e.what()),
             nullptr, nullptr);
    } catch (...) {
      Report(input.image->header, Status::Internal("unknown exception"), nullptr, nullptr);
    }
  }
}

Status CorridorDepthNode::FrameCamera(const Input& input, Camera* camera) {
  const sensor_msgs::Image& image = *input.image;
  Status status = CameraFromInfo(*input.info, static_cast<int>(image.width),
                                 static_cast<int>(image.height), camera);
  if (!status.ok()) return status;
  if (config_.base_frame.empty()) {
    camera->mount_height = config_.camera_height;
    return Status::Ok();
  }
  geometry_msgs::TransformStamped transform;
  try {
    transform = tf_buffer_.lookupTransform(config_.base_frame, image.header.frame_id,
                                           image.header.stamp, ros::Duration(config_.tf_timeout));
  } catch (const std::exception& at_stamp) {
    try {  // A static or slow transform: the latest one.
      transform = tf_buffer_.lookupTransform(config_.base_frame, image.header.frame_id,
                                             ros::Time(0));
    } catch (const std::exception&) {
      return Status::NotFound("no transform from " + config_.base_frame + " to " +
                              image.header.frame_id + " for the camera height: " +
                              at_stamp.what());
    }
  }
  camera->mount_height = transform.transform.translation.z;
  std::string why;
  if (!camera->Check(&why)) {
    return Status::InvalidArgument("camera height from TF (" + config_.base_frame + " -> " +
                                   image.header.frame_id + "): " + why);
  }
  return Status::Ok();
}

void CorridorDepthNode::Process(const Input& input) {
  const std_msgs::Header& header = input.image->header;
  const sensor_msgs::Image& image = *input.image;
  cv::Mat bgr;
  Status status = DecodeRawImage(image.encoding, static_cast<int>(image.width),
                                 static_cast<int>(image.height), static_cast<int>(image.step),
                                 image.data.data(), image.data.size(), &bgr);
  Camera camera;
  if (status.ok()) status = FrameCamera(input, &camera);
  if (!status.ok()) {
    Report(header, status, nullptr, nullptr);
    return;
  }
  // A new stream: another camera, frame or a stamp that went back (a bag played again).
  if (!SameCamera(camera, last_camera_) || header.frame_id != last_frame_id_ ||
      header.stamp < last_stamp_) {
    processor_->Reset();
    rays_.reset();
  }
  last_camera_ = camera;
  last_frame_id_ = header.frame_id;
  last_stamp_ = header.stamp;

  RecoverDepthResult result;
  status = processor_->Process(bgr, camera, &result);
  if (!status.ok() || result.depth.empty()) {
    if (status.ok()) status = Status::Internal("the library returned no depth");
    Report(header, status, &result, &camera);
    return;
  }
  // Depth first: it is what a robot waits for.
  auto depth = boost::make_shared<sensor_msgs::Image>();
  depth->header = header;
  status = FillDepthImage(result.depth, config_.depth_encoding, depth.get());
  if (!status.ok()) {
    Report(header, status, &result, &camera);
    return;
  }
  auto info = boost::make_shared<sensor_msgs::CameraInfo>();
  info->header = header;
  FillCameraInfo(camera, info.get());
  depth_publisher_.publish(depth, info);
  stats_.Published((ros::Time::now() - header.stamp).toSec());
  if (config_.publish_points) {
    if (!rays_ || !rays_->Matches(camera)) rays_ = std::make_unique<RayTable>(camera);
    auto cloud = boost::make_shared<sensor_msgs::PointCloud2>();
    cloud->header = header;
    FillDepthPoints(*rays_, result.depth, config_.points_stride, cloud.get());
    points_publisher_.publish(cloud);
  }
  const RasterizerOptions& raster = processor_->options().rasterizer_options;
  markers_publisher_.publish(
      CorridorMarkers(result.geometry, raster.max_range, raster.max_height, header,
                      result.roll));
  geometry_publisher_.publish(
      GeometryMessage(StampText(header.stamp), header.frame_id, status, &result, &camera));
}

void CorridorDepthNode::Report(const std_msgs::Header& header, const Status& status,
                               const RecoverDepthResult* result, const Camera* camera) {
  const std::string stamp = StampText(header.stamp);
  const char* status_class = StatusClass(status.code());
  stats_.Problem(stamp, status_class, status.ToString());
  ROS_WARN_THROTTLE(config_.diagnostics_period, "frame %s %s: %s", stamp.c_str(), status_class,
                    status.ToString().c_str());
  markers_publisher_.publish(ClearCorridorMarkers(header));
  geometry_publisher_.publish(GeometryMessage(stamp, header.frame_id, status, result, camera));
}

void CorridorDepthNode::PublishDiagnostics(const ros::WallTimerEvent&) {
  const ros::WallTime now = ros::WallTime::now();
  diagnostic_msgs::DiagnosticArray array;
  array.header.stamp = ros::Time::now();
  array.status.push_back(stats_.Report(ros::this_node::getName() + ": depth", "",
                                       (now - last_report_).toSec()));
  last_report_ = now;
  diagnostics_publisher_.publish(array);
}

}  // namespace corridor
