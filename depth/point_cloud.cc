#include "depth/point_cloud.h"

#include <cmath>
#include <string>

namespace corridor {

Status DepthToPointCloud(const RayTable& rays, const cv::Mat& depth_m, const cv::Mat& bgr,
                         PointCloud* cloud) {
  cloud->xyz.clear();
  cloud->rgb.clear();
  if (depth_m.type() != CV_32FC1 || depth_m.cols != rays.width() ||
      depth_m.rows != rays.height()) {
    return Status::InvalidArgument("point cloud: depth must be 32FC1 of the camera's size " +
                                   std::to_string(rays.width()) + "x" +
                                   std::to_string(rays.height()));
  }
  const bool colour = !bgr.empty();
  if (colour && (bgr.type() != CV_8UC3 || bgr.size() != depth_m.size())) {
    return Status::InvalidArgument(
        "point cloud: the colour image must be 8-bit BGR of the depth's "
        "size");
  }
  const size_t valid = static_cast<size_t>(cv::countNonZero(depth_m > 0));
  cloud->xyz.reserve(3 * valid);
  cloud->rgb.reserve(3 * valid);
  for (int v = 0; v < depth_m.rows; ++v) {
    const float* z = depth_m.ptr<float>(v);
    const float* rx = rays.row_x(v);
    const float* ry = rays.row_y(v);
    const cv::Vec3b* c = colour ? bgr.ptr<cv::Vec3b>(v) : nullptr;
    for (int u = 0; u < depth_m.cols; ++u) {
      if (!(z[u] > 0) || !std::isfinite(z[u])) continue;
      cloud->xyz.insert(cloud->xyz.end(), {z[u] * rx[u], z[u] * ry[u], z[u]});
      if (colour) {
        cloud->rgb.insert(cloud->rgb.end(), {c[u][2], c[u][1], c[u][0]});
      } else {
        cloud->rgb.insert(cloud->rgb.end(), {0, 0, 0});
      }
    }
  }
  return Status::Ok();
}

}  // namespace corridor
