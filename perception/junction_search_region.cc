#include "perception/junction_search_region.h"

#include <algorithm>

#include "kernels/edge_scan.h"
#include "perception/working_image.h"

namespace corridor {

Status MakeJunctionSearchRegion(const cv::Mat& color, const cv::Mat* halved, int roi_top,
                                int max_work_width, JunctionSearchRegion* region) {
  const int width = color.cols, height = color.rows;
  const int scale = WorkingScale(width, max_work_width);
  int crop_top = scale == 1 ? 0 : std::max(0, roi_top - 4 * scale) / scale * scale;
  cv::Mat work = color.rowRange(crop_top, height);
  if (halved != nullptr) {
    // The caller's image must be the whole image halved `scale` times over (itself at scale 1).
    cv::Size size(width, height);
    for (int s = 1; s < scale; s *= 2) size = cv::Size((size.width + 1) / 2, (size.height + 1) / 2);
    if (halved->size() != size || halved->type() != CV_8UC3) {
      return Status::InvalidArgument(
          "junction detector: the halved image is not the image's "
          "pyrDown to max_work_width");
    }
  }
  if (halved != nullptr && scale > 1) {
    crop_top = 0;
    work = *halved;
  } else {
    for (int s = 1; s < scale; s *= 2) PyrDown(work, &work);
  }
  region->roi_top = roi_top;
  region->scale = scale;
  region->crop_top = crop_top;
  region->work_roi_top = roi_top / scale - crop_top / scale;
  region->work = work;
  return Status::Ok();
}

void SegmentsToImage(const JunctionSearchRegion& region, std::vector<cv::Vec4f>* segments) {
  for (cv::Vec4f& segment : *segments) {
    for (int k = 0; k < 4; ++k) {
      segment[k] =
          static_cast<float>(region.scale * segment[k] + (k % 2 == 1 ? region.crop_top : 0));
    }
  }
}

GradientGrid SearchRegionGrid(const JunctionSearchRegion& region) {
  return {region.scale, region.crop_top + region.scale * region.work_roi_top};
}

std::vector<Eigen::Vector2d> EdgePixelsInImage(const JunctionSearchRegion& region,
                                               const cv::Mat& edges) {
  std::vector<Eigen::Vector2d> points;
  EdgePixelsInImage(region, edges, &points);
  return points;
}

void EdgePixelsInImage(const JunctionSearchRegion& region, const cv::Mat& edges,
                       std::vector<Eigen::Vector2d>* points) {
  // Sized once (Eigen's vectors are not initialised), then written through a pointer.
  points->resize(static_cast<size_t>(cv::countNonZero(edges)));
  Eigen::Vector2d* next = points->data();
  const int scale = region.scale, row0 = region.work_roi_top, crop_top = region.crop_top;
  ForEachEdgePixel(edges, [&](int u, int v) {
    *next++ = Eigen::Vector2d(scale * u, scale * (v + row0) + crop_top);
  });
}

}  // namespace corridor
