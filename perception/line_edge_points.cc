#include "perception/line_edge_points.h"

#include <algorithm>
#include <cmath>

#include "core/cpu_features.h"

#ifdef CORRIDOR_AVX2_VARIANTS
#include <immintrin.h>
#endif

namespace corridor {
namespace {

// The gradient across the line at each cell k = 3 i + c of a run (pixel i, channel c) from
// `from` to `cells`: |n_along along + n_across across|, along the derivative of `smooth` (cells
// k and k + 6: the pixels either side) and across `step` smoothed 1 2 1 (cells k, k + 3, k + 6).
void CellGradients(const int* sm, const int* st, int from, int cells, double n_along,
                   double n_across, double* g) {
  for (int k = from; k < cells; ++k) {
    const int along = sm[k + 6] - sm[k];
    const int across = st[k] + 2 * st[k + 3] + st[k + 6];
    g[k] = std::abs(n_along * along + n_across * across);
  }
}

#ifdef CORRIDOR_AVX2_VARIANTS
// CellGradients four cells a step, operation for operation (no FMA), so both give the same values.
__attribute__((target("avx2"))) void CellGradientsAvx2(const int* sm, const int* st, int cells,
                                                       double n_along, double n_across,
                                                       double* g) {
  const __m256d va = _mm256_set1_pd(n_along), vc = _mm256_set1_pd(n_across);
  const __m256d sign = _mm256_set1_pd(-0.0);
  const auto load = [](const int* p) {
    return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
  };
  int k = 0;
  for (; k + 4 <= cells; k += 4) {
    const __m128i along = _mm_sub_epi32(load(sm + k + 6), load(sm + k));
    const __m128i mid = load(st + k + 3);
    const __m128i across =
        _mm_add_epi32(_mm_add_epi32(load(st + k), _mm_add_epi32(mid, mid)), load(st + k + 6));
    const __m256d d = _mm256_add_pd(_mm256_mul_pd(va, _mm256_cvtepi32_pd(along)),
                                    _mm256_mul_pd(vc, _mm256_cvtepi32_pd(across)));
    _mm256_storeu_pd(g + k, _mm256_andnot_pd(sign, d));
  }
  CellGradients(sm, st, k, cells, n_along, n_across, g);
}
#endif

// The colour gradient across the line of unit normal n at `count` pixels in a row from (u0, v)
// (by_rows) or in a column from (k, v0) (!by_rows), all at least one pixel inside the image:
// |n . (dx, dy)| of the 3x3 Sobel, the strongest of the three channels, into m[0..count). The
// Sobel's sums across the run are shared between neighbours: `smooth` (1 2 1 across the run) and
// `step` (the difference across it), one per pixel and channel of the run and its two ends;
// `cell_gradients` gets each channel's gradient.
void GradientsAcross(const cv::Mat& bgr, bool by_rows, int major, int first, int count,
                     const Eigen::Vector2d& n, std::vector<int>* smooth, std::vector<int>* step,
                     std::vector<double>* cell_gradients, double* m) {
  const int cells = 3 * (count + 2);
  smooth->resize(cells);
  step->resize(cells);
  int* sm = smooth->data();
  int* st = step->data();
  if (by_rows) {
    // The run and its two ends are contiguous in the three rows around it.
    const uchar* before = bgr.ptr<uchar>(major - 1) + 3 * (first - 1);
    const uchar* mid = bgr.ptr<uchar>(major) + 3 * (first - 1);
    const uchar* after = bgr.ptr<uchar>(major + 1) + 3 * (first - 1);
    for (int k = 0; k < cells; ++k) {
      sm[k] = before[k] + 2 * mid[k] + after[k];
      st[k] = after[k] - before[k];
    }
  } else {
    // Pixel i of the run lies in row first - 1 + i, its neighbours across in columns major -+ 1.
    for (int i = 0; i < count + 2; ++i) {
      const uchar* p = bgr.ptr<uchar>(first - 1 + i) + 3 * (major - 1);
      for (int c = 0; c < 3; ++c) {
        sm[3 * i + c] = p[c] + 2 * p[3 + c] + p[6 + c];
        st[3 * i + c] = p[6 + c] - p[c];
      }
    }
  }
  // Along the run: the derivative of `smooth`; across it: `step` smoothed (1 2 1).
  const double n_along = by_rows ? n.x() : n.y(), n_across = by_rows ? n.y() : n.x();
  cell_gradients->resize(3 * count);
  double* g = cell_gradients->data();
#ifdef CORRIDOR_AVX2_VARIANTS
  static const bool avx2 = CpuHasAvx2();
  if (avx2) {
    CellGradientsAvx2(sm, st, 3 * count, n_along, n_across, g);
  } else {
    CellGradients(sm, st, 0, 3 * count, n_along, n_across, g);
  }
#else
  CellGradients(sm, st, 0, 3 * count, n_along, n_across, g);
#endif
  for (int i = 0; i < count; ++i) {
    double best = 0;
    for (int c = 0; c < 3; ++c) best = std::max(best, g[3 * i + c]);
    m[i] = best;
  }
}

}  // namespace

int EdgePeaksAlong(const cv::Mat& bgr, const Eigen::Vector3d& line, double t0, double t1,
                   const EdgePeakSearch& search, std::vector<EdgePeak>* peaks) {
  if (bgr.empty() || bgr.type() != CV_8UC3) return 0;
  const Eigen::Vector2d n = line.head<2>();
  const Eigen::Vector2d direction(line.y(), -line.x());
  const Eigen::Vector2d origin = -line.z() * n;
  const bool by_rows = CrossedByRows(line);
  const Eigen::Vector2d a = origin + t0 * direction, b = origin + t1 * direction;
  const int major_lo = static_cast<int>(std::ceil(std::min(by_rows ? a.y() : a.x(),
                                                           by_rows ? b.y() : b.x())));
  const int major_hi = static_cast<int>(std::floor(std::max(by_rows ? a.y() : a.x(),
                                                            by_rows ? b.y() : b.x())));
  const int major_size = by_rows ? bgr.rows : bgr.cols, minor_size = by_rows ? bgr.cols : bgr.rows;
  const int reach = static_cast<int>(std::ceil(search.reach_px));
  // The thread's buffers, which keep their memory from call to call.
  thread_local std::vector<double> thread_m;
  thread_local std::vector<int> thread_smooth, thread_step;
  thread_local std::vector<double> thread_cell_gradients;
  std::vector<double>& m = thread_m;
  std::vector<int>&smooth = thread_smooth, &step = thread_step;
  m.assign(2 * reach + 3, 0.0);
  const int stride = std::max(1, search.step_px);
  int searched = 0;
  for (int k = std::max(1, major_lo); k <= std::min(major_size - 2, major_hi); k += stride) {
    // Where the line crosses this row (column): a u + b v + c = 0.
    const double minor = by_rows ? -(line.y() * k + line.z()) / line.x()
                                 : -(line.x() * k + line.z()) / line.y();
    if (!std::isfinite(minor)) continue;
    const int centre = static_cast<int>(std::lround(minor));
    const int first = centre - reach - 1;  // m[0] is one beyond the reach, for the peak test.
    if (first < 1 || first + 2 * reach + 2 > minor_size - 2) continue;
    GradientsAcross(bgr, by_rows, k, first, 2 * reach + 3, n, &smooth, &step,
                    &thread_cell_gradients, m.data());
    ++searched;
    const auto peak_at = [&](int i) {
      const double curve = m[i - 1] - 2 * m[i] + m[i + 1];
      const double shift =
          curve < 0 ? std::clamp(0.5 * (m[i - 1] - m[i + 1]) / curve, -0.5, 0.5) : 0.0;
      const double at = first + i + shift;
      EdgePeak peak;
      peak.point = by_rows ? Eigen::Vector2d(at, k) : Eigen::Vector2d(k, at);
      peak.major = k;
      peak.offset = at - minor;
      peak.strength = m[i];
      return peak;
    };
    int nearest = -1;
    for (int i = 1; i <= 2 * reach + 1; ++i) {
      if (m[i] < search.threshold || m[i] < m[i - 1] || m[i] <= m[i + 1]) continue;
      if (!search.nearest_only) {
        peaks->push_back(peak_at(i));
      } else if (nearest < 0 || std::abs(first + i - minor) < std::abs(first + nearest - minor)) {
        nearest = i;
      }
    }
    if (nearest >= 0) peaks->push_back(peak_at(nearest));
  }
  return searched;
}

}  // namespace corridor
