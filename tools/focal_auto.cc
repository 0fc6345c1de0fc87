#include "tools/focal_auto.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "corridor_depth/image_io.h"
#include "perception/focal_estimator.h"
#include "tools/frame_source.h"

namespace corridor {

Status EstimateSceneFocal(const InputScene& scene, double fallback_hfov_deg, double* focal_px,
                          std::string* how) {
  std::vector<cv::Mat> images;
  if (scene.kind == InputKind::kImages) {
    const size_t n = scene.frames.size();
    const size_t count = std::min<size_t>(5, n);
    for (size_t k = 0; k < count; ++k) {
      cv::Mat image;
      const size_t index = count > 1 ? k * (n - 1) / (count - 1) : 0;
      if (ReadColorImage(scene.frames[index].rgb_path, &image).ok()) images.push_back(image);
    }
  } else {
    cv::Mat first;
    const Status status = ReadFirstFrame(scene, &first);
    if (!status.ok()) return status;
    images.push_back(first);
  }
  if (images.empty()) return Status::InvalidArgument(scene.name + ": no readable image for --focal=auto");
  std::vector<double> focals;
  FocalEstimate estimate;
  std::string last_reason;
  for (const cv::Mat& image : images) {
    const Status status = EstimateFocal(image, FocalEstimatorOptions(), fallback_hfov_deg, &estimate);
    if (!status.ok()) return Status::InvalidArgument(scene.name + ": --focal=auto: " + status.message());
    if (estimate.from_vanishing_points) {
      focals.push_back(estimate.focal_px);
    } else {
      last_reason = estimate.how;
    }
  }
  char text[200];
  if (focals.empty()) {
    *focal_px = estimate.focal_px;  // The fallback's.
    std::snprintf(text, sizeof(text), "--focal=auto: fx = %.1f px; %s", *focal_px,
                  last_reason.c_str());
  } else {
    std::nth_element(focals.begin(), focals.begin() + focals.size() / 2, focals.end());
    *focal_px = focals[focals.size() / 2];
    std::snprintf(text, sizeof(text),
                  "--focal=auto: fx = %.1f px from vanishing points (median of %zu of %zu frames)",
                  *focal_px, focals.size(), images.size());
  }
  *how = text;
  return Status::Ok();
}

}  // namespace corridor
