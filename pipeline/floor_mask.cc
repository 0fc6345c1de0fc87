#include "pipeline/floor_mask.h"

#include <cmath>
#include <limits>

#include "core/corridor_frame.h"

namespace corridor {

cv::Mat PredictFloorMask(const Camera& camera, const CorridorGeometry& g, double max_range) {
  const CorridorRotation<double> r(g.pitch, g.yaw);
  const Vec3<double> n = r.FloorNormal(), m = r.WallNormal(), d = r.Axis();
  cv::Mat mask(camera.image_height, camera.image_width, CV_8U, cv::Scalar(0));
  for (int v = 0; v < camera.image_height; ++v) {
    uchar* row = mask.ptr<uchar>(v);
    for (int u = 0; u < camera.image_width; ++u) {
      const Vec3<double> ray = RayOfRawPixel(camera, u, v);
      const double nr = Dot(n, ray), mr = Dot(m, ray);
      if (nr <= 0) continue;
      const double z_floor = g.camera_height / nr;
      const double z_wall = mr < 0   ? -g.LeftDistance() / mr
                            : mr > 0 ? g.RightDistance() / mr
                                     : std::numeric_limits<double>::infinity();
      // Floor beyond an end wall is hidden by it: its Z_W, z (d.r), is past the wall's.
      const bool hidden = g.HasEndWall() && z_floor * Dot(d, ray) > g.end_distance;
      if (z_floor < z_wall && z_floor <= max_range && !hidden) row[u] = 255;
    }
  }
  return mask;
}

double MaskIoU(const cv::Mat& a, const cv::Mat& b) {
  const cv::Mat sa = a > 127, sb = b > 127;
  const double inter = cv::countNonZero(sa & sb), uni = cv::countNonZero(sa | sb);
  return uni > 0 ? inter / uni : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace corridor
