#include "perception/floor_texture.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "kernels/edge_scan.h"
#include "perception/line_side_span.h"

namespace corridor {
namespace {

// True when the edge through (u, v) with gradient (gx, gy) runs within the tolerance of
// horizontal, of vertical, or of the direction to the vanishing point.
bool AlongCorridorLine(double gx, double gy, double u, double v, const Eigen::Vector2d& vp,
                       double tan_tolerance, double sin_tolerance) {
  const double ax = std::abs(gx), ay = std::abs(gy);
  if (ax <= tan_tolerance * ay || ay <= tan_tolerance * ax) return true;
  // The edge runs along (-gy, gx); the vanishing point lies along (tx, ty).
  const double tx = vp.x() - u, ty = vp.y() - v;
  const double cross = -gy * ty - gx * tx;
  return std::abs(cross) <= sin_tolerance * std::hypot(gx, gy) * std::hypot(tx, ty);
}

}  // namespace

FloorTexture MeasureFloorTexture(const cv::Mat& dx, const cv::Mat& dy, const GradientGrid& grid,
                                 const Eigen::Vector3d& left, const Eigen::Vector3d& right,
                                 const Eigen::Vector2d& vanishing_point,
                                 const FloorTextureOptions& options) {
  FloorTexture out;
  long strong_pixels = 0, odd_pixels = 0;
  if (dx.type() != CV_16S || dy.type() != CV_16S || dx.size() != dy.size()) return out;
  const double tolerance = options.line_tolerance_deg * M_PI / 180.0;
  const double tan_tolerance = std::tan(tolerance), sin_tolerance = std::sin(tolerance);
  const double margin = options.margin;
  thread_local std::vector<uint8_t> thread_strong;  // Keeps its memory from call to call.
  std::vector<uint8_t>& strong = thread_strong;
  strong.assign(dx.cols, 0);
  for (int j = 0; j < dx.rows; ++j) {
    const double v = grid.first_row + static_cast<double>(grid.scale) * j;
    if (!(v > vanishing_point.y() + margin)) continue;
    double lo = 0, hi = dx.cols;
    KeepLineSide(left, 1.0, v, margin, grid.scale, &lo, &hi);
    KeepLineSide(right, 1.0, v, margin, grid.scale, &lo, &hi);
    if (!(lo < hi)) continue;
    const int begin = static_cast<int>(lo), end = static_cast<int>(hi);
    const short* gx = dx.ptr<short>(j);
    const short* gy = dy.ptr<short>(j);
    const auto visit = [&](int i) {
      ++strong_pixels;
      const double u = static_cast<double>(grid.scale) * i;
      odd_pixels += AlongCorridorLine(gx[i], gy[i], u, v, vanishing_point, tan_tolerance,
                                      sin_tolerance)
                        ? 0
                        : 1;
    };
    int i = begin;
#ifdef __SSE2__
    // Eight pixels a step: |gx| + |gy| (at most 2040, so in 16 bits) against the threshold, and
    // only the strong ones visited, in order.
    if (options.strong <= 32767) {
      const __m128i zero = _mm_setzero_si128();
      const __m128i limit = _mm_set1_epi16(static_cast<short>(options.strong));
      for (; i + 8 <= end; i += 8) {
        const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(gx + i));
        const __m128i y = _mm_loadu_si128(reinterpret_cast<const __m128i*>(gy + i));
        const __m128i sum = _mm_add_epi16(_mm_max_epi16(x, _mm_sub_epi16(zero, x)),
                                          _mm_max_epi16(y, _mm_sub_epi16(zero, y)));
        // One bit per lane (its low byte's) where the sum is not below the threshold.
        int bits = ~_mm_movemask_epi8(_mm_cmplt_epi16(sum, limit)) & 0x5555;
        for (; bits != 0; bits &= bits - 1) visit(i + (__builtin_ctz(bits) >> 1));
      }
    }
#endif
    // The rest (or all): which pixels are strong, in one pass the compiler vectorises; then only
    // those.
    for (int k = i; k < end; ++k) {
      strong[k] = static_cast<uint8_t>(std::abs(gx[k]) + std::abs(gy[k]) >= options.strong);
    }
    ForEachNonZeroByte(strong.data(), i, end, visit);
    out.floor_pixels += end - begin;
  }
  if (out.floor_pixels > 0) {
    out.strong_fraction = static_cast<double>(strong_pixels) / out.floor_pixels;
    out.odd_fraction = static_cast<double>(odd_pixels) / out.floor_pixels;
  }
  return out;
}

}  // namespace corridor
