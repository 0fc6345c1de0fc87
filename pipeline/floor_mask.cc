#include "pipeline/floor_mask.h"

#include <cmath>
#include <limits>

#include "corridor_depth/corridor_frame.h"
#include "pipeline/box_surface.h"

namespace corridor {

cv::Mat PredictFloorMask(const Camera& camera, const CorridorGeometry& g, double max_range) {
  const BoxFrame box(g);
  cv::Mat mask(camera.image_height, camera.image_width, CV_8U, cv::Scalar(0));
  for (int v = 0; v < camera.image_height; ++v) {
    uchar* row = mask.ptr<uchar>(v);
    for (int u = 0; u < camera.image_width; ++u) {
      // Floor hidden by a wall or an end wall is not floor in the image.
      const BoxHit hit = FirstBoxSurface(box, RayOfRawPixel(camera, u, v));
      if (hit.surface == BoxSurface::kFloor && hit.z <= max_range) row[u] = 255;
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
