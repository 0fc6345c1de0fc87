#include "ros/node_config.h"

#include "io/ros_depth_message.h"
#include "pipeline/option_table.h"

namespace corridor {
namespace {

// Reads each option from ~name, its default the field's value.
class ParamVisitor : public OptionVisitor {
 public:
  explicit ParamVisitor(const ros::NodeHandle& nh) : nh_(nh) {}
  void String(const char* name, std::string* field) override { nh_.param(name, *field, *field); }
  void Double(const char* name, double* field) override { nh_.param(name, *field, *field); }
  void Int(const char* name, int* field) override { nh_.param(name, *field, *field); }
  void Bool(const char* name, bool* field) override { nh_.param(name, *field, *field); }

 private:
  const ros::NodeHandle& nh_;
};

}  // namespace

Status ReadNodeConfig(const ros::NodeHandle& nh, NodeConfig* config) {
  *config = NodeConfig();
  ParamVisitor visitor(nh);
  VisitRecoverDepthOptions(&config->options, &visitor);
  nh.param("camera_height", config->camera_height, config->camera_height);
  nh.param("base_frame", config->base_frame, config->base_frame);
  nh.param("tf_timeout", config->tf_timeout, config->tf_timeout);
  nh.param("sequence", config->sequence, config->sequence);
  nh.param("depth_encoding", config->depth_encoding, config->depth_encoding);
  nh.param("publish_points", config->publish_points, config->publish_points);
  nh.param("points_stride", config->points_stride, config->points_stride);
  nh.param("diagnostics_period", config->diagnostics_period, config->diagnostics_period);
  if (config->base_frame.empty() && !(config->camera_height > 0)) {
    return Status::InvalidArgument(
        "set ~camera_height (m, > 0) or ~base_frame (a frame on the floor, for TF)");
  }
  if (!IsDepthEncoding(config->depth_encoding)) {
    return Status::InvalidArgument("~depth_encoding must be 32FC1 or 16UC1, not '" +
                                   config->depth_encoding + "'");
  }
  if (config->points_stride < 1) return Status::InvalidArgument("~points_stride must be >= 1");
  if (!(config->diagnostics_period > 0)) {
    return Status::InvalidArgument("~diagnostics_period must be positive");
  }
  if (!(config->tf_timeout >= 0)) return Status::InvalidArgument("~tf_timeout must be >= 0");
  std::unique_ptr<DepthRecoverer> probe;
  return DepthRecoverer::Create(config->options, &probe);
}

}  // namespace corridor
