#include "ros/corridor_markers.h"

#include <array>

#include <Eigen/Geometry>

namespace corridor {
namespace {

enum SurfaceId { kFloor = 0,
                 kLeftWall = 1,
                 kRightWall = 2,
                 kCeiling = 3,
                 kEndWall = 4 };

visualization_msgs::Marker BaseMarker(const std_msgs::Header& header, int id) {
  visualization_msgs::Marker marker;
  marker.header = header;
  marker.ns = "corridor";
  marker.id = id;
  marker.type = visualization_msgs::Marker::TRIANGLE_LIST;
  marker.pose.orientation.w = 1.0;
  marker.scale.x = marker.scale.y = marker.scale.z = 1.0;
  return marker;
}

}  // namespace

visualization_msgs::MarkerArray CorridorMarkers(const CorridorGeometry& g, double max_range,
                                                double max_height, const std_msgs::Header& header,
                                                double roll) {
  const Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(g.pitch, Eigen::Vector3d::UnitX()) *
       Eigen::AngleAxisd(g.yaw, Eigen::Vector3d::UnitY()))
          .toRotationMatrix();
  const double h = g.camera_height;
  const double top = g.HasCeiling() ? h - g.ceiling_height : h - max_height;
  const double left = -g.LeftDistance();
  const double right = g.RightDistance();
  const double end = g.HasEndWall() ? g.end_distance : max_range;
  using Quad = std::array<Eigen::Vector3d, 4>;
  const auto add = [&](visualization_msgs::MarkerArray* array, int id, const Quad& quad,
                       float r, float gr, float b) {
    visualization_msgs::Marker marker = BaseMarker(header, id);
    marker.action = visualization_msgs::Marker::ADD;
    marker.color.r = r;
    marker.color.g = gr;
    marker.color.b = b;
    marker.color.a = 0.5f;
    for (int i : {0, 1, 2, 0, 2, 3}) {
      const Eigen::Vector3d p = rotation * quad[static_cast<size_t>(i)];
      geometry_msgs::Point point;
      point.x = p.x();
      point.y = p.y();
      point.z = p.z();
      marker.points.push_back(point);
    }
    array->markers.push_back(marker);
  };
  const auto remove = [&](visualization_msgs::MarkerArray* array, int id) {
    visualization_msgs::Marker marker = BaseMarker(header, id);
    marker.action = visualization_msgs::Marker::DELETE;
    array->markers.push_back(marker);
  };
  visualization_msgs::MarkerArray array;
  add(&array, kFloor, {{{left, h, 0}, {right, h, 0}, {right, h, end}, {left, h, end}}}, 0.3f,
      0.5f, 0.9f);
  add(&array, kLeftWall, {{{left, h, 0}, {left, h, end}, {left, top, end}, {left, top, 0}}},
      0.9f, 0.5f, 0.3f);
  add(&array, kRightWall, {{{right, h, 0}, {right, top, 0}, {right, top, end}, {right, h, end}}},
      0.9f, 0.5f, 0.3f);
  if (g.HasCeiling()) {
    add(&array, kCeiling, {{{left, top, 0}, {left, top, end}, {right, top, end}, {right, top, 0}}},
        0.6f, 0.9f, 0.6f);
  } else {
    remove(&array, kCeiling);
  }
  if (g.HasEndWall()) {
    add(&array, kEndWall, {{{left, h, end}, {right, h, end}, {right, top, end}, {left, top, end}}},
        0.8f, 0.8f, 0.3f);
  } else {
    remove(&array, kEndWall);
  }
  return array;
}

visualization_msgs::MarkerArray ClearCorridorMarkers(const std_msgs::Header& header) {
  visualization_msgs::MarkerArray array;
  visualization_msgs::Marker marker = BaseMarker(header, 0);
  marker.action = visualization_msgs::Marker::DELETEALL;
  array.markers.push_back(marker);
  return array;
}

}  // namespace corridor
