#include "pipeline/image_input.h"

#include <limits>
#include <mutex>
#include <sstream>
#include <string>

#include <opencv2/imgproc.hpp>

#ifdef __x86_64__
#include <immintrin.h>
#endif

#include "core/cpu_features.h"

namespace corridor {

Status ToBgr(const cv::Mat& image, const Camera& camera, cv::Mat* bgr) {
  if (image.empty()) return Status::InvalidArgument("image is empty");
  if (image.cols != camera.image_width || image.rows != camera.image_height) {
    std::ostringstream msg;
    msg << "image is " << image.cols << "x" << image.rows << " but the calibration is for "
        << camera.image_width << "x" << camera.image_height;
    return Status::InvalidArgument(msg.str());
  }
  cv::Mat eight_bit = image;
  if (image.depth() == CV_16U) {
    image.convertTo(eight_bit, CV_8U, 1.0 / 257.0);  // 65535 -> 255, as ReadColorImage does.
  } else if (image.depth() != CV_8U) {
    return Status::InvalidArgument("image must be 8- or 16-bit unsigned, but it is " +
                                   cv::typeToString(image.type()));
  }
  if (eight_bit.channels() == 3) {
    *bgr = eight_bit;
  } else if (eight_bit.channels() == 1) {
    cv::cvtColor(eight_bit, *bgr, cv::COLOR_GRAY2BGR);
  } else if (eight_bit.channels() == 2) {  // Grey + alpha: keep the grey.
    cv::Mat grey;
    cv::extractChannel(eight_bit, grey, 0);
    cv::cvtColor(grey, *bgr, cv::COLOR_GRAY2BGR);
  } else if (eight_bit.channels() == 4) {
    cv::cvtColor(eight_bit, *bgr, cv::COLOR_BGRA2BGR);
  } else {
    return Status::InvalidArgument("image must have 1, 2, 3 or 4 channels, but it has " +
                                   std::to_string(eight_bit.channels()));
  }
  return Status::Ok();
}

// OpenCV 4.6 builds its BGR->Lab tables lazily and without a lock (color_lab.cpp, initLabTabs):
// two threads converting their first image at once both build them, and one copy leaks (found by
// LeakSanitizer in corridor_eval --threads=2). Building them once, before any Recover, keeps
// concurrent Recover calls clean. (Perception converts to Lab: the junction detector's floor
// appearance.)
void BuildOpenCvTablesOnce() {
  static std::once_flag once;
  std::call_once(once, [] {
    cv::Mat lab;
    cv::cvtColor(cv::Mat(1, 1, CV_8UC3, cv::Scalar::all(128)), lab, cv::COLOR_BGR2Lab);
  });
}

// NaN, which depth_image_proc and point-cloud code read as no point (0 would be a point at the
// origin).
namespace {

#ifdef CORRIDOR_AVX2_VARIANTS
// Eight pixels at a time, four times a step: the same comparison (false for NaN) selecting the
// pixel or NaN.
__attribute__((target("avx2"))) int MarkRowAvx2(float* row, int cols) {
  const __m256 zero = _mm256_setzero_ps();
  const __m256 nan = _mm256_set1_ps(std::numeric_limits<float>::quiet_NaN());
  int u = 0;
  for (; u + 32 <= cols; u += 32) {
    for (int k = 0; k < 32; k += 8) {
      const __m256 x = _mm256_loadu_ps(row + u + k);
      _mm256_storeu_ps(row + u + k, _mm256_blendv_ps(nan, x, _mm256_cmp_ps(x, zero, _CMP_GT_OQ)));
    }
  }
  for (; u + 8 <= cols; u += 8) {
    const __m256 x = _mm256_loadu_ps(row + u);
    _mm256_storeu_ps(row + u, _mm256_blendv_ps(nan, x, _mm256_cmp_ps(x, zero, _CMP_GT_OQ)));
  }
  return u;
}
#endif

}  // namespace

void MarkNoEstimateNaN(cv::Mat* depth) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  int rows = depth->rows, cols = depth->cols;
  if (depth->isContinuous()) cols *= rows, rows = 1;
#ifdef CORRIDOR_AVX2_VARIANTS
  const bool avx2 = CpuHasAvx2();
#endif
  for (int v = 0; v < rows; ++v) {
    float* row = depth->ptr<float>(v);
    int u = 0;
#ifdef CORRIDOR_AVX2_VARIANTS
    if (avx2) u = MarkRowAvx2(row, cols);
#endif
    for (; u < cols; ++u) row[u] = row[u] > 0 ? row[u] : nan;
  }
}

}  // namespace corridor
