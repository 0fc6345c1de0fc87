#pragma once

#include <memory>
#include <string>
#include <thread>

#include <image_transport/image_transport.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "depth/ray_table.h"
#include "ros/frame_mailbox.h"
#include "ros/frame_processor.h"
#include "ros/node_config.h"
#include "ros/node_stats.h"

namespace corridor {

// The live node: image + camera_info in (image_transport's camera subscriber), depth, its
// camera_info, points, the corridor's markers and geometry out, all relative to the node's
// namespace and on the input's stamp and frame_id. The callback only drops the frame into a
// one-slot mailbox; a worker thread takes the newest frame and processes it, so a slow frame
// never queues others. Nothing a frame holds can stop the node: its problems go to /diagnostics.
class CorridorDepthNode {
 public:
  // `config` from ReadNodeConfig; `processor` created from its options.
  CorridorDepthNode(ros::NodeHandle nh, ros::NodeHandle private_nh, const NodeConfig& config,
                    std::unique_ptr<FrameProcessor> processor);
  ~CorridorDepthNode();

 private:
  struct Input {
    sensor_msgs::ImageConstPtr image;
    sensor_msgs::CameraInfoConstPtr info;
  };

  void OnImage(const sensor_msgs::ImageConstPtr& image,
               const sensor_msgs::CameraInfoConstPtr& info);
  void Work();
  void Process(const Input& input);
  // The frame's camera: the camera_info's intrinsics and the height (parameter or TF).
  Status FrameCamera(const Input& input, Camera* camera);
  // A frame that gives no depth: why, on /diagnostics (bounded rate) and corridor/geometry.
  void Report(const std_msgs::Header& header, const Status& status,
              const RecoverDepthResult* result, const Camera* camera);
  void PublishDiagnostics(const ros::WallTimerEvent& event);

  ros::NodeHandle nh_;
  const NodeConfig config_;
  std::unique_ptr<FrameProcessor> processor_;  // Worker thread only.
  image_transport::ImageTransport transport_;
  image_transport::CameraSubscriber subscriber_;
  image_transport::CameraPublisher depth_publisher_;
  ros::Publisher points_publisher_, markers_publisher_, geometry_publisher_, diagnostics_publisher_;
  ros::WallTimer diagnostics_timer_;
  ros::WallTime last_report_;
  tf2_ros::Buffer tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  NodeStats stats_;
  FrameMailbox<Input> mailbox_;
  // Worker-thread state: the previous frame, to start a new sequence on a jump.
  Camera last_camera_;
  std::string last_frame_id_;
  ros::Time last_stamp_;
  std::unique_ptr<RayTable> rays_;
  std::thread worker_;
};

}  // namespace corridor
