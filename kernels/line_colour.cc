#include "kernels/line_colour.h"

#include <algorithm>
#include <limits>

#include <immintrin.h>

#include "core/cpu_features.h"
#include "core/round_half_away.h"

namespace corridor {
namespace {

// The pixel nearest (x, y) of the image, clamped into the roi, added to sum[0..2].
inline void AddPixel(const cv::Mat& roi, int roi_top, int u, int v, int* sum) {
  u = std::clamp(u, 0, roi.cols - 1);
  v = std::clamp(v - roi_top, 0, roi.rows - 1);
  const uchar* p = roi.ptr<uchar>(v) + 3 * u;
  sum[0] += p[0];
  sum[1] += p[1];
  sum[2] += p[2];
}

void SumScalar(const cv::Mat& roi, int roi_top, double x0, double y0, double dx, double dy,
               const double* radii, int from, int count, int* sum) {
  for (int i = from; i < count; ++i) {
    const double r = radii[i];
    AddPixel(roi, roi_top, RoundHalfAway(x0 + r * dx), RoundHalfAway(y0 + r * dy), sum);
  }
}

// RoundHalfAway of four coordinates: truncated, then one step away from zero when the rest is at
// least a half; -1 beyond 1e9 or not a number. Multiplications and additions stay separate (no
// fused multiply-add), as in the scalar code, so that the coordinates are the same doubles.
__attribute__((target("avx2"))) inline __m128i RoundHalfAway4(__m256d x) {
  const __m256d abs_mask = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffffLL));
  const __m256d valid = _mm256_cmp_pd(_mm256_and_pd(x, abs_mask), _mm256_set1_pd(1e9), _CMP_LT_OQ);
  const __m256d t = _mm256_round_pd(x, _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC);
  const __m256d rest = _mm256_sub_pd(x, t);
  const __m256d up = _mm256_and_pd(_mm256_cmp_pd(rest, _mm256_set1_pd(0.5), _CMP_GE_OQ),
                                   _mm256_set1_pd(1.0));
  const __m256d down = _mm256_and_pd(_mm256_cmp_pd(rest, _mm256_set1_pd(-0.5), _CMP_LE_OQ),
                                     _mm256_set1_pd(1.0));
  const __m256d rounded = _mm256_sub_pd(_mm256_add_pd(t, up), down);
  const __m256d out = _mm256_blendv_pd(_mm256_set1_pd(-1.0), rounded, valid);
  return _mm256_cvtpd_epi32(out);  // Whole numbers within int's range: exact.
}

// Four points at a time: their coordinates rounded and clamped in the lanes, each pixel's first
// 32 bits gathered (its three bytes and the next one's first) and its channels added in 32-bit
// lanes. Integer sums, so the order of the additions changes nothing. A group whose 32-bit read
// would pass the roi's last byte is added pixel by pixel. Returns how many points it did.
__attribute__((target("avx2"))) int SumAvx2(const cv::Mat& roi, int roi_top, double x0, double y0,
                                            double dx, double dy, const double* radii, int count,
                                            int* sum) {
  // Offsets in 32-bit lanes: larger rois are left to the scalar loop.
  if (roi.dataend - roi.data > std::numeric_limits<int>::max()) return 0;
  const __m256d vx0 = _mm256_set1_pd(x0), vy0 = _mm256_set1_pd(y0);
  const __m256d vdx = _mm256_set1_pd(dx), vdy = _mm256_set1_pd(dy);
  const __m128i top = _mm_set1_epi32(roi_top), zero = _mm_setzero_si128();
  const __m128i max_u = _mm_set1_epi32(roi.cols - 1), max_v = _mm_set1_epi32(roi.rows - 1);
  const __m128i step = _mm_set1_epi32(static_cast<int>(roi.step[0]));
  const __m128i three = _mm_set1_epi32(3), byte = _mm_set1_epi32(0xff);
  // The largest offset whose four bytes lie within the roi's data.
  const __m128i last = _mm_set1_epi32(static_cast<int>(roi.dataend - roi.data) - 4);
  const int* base = reinterpret_cast<const int*>(roi.data);
  __m128i b = zero, g = zero, r = zero;
  int i = 0;
  for (; i + 4 <= count; i += 4) {
    const __m256d radius = _mm256_loadu_pd(radii + i);
    const __m128i us = RoundHalfAway4(_mm256_add_pd(vx0, _mm256_mul_pd(radius, vdx)));
    const __m128i vs = RoundHalfAway4(_mm256_add_pd(vy0, _mm256_mul_pd(radius, vdy)));
    const __m128i u = _mm_min_epi32(_mm_max_epi32(us, zero), max_u);
    const __m128i v = _mm_min_epi32(_mm_max_epi32(_mm_sub_epi32(vs, top), zero), max_v);
    const __m128i offset = _mm_add_epi32(_mm_mullo_epi32(v, step), _mm_mullo_epi32(u, three));
    if (_mm_movemask_epi8(_mm_cmpgt_epi32(offset, last)) != 0) {
      alignas(16) int ua[4], va[4];
      _mm_store_si128(reinterpret_cast<__m128i*>(ua), us);
      _mm_store_si128(reinterpret_cast<__m128i*>(va), vs);
      for (int k = 0; k < 4; ++k) AddPixel(roi, roi_top, ua[k], va[k], sum);
      continue;
    }
    const __m128i pixels = _mm_i32gather_epi32(base, offset, 1);
    b = _mm_add_epi32(b, _mm_and_si128(pixels, byte));
    g = _mm_add_epi32(g, _mm_and_si128(_mm_srli_epi32(pixels, 8), byte));
    r = _mm_add_epi32(r, _mm_and_si128(_mm_srli_epi32(pixels, 16), byte));
  }
  // The lanes' totals.
  const __m128i bg = _mm_hadd_epi32(b, g), rr = _mm_hadd_epi32(r, r);
  const __m128i totals = _mm_hadd_epi32(bg, rr);  // b, g, r, r.
  sum[0] += _mm_cvtsi128_si32(totals);
  sum[1] += _mm_extract_epi32(totals, 1);
  sum[2] += _mm_extract_epi32(totals, 2);
  return i;
}

}  // namespace

cv::Vec3d MeanColourAtRadii(const cv::Mat& roi, int roi_top, double x0, double y0, double dx,
                            double dy, const double* radii, int count) {
  int sum[3] = {0, 0, 0};
  const int done = CpuHasAvx2() ? SumAvx2(roi, roi_top, x0, y0, dx, dy, radii, count, sum) : 0;
  SumScalar(roi, roi_top, x0, y0, dx, dy, radii, done, count, sum);
  // Whole numbers below 2^53: the sums are those of doubles added in order.
  return cv::Vec3d(sum[0], sum[1], sum[2]) / static_cast<double>(count);
}

}  // namespace corridor
