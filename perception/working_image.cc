#include "perception/working_image.h"

#include <opencv2/imgproc.hpp>

namespace corridor {

WorkingImage HalveToWidth(const cv::Mat& bgr, const Camera& camera, int max_width) {
  WorkingImage work{bgr, camera, 1};
  while (max_width > 0 && work.bgr.cols > max_width && work.bgr.rows > 1) {
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
