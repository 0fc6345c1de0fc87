#include "perception/vertical_crossings.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#ifdef __x86_64__
#include <immintrin.h>
#endif

#include "core/cpu_features.h"
#include "core/round_half_away.h"
#include "corridor_depth/corridor_frame.h"

namespace corridor {
namespace {

// One examined point of the junction: its pixel, the image direction of "up" on the wall there,
// and the length in pixels of the band above it.
struct BandPoint {
  Eigen::Vector2d pixel;
  Eigen::Vector2d up;
  double length = 0;
};

// The 3x3 Sobel gradient of the sum of the three colour channels at (u, v), an interior pixel of
// an 8-bit BGR image: computed only where a band needs it, not over whole rows.
inline void SumSobel(const cv::Mat& bgr, int u, int v, int* gx, int* gy) {
  const uchar* r0 = bgr.ptr<uchar>(v - 1) + 3 * (u - 1);
  const uchar* r1 = bgr.ptr<uchar>(v) + 3 * (u - 1);
  const uchar* r2 = bgr.ptr<uchar>(v + 1) + 3 * (u - 1);
  const auto s = [](const uchar* p) { return p[0] + p[1] + p[2]; };
  *gx = (s(r0 + 6) + 2 * s(r1 + 6) + s(r2 + 6)) - (s(r0) + 2 * s(r1) + s(r2));
  *gy = (s(r2) + 2 * s(r2 + 3) + s(r2 + 6)) - (s(r0) + 2 * s(r0 + 3) + s(r0 + 6));
}

#ifdef CORRIDOR_AVX2_VARIANTS
// SumSobel with byte products: the nine bytes of each of the three rows against the Sobel
// weights of their pixel (gx: -1 0 1 down the rows 1, 2, 1; gy: 1 2 1 on the row below less the
// row above), summed in 16 then 32 bits: the same integers. Reads 16 bytes from each row's first
// pixel, so only where that stays inside the image's data (else the scalar one).
// `data`, `step` and `end` are bgr's first pixel, row step and data end, read once by the caller.
__attribute__((target("avx2"))) inline void SumSobelAvx2(const cv::Mat& bgr, const uchar* data,
                                                         size_t step, const uchar* end, int u,
                                                         int v, int* gx, int* gy) {
  const uchar* r1 = data + step * static_cast<size_t>(v) + 3 * (u - 1);
  const uchar* r0 = r1 - step;
  const uchar* r2 = r1 + step;
  if (r2 + 16 > end) return SumSobel(bgr, u, v, gx, gy);
  const __m128i wx = _mm_setr_epi8(-1, -1, -1, 0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0);
  const __m128i wx2 = _mm_setr_epi8(-2, -2, -2, 0, 0, 0, 2, 2, 2, 0, 0, 0, 0, 0, 0, 0);
  const __m128i wy = _mm_setr_epi8(1, 1, 1, 2, 2, 2, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0);
  const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(r0));
  const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(r1));
  const __m128i c = _mm_loadu_si128(reinterpret_cast<const __m128i*>(r2));
  const __m128i x = _mm_add_epi16(_mm_add_epi16(_mm_maddubs_epi16(a, wx), _mm_maddubs_epi16(b, wx2)),
                                  _mm_maddubs_epi16(c, wx));
  const __m128i y = _mm_sub_epi16(_mm_maddubs_epi16(c, wy), _mm_maddubs_epi16(a, wy));
  // Lanes 0-3: pairs of x, 4-7: pairs of y; then 32-bit sums, then x and y.
  const __m128i pairs = _mm_madd_epi16(_mm_hadd_epi16(x, y), _mm_set1_epi16(1));
  const __m128i sums = _mm_hadd_epi32(pairs, pairs);
  *gx = _mm_cvtsi128_si32(sums);
  *gy = _mm_extract_epi32(sums, 1);
}
#endif

// The band from the point along `direction` (from 2 px on, its length): the fraction of it on an
// edge running along `up` (within 1 px across, its gradient across `up` at least `threshold` and
// twice its gradient along `up`), and its mean contrast across `up` (the largest within 1 px).
// The walk stops once the fraction cannot reach `min_fraction`: the fraction is then the most it
// could have been (below min_fraction, as the whole walk's would be) and the contrast is not
// meaningful; callers read it only for a band at min_fraction or above.
struct Run {
  double fraction = 0;
  double contrast = 0;
};

// The band's points (k = 2, 3, ... up to `length`).
inline int BandPoints(double length) {
  return length >= 2 ? static_cast<int>(std::floor(length)) - 1 : 0;
}

// The fewest points off an edge that leave a band of `total` points below min_fraction, its best
// fraction computed as the whole walk's would be; total + 1 when none do.
inline int MissesToFail(int total, double min_fraction) {
  for (int misses = 0; misses <= total; ++misses) {
    if (static_cast<double>(total - misses) / total < min_fraction) return misses;
  }
  return total + 1;
}

// The Run of a walk cut after `misses` points off an edge: the best fraction it could have had.
inline Run CutRun(int total, int misses) {
  Run run;
  run.fraction = static_cast<double>(total - misses) / total;
  return run;
}

Run BandRunBaseline(const cv::Mat& bgr, const BandPoint& p, const Eigen::Vector2d& direction,
                    double threshold, double min_fraction) {
  const Eigen::Vector2d across(-p.up.y(), p.up.x());
  const int total = BandPoints(p.length);
  const int fail = MissesToFail(total, min_fraction);
  int on = 0, n = 0;
  double contrast = 0;
  for (double k = 2; k <= p.length; k += 1, ++n) {
    if (n - on >= fail) return CutRun(total, n - on);
    const Eigen::Vector2d q = p.pixel + k * direction;
    double best = 0;
    bool edge = false;
    for (int d = -1; d <= 1; ++d) {
      const int u = RoundHalfAway(q.x() + d * across.x());
      const int v = RoundHalfAway(q.y() + d * across.y());
      if (u < 1 || v < 1 || u >= bgr.cols - 1 || v >= bgr.rows - 1) continue;
      int gx = 0, gy = 0;
      SumSobel(bgr, u, v, &gx, &gy);
      const double g_across = std::abs(gx * across.x() + gy * across.y());
      const double g_up = std::abs(gx * p.up.x() + gy * p.up.y());
      best = std::max(best, g_across);
      edge = edge || (g_across >= threshold && g_across >= 2 * g_up);
    }
    on += edge;
    contrast += best;
  }
  Run run;
  if (n > 0) run.fraction = static_cast<double>(on) / n, run.contrast = contrast / n;
  return run;
}

#ifdef CORRIDOR_AVX2_VARIANTS
// SumSobel of the three pixels (u0, v), (u0 + 1, v), (u0 + 2, v), all at least 1 px inside the
// image, from one 16-byte read of each of the three rows (the five pixels u0 - 1 .. u0 + 3): the
// first two in the two halves of one AVX2 register, the third alone. *gx and *gy get
// (gx0, gx1, gx2, 0) and (gy0, gy1, gy2, 0); the same integers (no sum comes near 2^15). False
// (nothing written) when a read would leave the image's data.
__attribute__((target("avx2"))) inline bool SumSobel3Avx2(const uchar* data, size_t step,
                                                          const uchar* end, int u0, int v,
                                                          __m128i* gx, __m128i* gy) {
  const uchar* r1 = data + step * static_cast<size_t>(v) + 3 * (u0 - 1);
  const uchar* r0 = r1 - step;
  const uchar* r2 = r1 + step;
  if (r2 + 16 > end) return false;
  // The window's pixel p is bytes 3p .. 3p + 2; the centres are pixels 1 and 2 (the two halves)
  // and 3 (alone).
  const __m256i wx = _mm256_setr_epi8(-1, -1, -1, 0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0,  //
                                      0, 0, 0, -1, -1, -1, 0, 0, 0, 1, 1, 1, 0, 0, 0, 0);
  const __m256i wx2 = _mm256_setr_epi8(-2, -2, -2, 0, 0, 0, 2, 2, 2, 0, 0, 0, 0, 0, 0, 0,  //
                                       0, 0, 0, -2, -2, -2, 0, 0, 0, 2, 2, 2, 0, 0, 0, 0);
  const __m256i wy = _mm256_setr_epi8(1, 1, 1, 2, 2, 2, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0,  //
                                      0, 0, 0, 1, 1, 1, 2, 2, 2, 1, 1, 1, 0, 0, 0, 0);
  const __m128i wx3 = _mm_setr_epi8(0, 0, 0, 0, 0, 0, -1, -1, -1, 0, 0, 0, 1, 1, 1, 0);
  const __m128i wx23 = _mm_setr_epi8(0, 0, 0, 0, 0, 0, -2, -2, -2, 0, 0, 0, 2, 2, 2, 0);
  const __m128i wy3 = _mm_setr_epi8(0, 0, 0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 1, 1, 1, 0);
  const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(r0));
  const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(r1));
  const __m128i c = _mm_loadu_si128(reinterpret_cast<const __m128i*>(r2));
  const __m256i aa = _mm256_broadcastsi128_si256(a), bb = _mm256_broadcastsi128_si256(b);
  const __m256i cc = _mm256_broadcastsi128_si256(c);
  const __m256i x = _mm256_add_epi16(
      _mm256_add_epi16(_mm256_maddubs_epi16(aa, wx), _mm256_maddubs_epi16(bb, wx2)),
      _mm256_maddubs_epi16(cc, wx));
  const __m256i y = _mm256_sub_epi16(_mm256_maddubs_epi16(cc, wy), _mm256_maddubs_epi16(aa, wy));
  // Each half: (x, y, x, y) of its centre.
  const __m256i pairs = _mm256_madd_epi16(_mm256_hadd_epi16(x, y), _mm256_set1_epi16(1));
  const __m256i sums = _mm256_hadd_epi32(pairs, pairs);
  const __m128i x3 = _mm_add_epi16(
      _mm_add_epi16(_mm_maddubs_epi16(a, wx3), _mm_maddubs_epi16(b, wx23)),
      _mm_maddubs_epi16(c, wx3));
  const __m128i y3 = _mm_sub_epi16(_mm_maddubs_epi16(c, wy3), _mm_maddubs_epi16(a, wy3));
  const __m128i pairs3 = _mm_madd_epi16(_mm_hadd_epi16(x3, y3), _mm_set1_epi16(1));
  const __m128i sums3 = _mm_hadd_epi32(pairs3, pairs3);  // (x, y, x, y) of the third.
  const __m128i first_two = _mm_unpacklo_epi32(_mm256_castsi256_si128(sums),
                                               _mm256_extracti128_si256(sums, 1));  // x0 x1 y0 y1
  const __m128i third = _mm_unpacklo_epi32(sums3, _mm_setzero_si128());             // x2 0 y2 0
  *gx = _mm_unpacklo_epi64(first_two, third);
  *gy = _mm_unpackhi_epi64(first_two, third);
  return true;
}

// RoundHalfAway of four doubles: truncation, the exact remainder, then the whole step.
__attribute__((target("avx2"))) inline __m128i RoundHalfAwayAvx2(__m256d x) {
  const __m256d t = _mm256_round_pd(x, _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC);
  const __m256d rest = _mm256_sub_pd(x, t);
  const __m256d one = _mm256_set1_pd(1.0);
  const __m256d up = _mm256_and_pd(_mm256_cmp_pd(rest, _mm256_set1_pd(0.5), _CMP_GE_OQ), one);
  const __m256d down =
      _mm256_and_pd(_mm256_cmp_pd(rest, _mm256_set1_pd(-0.5), _CMP_LE_OQ), one);
  return _mm256_cvttpd_epi32(_mm256_sub_pd(_mm256_add_pd(t, up), down));
}

// The same band with the three points across (d = -1, 0, 1) in the lanes of AVX2 registers:
// the same products and sums (no FMA), RoundHalfAway's rounding (truncation, then the exact
// remainder), SumSobelAvx2's integers. A point outside the image counts as a zero gradient,
// which changes neither the largest contrast (>= 0) nor the edge test (threshold > 0).
__attribute__((target("avx2"))) Run BandRunAvx2(const cv::Mat& bgr, const BandPoint& p,
                                                const Eigen::Vector2d& direction,
                                                double threshold, double min_fraction) {
  const Eigen::Vector2d across(-p.up.y(), p.up.x());
  const __m256d steps = _mm256_setr_pd(-1.0, 0.0, 1.0, 0.0);
  const __m256d step_x = _mm256_mul_pd(steps, _mm256_set1_pd(across.x()));
  const __m256d step_y = _mm256_mul_pd(steps, _mm256_set1_pd(across.y()));
  const __m256d ax = _mm256_set1_pd(across.x()), ay = _mm256_set1_pd(across.y());
  const __m256d ux = _mm256_set1_pd(p.up.x()), uy = _mm256_set1_pd(p.up.y());
  const __m256d two = _mm256_set1_pd(2.0);
  const __m256d sign = _mm256_set1_pd(-0.0), limit = _mm256_set1_pd(threshold);
  const int max_u = bgr.cols - 2, max_v = bgr.rows - 2;
  const uchar* data = bgr.data;
  const uchar* end = bgr.dataend;
  const size_t step = bgr.step[0];
  const int total = BandPoints(p.length);
  const int fail = MissesToFail(total, min_fraction);
  int on = 0, n = 0;
  double contrast = 0;
  for (double k = 2; k <= p.length; k += 1, ++n) {
    if (n - on >= fail) return CutRun(total, n - on);
    const Eigen::Vector2d q = p.pixel + k * direction;
    alignas(16) int us[4], vs[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(us),
                    RoundHalfAwayAvx2(_mm256_add_pd(_mm256_set1_pd(q.x()), step_x)));
    _mm_store_si128(reinterpret_cast<__m128i*>(vs),
                    RoundHalfAwayAvx2(_mm256_add_pd(_mm256_set1_pd(q.y()), step_y)));
    __m256d gx, gy;
    __m128i gx3, gy3;
    // Three neighbours along one row, all inside (the usual case, the band running up): their
    // gradients together.
    if (vs[0] == vs[1] && vs[1] == vs[2] && us[1] == us[0] + 1 && us[2] == us[0] + 2 &&
        us[0] >= 1 && us[2] <= max_u && vs[0] >= 1 && vs[0] <= max_v &&
        SumSobel3Avx2(data, step, end, us[0], vs[0], &gx3, &gy3)) {
      gx = _mm256_cvtepi32_pd(gx3);
      gy = _mm256_cvtepi32_pd(gy3);
    } else {
      alignas(32) double gxs[4] = {0, 0, 0, 0}, gys[4] = {0, 0, 0, 0};
      for (int d = 0; d < 3; ++d) {
        const int u = us[d], v = vs[d];
        if (u < 1 || v < 1 || u > max_u || v > max_v) continue;
        int sx = 0, sy = 0;
        SumSobelAvx2(bgr, data, step, end, u, v, &sx, &sy);
        gxs[d] = sx;
        gys[d] = sy;
      }
      gx = _mm256_load_pd(gxs);
      gy = _mm256_load_pd(gys);
    }
    const __m256d g_across = _mm256_andnot_pd(
        sign, _mm256_add_pd(_mm256_mul_pd(gx, ax), _mm256_mul_pd(gy, ay)));
    const __m256d g_up = _mm256_andnot_pd(
        sign, _mm256_add_pd(_mm256_mul_pd(gx, ux), _mm256_mul_pd(gy, uy)));
    const __m256d is_edge = _mm256_and_pd(_mm256_cmp_pd(g_across, limit, _CMP_GE_OQ),
                                          _mm256_cmp_pd(g_across, _mm256_mul_pd(two, g_up),
                                                        _CMP_GE_OQ));
    on += _mm256_movemask_pd(is_edge) != 0;
    alignas(32) double g[4];
    _mm256_store_pd(g, g_across);
    contrast += std::max(std::max(g[0], g[1]), g[2]);
  }
  Run run;
  if (n > 0) run.fraction = static_cast<double>(on) / n, run.contrast = contrast / n;
  return run;
}
#endif

Run BandRun(const cv::Mat& bgr, const BandPoint& p, const Eigen::Vector2d& direction,
            double threshold, double min_fraction) {
#ifdef CORRIDOR_AVX2_VARIANTS
  if (CpuHasAvx2()) return BandRunAvx2(bgr, p, direction, threshold, min_fraction);
#endif
  return BandRunBaseline(bgr, p, direction, threshold, min_fraction);
}

}  // namespace

bool VerticalCrossingOptions::Check(std::string* why) const {
  if (!(band_height > 0 && band_height < 3)) {
    *why = "band_height must be in (0, 3) m";
  } else if (!(min_band_px >= 3)) {
    *why = "min_band_px must be at least 3";
  } else if (!(max_band_px >= min_band_px)) {
    *why = "max_band_px must be at least min_band_px";
  } else if (!(min_run > 0 && min_run <= 1)) {
    *why = "min_run must be in (0, 1]";
  } else if (!(min_contrast_ratio >= 0 && min_contrast_ratio <= 10)) {
    *why = "min_contrast_ratio must be in [0, 10]";
  } else if (!(min_step > 0 && min_step < 256)) {
    *why = "min_step must be in (0, 256) grey levels";
  } else if (step_px < 1) {
    *why = "step_px must be at least 1";
  } else {
    return true;
  }
  return false;
}

VerticalCrossings CountVerticalCrossings(const cv::Mat& bgr, const Camera& camera, int scale,
                                         const CorridorGeometry& g, const JunctionLine& line,
                                         const VerticalCrossingOptions& options) {
  VerticalCrossings out;
  if (bgr.empty() || bgr.type() != CV_8UC3 || scale < 1 || !(g.camera_height > 0)) return out;
  const CorridorRotation<double> r(g.pitch, g.yaw);
  const Vec3<double> n = r.FloorNormal();  // Down, in the camera frame.
  const Eigen::Vector2d a = line.near_end / scale, b = line.far_end / scale;
  const double span = (b - a).norm();
  if (!(span >= 2) || !a.allFinite() || !b.allFinite()) return out;
  // A step of min_step grey levels in each channel gives this summed Sobel response.
  const double threshold = 12.0 * options.min_step;
  // Runs of consecutive points whose band above is on a vertical edge: one edge reaching down to
  // the junction; it crosses when, somewhere along the run, the band below is on one too, of
  // nearly the same contrast (a glossy floor's reflection of it is fainter).
  bool in_run = false, run_crosses = false;
  const auto end_run = [&] {
    if (in_run) {
      ++out.reaching;
      out.crossing += run_crosses;
    }
    in_run = run_crosses = false;
  };
  for (double t = 0; t <= span; t += options.step_px) {
    // The floor point seen at the pixel, and the point band_height above it on the wall,
    // projected: the direction of "up" there and the band's length.
    const Eigen::Vector2d pixel = a + (b - a) * (t / span);
    const Vec3<double> ray = RayOfRawPixel(camera, pixel.x(), pixel.y());
    const double along = n.x * ray.x + n.y * ray.y + n.z * ray.z;
    if (!(along > 1e-6)) continue;  // The ray does not meet the floor.
    const double depth = g.camera_height / along;
    const Eigen::Vector3d floor_point(depth * ray.x, depth * ray.y, depth * ray.z);
    const Eigen::Vector3d above =
        floor_point - options.band_height * Eigen::Vector3d(n.x, n.y, n.z);
    if (!(above.z() > 0.05)) continue;
    Eigen::Vector2d up_pixel = camera.Project(above);
    if (camera.HasDistortion()) up_pixel = camera.Distort(up_pixel);
    const Eigen::Vector2d up = up_pixel - pixel;
    BandPoint p{pixel, up.normalized(), std::min(up.norm(), options.max_band_px)};
    if (!(up.norm() >= options.min_band_px) || !p.up.allFinite()) continue;
    ++out.samples;
    const Run above_run = BandRun(bgr, p, p.up, threshold, options.min_run);
    if (above_run.fraction < options.min_run) {
      end_run();
      continue;
    }
    in_run = true;
    if (!run_crosses) {
      const Run below = BandRun(bgr, p, -p.up, threshold, options.min_run);
      run_crosses = below.fraction >= options.min_run &&
                    below.contrast >= options.min_contrast_ratio * above_run.contrast;
    }
  }
  end_run();
  return out;
}

}  // namespace corridor
