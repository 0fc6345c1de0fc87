#pragma once

#include <string>

#include <ros/node_handle.h>

#include "corridor_depth/status.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {

// Everything the node reads from its private parameters at start-up.
struct NodeConfig {
  RecoverDepthOptions options;           // ~solver, ~rasterizer, ... (pipeline/option_table.h).
  double camera_height = 0.0;            // ~camera_height: optical centre above the floor, m.
  std::string base_frame;                // ~base_frame: a frame on the floor; height from TF instead.
  double tf_timeout = 0.1;               // ~tf_timeout: wait this long for the transform, s.
  bool sequence = true;                  // ~sequence: frames are one stream (junction track, holds).
  std::string depth_encoding = "32FC1";  // ~depth_encoding: 32FC1 (m, NaN = none) or 16UC1 (mm).
  bool publish_points = false;           // ~publish_points: depth/points as well.
  int points_stride = 2;                 // ~points_stride: every n-th row and column (1 = all).
  double diagnostics_period = 1.0;       // ~diagnostics_period: /diagnostics at most this often, s.
};

// Reads and checks the parameters; InvalidArgument names the bad one.
Status ReadNodeConfig(const ros::NodeHandle& private_nh, NodeConfig* config);

}  // namespace corridor
