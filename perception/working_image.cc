#include "perception/working_image.h"

#include <opencv2/imgproc.hpp>

namespace corridor {

int WorkingScale(int width, int max_width) {
  int scale = 1;
  for (int w = width; max_width > 0 && w > max_width; w = (w + 1) / 2) scale *= 2;
  return scale;
}

WorkingImage HalveToWidth(const cv::Mat& bgr, const Camera& camera, int max_width) {
  WorkingImage work{bgr, camera, 1};
  const int scale = WorkingScale(bgr.cols, max_width);
  while (work.scale < scale && work.bgr.rows > 1) {
    cv::pyrDown(work.bgr, work.bgr);
    work.scale *= 2;
    Camera& c = work.camera;
    c.image_width = work.bgr.cols;
    c.image_height = work.bgr.rows;
    c.fx *= 0.5;
    c.fy *= 0.5;
    c.cx *= 0.5;
    c.cy *= 0.5;
  }
  return work;
}

}  // namespace corridor
