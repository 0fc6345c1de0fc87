#include "ros/depth_points.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace corridor {

void FillDepthPoints(const RayTable& rays, const cv::Mat& depth_m, int stride,
                     sensor_msgs::PointCloud2* cloud) {
  const int step = std::max(1, stride);
  cloud->height = static_cast<uint32_t>((depth_m.rows + step - 1) / step);
  cloud->width = static_cast<uint32_t>((depth_m.cols + step - 1) / step);
  cloud->fields.resize(3);
  const char* names[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    cloud->fields[i].name = names[i];
    cloud->fields[i].offset = static_cast<uint32_t>(4 * i);
    cloud->fields[i].datatype = sensor_msgs::PointField::FLOAT32;
    cloud->fields[i].count = 1;
  }
  cloud->is_bigendian = false;
  cloud->point_step = 12;
  cloud->row_step = cloud->point_step * cloud->width;
  cloud->data.resize(static_cast<size_t>(cloud->row_step) * cloud->height);
  cloud->is_dense = true;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  uint8_t* out = cloud->data.data();
  for (int v = 0; v < depth_m.rows; v += step) {
    const float* depth = depth_m.ptr<float>(v);
    const float* rx = rays.row_x(v);
    const float* ry = rays.row_y(v);
    for (int u = 0; u < depth_m.cols; u += step) {
      const float z = depth[u];
      float p[3] = {nan, nan, nan};
      if (std::isfinite(z) && z > 0) {
        p[0] = z * rx[u];
        p[1] = z * ry[u];
        p[2] = z;
      } else {
        cloud->is_dense = false;
      }
      std::memcpy(out, p, sizeof(p));
      out += sizeof(p);
    }
  }
}

}  // namespace corridor
