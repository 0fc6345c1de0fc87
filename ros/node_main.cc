// corridor_depth_node: live dense depth from a corridor camera (see ros/README.md).
//   corridor_depth_node image:=/my_camera/image_raw _camera_height:=0.6
// Exits 2 on a bad parameter; a bad frame never stops it.

#include <ros/ros.h>

#include "ros/corridor_depth_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "corridor_depth");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  corridor::NodeConfig config;
  corridor::Status status = corridor::ReadNodeConfig(private_nh, &config);
  std::unique_ptr<corridor::FrameProcessor> processor;
  if (status.ok()) {
    status = corridor::FrameProcessor::Create(config.options, config.sequence, &processor);
  }
  if (!status.ok()) {
    ROS_FATAL("corridor_depth_node: %s", status.message().c_str());
    return 2;
  }
  corridor::CorridorDepthNode node(nh, private_nh, config, std::move(processor));
  ros::spin();
  return 0;
}
