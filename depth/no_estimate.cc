#include "depth/no_estimate.h"

#include <limits>

#ifdef __x86_64__
#include <immintrin.h>
#endif

#include "core/cpu_features.h"

namespace corridor {

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
