#include "kernels/color_gradient.h"

#include <algorithm>
#include <cstdlib>

#include <opencv2/imgproc.hpp>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "core/cpu_features.h"
#include "kernels/avx2_loads.h"
#include "kernels/image_border.h"
#include "kernels/three_channels.h"

namespace corridor {
namespace {

// Sobel of one channel's 8-bit row triple (above, centre, below): gx = s[u+1] - s[u-1] with
// s = above + 2 centre + below, gy = t[u-1] + 2 t[u] + t[u+1] with t = below - above. Its s and
// t rows (cols + 2, the reflected columns at 0 and cols + 1):
// The first `from` columns may have been done already (SobelSumsAvx2).
CORRIDOR_ALWAYS_INLINE inline void SobelSumsBody(const uchar* above, const uchar* centre,
                                                 const uchar* below, int cols,
                                                 short* __restrict s, short* __restrict t,
                                                 int from = 0) {
  for (int u = from; u < cols; ++u) {
    s[u + 1] = static_cast<short>(above[u] + 2 * centre[u] + below[u]);
    t[u + 1] = static_cast<short>(below[u] - above[u]);
  }
  s[0] = s[Reflect101(-1, cols) + 1];
  t[0] = t[Reflect101(-1, cols) + 1];
  s[cols + 1] = s[Reflect101(cols, cols) + 1];
  t[cols + 1] = t[Reflect101(cols, cols) + 1];
}

#ifdef CORRIDOR_AVX2_VARIANTS
// SobelSumsBody sixteen columns a step, each row's bytes widened straight from memory (the
// vectoriser takes 32 and splits the halves in registers): the same sums.
__attribute__((target("avx2"))) inline void SobelSumsAvx2(const uchar* above, const uchar* centre,
                                                          const uchar* below, int cols, short* s,
                                                          short* t) {
  int u = 0;
  for (; u + 16 <= cols; u += 16) {
    const __m256i a = avx2::Widen16(above + u), c = avx2::Widen16(centre + u);
    const __m256i b = avx2::Widen16(below + u);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(s + u + 1),
                        _mm256_add_epi16(_mm256_add_epi16(a, b), _mm256_slli_epi16(c, 1)));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(t + u + 1), _mm256_sub_epi16(b, a));
  }
  SobelSumsBody(above, centre, below, cols, s, t, u);
}
#endif

// One channel's gx, gy and |gx| + |gy| at u from its s and t rows; the first channel (kFirst)
// sets x, y and mag, the others replace them where larger (branch-free selects through a mask,
// so that the loop vectorises).
template <bool kFirst>
CORRIDOR_ALWAYS_INLINE inline void SelectChannel(const short* s, const short* t, int u, short* x,
                                                 short* y, short* mag) {
  const short cx = static_cast<short>(s[u + 2] - s[u]);
  const short cy = static_cast<short>(t[u] + 2 * t[u + 1] + t[u + 2]);
  const short cm = static_cast<short>(std::abs(cx) + std::abs(cy));
  if (kFirst) {
    *x = cx, *y = cy, *mag = cm;
  } else {
    const short larger = static_cast<short>(-static_cast<short>(cm > *mag));
    *x = static_cast<short>((cx & larger) | (*x & ~larger));
    *y = static_cast<short>((cy & larger) | (*y & ~larger));
    *mag = static_cast<short>((cm & larger) | (*mag & ~larger));
  }
}

#ifdef CORRIDOR_AVX2_VARIANTS
// Sixteen shorts from memory.
__attribute__((target("avx2"))) inline __m256i LoadShorts(const short* p) {
  return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
}

// The per-pixel choice among the channels (SelectChannel's) sixteen pixels a step from each
// channel's s and t rows (s[c], t[c]); returns the first pixel not done. 16-bit lanes: the same
// wrapping sums as SelectChannel's shorts, magnitudes (at most 2040) compared signed, a later
// channel taken only where strictly larger.
template <int kChannels>
__attribute__((target("avx2"))) inline int SelectChannelsAvx2(const short* const* s,
                                                              const short* const* t, int cols,
                                                              short* bx, short* by, short* best) {
  int u = 0;
  for (; u + 16 <= cols; u += 16) {
    __m256i x = _mm256_setzero_si256(), y = x, mag = x;
    for (int c = 0; c < kChannels; ++c) {
      const __m256i cx = _mm256_sub_epi16(LoadShorts(s[c] + u + 2), LoadShorts(s[c] + u));
      const __m256i middle = LoadShorts(t[c] + u + 1);
      const __m256i cy = _mm256_add_epi16(_mm256_add_epi16(LoadShorts(t[c] + u), LoadShorts(t[c] + u + 2)),
                                          _mm256_add_epi16(middle, middle));
      const __m256i cm = _mm256_add_epi16(_mm256_abs_epi16(cx), _mm256_abs_epi16(cy));
      if (c == 0) {
        x = cx, y = cy, mag = cm;
        continue;
      }
      const __m256i larger = _mm256_cmpgt_epi16(cm, mag);
      x = _mm256_blendv_epi8(x, cx, larger);
      y = _mm256_blendv_epi8(y, cy, larger);
      mag = _mm256_max_epi16(mag, cm);  // cm where larger, else mag.
    }
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(bx + u), x);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(by + u), y);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(best + u), mag);
  }
  return u;
}
#endif

// All kChannels channels of a row (planar rows above, at and below): their s and t rows into
// `sums` (2 (cols + 2) shorts a channel), then one pass choosing per pixel among the channels
// in registers, storing bx, by and best once. kAvx2: the sums through SobelSumsAvx2.
template <int kChannels, bool kAvx2>
CORRIDOR_ALWAYS_INLINE inline void ChannelsRowBody(const uchar* const* above,
                                                   const uchar* const* centre,
                                                   const uchar* const* below, int cols,
                                                   short* sums, short* __restrict bx,
                                                   short* __restrict by, short* __restrict best) {
  const int stride = 2 * (cols + 2);
  for (int c = 0; c < kChannels; ++c) {
#ifdef CORRIDOR_AVX2_VARIANTS
    if constexpr (kAvx2) {
      SobelSumsAvx2(above[c], centre[c], below[c], cols, sums + c * stride,
                    sums + c * stride + cols + 2);
      continue;
    }
#endif
    SobelSumsBody(above[c], centre[c], below[c], cols, sums + c * stride,
                  sums + c * stride + cols + 2);
  }
  const short* s0 = sums;
  const short* t0 = s0 + cols + 2;
  const short* s1 = sums + (kChannels > 1 ? 1 : 0) * stride;
  const short* t1 = s1 + cols + 2;
  const short* s2 = sums + (kChannels > 2 ? 2 : 0) * stride;
  const short* t2 = s2 + cols + 2;
  const short* s3 = sums + (kChannels > 3 ? 3 : 0) * stride;
  const short* t3 = s3 + cols + 2;
  int from = 0;
#ifdef CORRIDOR_AVX2_VARIANTS
  if constexpr (kAvx2) {
    const short* const s[4] = {s0, s1, s2, s3};
    const short* const t[4] = {t0, t1, t2, t3};
    from = SelectChannelsAvx2<kChannels>(s, t, cols, bx, by, best);
  }
#endif
  // The outputs never overlap the sums (GCC cannot tell, and checking it at run time for every
  // pointer pair is more than it will do).
#pragma GCC ivdep
  for (int u = from; u < cols; ++u) {
    short x, y, mag;
    SelectChannel<true>(s0, t0, u, &x, &y, &mag);
    if (kChannels > 1) SelectChannel<false>(s1, t1, u, &x, &y, &mag);
    if (kChannels > 2) SelectChannel<false>(s2, t2, u, &x, &y, &mag);
    if (kChannels > 3) SelectChannel<false>(s3, t3, u, &x, &y, &mag);
    bx[u] = x;
    by[u] = y;
    best[u] = mag;
  }
}

using ChannelsRowFn = void (*)(const uchar* const*, const uchar* const*, const uchar* const*,
                               int, short*, short*, short*, short*);

template <int kChannels>
void ChannelsRow(const uchar* const* above, const uchar* const* centre, const uchar* const* below,
                 int cols, short* sums, short* bx, short* by, short* best) {
  ChannelsRowBody<kChannels, false>(above, centre, below, cols, sums, bx, by, best);
}

#ifdef CORRIDOR_AVX2_VARIANTS
template <int kChannels>
__attribute__((target("avx2"))) void ChannelsRowAvx2(const uchar* const* above,
                                                     const uchar* const* centre,
                                                     const uchar* const* below, int cols,
                                                     short* sums, short* bx, short* by,
                                                     short* best) {
  ChannelsRowBody<kChannels, true>(above, centre, below, cols, sums, bx, by, best);
}
#endif

// The row function for n channels (2 to 4): AVX2 where the CPU has it.
ChannelsRowFn ChooseChannelsRow(int n) {
#ifdef CORRIDOR_AVX2_VARIANTS
  if (CpuHasAvx2()) {
    return n == 2 ? ChannelsRowAvx2<2> : n == 3 ? ChannelsRowAvx2<3>
                                                : ChannelsRowAvx2<4>;
  }
#endif
  return n == 2 ? ChannelsRow<2> : n == 3 ? ChannelsRow<3>
                                          : ChannelsRow<4>;
}

// Splits one row of 8-bit pixels of n channels (2 to 4) into n planar rows.
CORRIDOR_ALWAYS_INLINE inline void DeinterleaveBody(const uchar* pixels, int cols, int n,
                                                    uchar* const* planes) {
  if (n == 3) {
    uchar* __restrict p0 = planes[0];
    uchar* __restrict p1 = planes[1];
    uchar* __restrict p2 = planes[2];
    for (int u = 0; u < cols; ++u) {
      p0[u] = pixels[3 * u];
      p1[u] = pixels[3 * u + 1];
      p2[u] = pixels[3 * u + 2];
    }
    return;
  }
  for (int c = 0; c < n; ++c) {
    uchar* __restrict p = planes[c];
    for (int u = 0; u < cols; ++u) p[u] = pixels[n * u + c];
  }
}

using DeinterleaveFn = void (*)(const uchar*, int, int, uchar* const*);

void Deinterleave(const uchar* pixels, int cols, int n, uchar* const* planes) {
  DeinterleaveBody(pixels, cols, n, planes);
}

#ifdef CORRIDOR_AVX2_VARIANTS
// Three-channel rows 32 pixels a step by byte shuffles (each 128-bit lane 16 pixels), the rest
// as DeinterleaveBody; other channel counts as DeinterleaveBody. The same bytes.
__attribute__((target("avx2"))) void DeinterleaveAvx2(const uchar* pixels, int cols, int n,
                                                      uchar* const* planes) {
  if (n != 3) return DeinterleaveBody(pixels, cols, n, planes);
  using namespace three_channels;
  __m256i pick[3][3];
  for (int c = 0; c < 3; ++c) {
    for (int part = 0; part < 3; ++part) pick[c][part] = PickOf(c, part);
  }
  int u = 0;
  for (; u + 32 <= cols; u += 32) {
    const uchar* p = pixels + 3 * u;
    const __m256i parts[3] = {LoadPart(p, 0), LoadPart(p, 1), LoadPart(p, 2)};
    for (int c = 0; c < 3; ++c) {
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(planes[c] + u), Channel(parts, pick[c]));
    }
  }
  uchar* const rest[3] = {planes[0] + u, planes[1] + u, planes[2] + u};
  DeinterleaveBody(pixels + 3 * u, cols - u, 3, rest);
}
#endif

// The row split: AVX2 where the CPU has it.
DeinterleaveFn ChooseDeinterleave() {
#ifdef CORRIDOR_AVX2_VARIANTS
  if (CpuHasAvx2()) return DeinterleaveAvx2;
#endif
  return Deinterleave;
}

// The same through cv::Sobel: grey images (a view keeps using the pixels around it, as
// cv::Sobel does) and depths other than 8 bits.
void ColorGradientOpenCv(const cv::Mat& image, cv::Mat* dx, cv::Mat* dy) {
  if (image.channels() == 1) {
    cv::Sobel(image, *dx, CV_16S, 1, 0, 3);
    cv::Sobel(image, *dy, CV_16S, 0, 1, 3);
    return;
  }
  std::vector<cv::Mat> channels;
  cv::split(image, channels);
  cv::Sobel(channels[0], *dx, CV_16S, 1, 0, 3);
  cv::Sobel(channels[0], *dy, CV_16S, 0, 1, 3);
  cv::Mat cx, cy;
  for (size_t c = 1; c < channels.size(); ++c) {
    cv::Sobel(channels[c], cx, CV_16S, 1, 0, 3);
    cv::Sobel(channels[c], cy, CV_16S, 0, 1, 3);
    for (int r = 0; r < dx->rows; ++r) {
      short* bx = dx->ptr<short>(r);
      short* by = dy->ptr<short>(r);
      const short* x = cx.ptr<short>(r);
      const short* y = cy.ptr<short>(r);
      for (int u = 0; u < dx->cols; ++u) {
        if (std::abs(x[u]) + std::abs(y[u]) > std::abs(bx[u]) + std::abs(by[u])) {
          bx[u] = x[u];
          by[u] = y[u];
        }
      }
    }
  }
}

// ColorGradient's working memory: planar rows and Sobel scratch rows.
struct GradientScratch {
  std::vector<uchar> plane_rows;
  std::vector<short> rows;
};

}  // namespace

namespace {

// Adds a row of |dx| + |dy| values (0 .. 2040) to the histogram, those below `floor` (> 0) all to
// bin floor - 1: eight values a step with SSE2, the small ones only counted.
void AddRowAboveFloor(const short* best, int cols, int floor, int* bins) {
  int u = 0, below = 0;
#ifdef __SSE2__
  const __m128i limit = _mm_set1_epi16(static_cast<short>(floor));
  __m128i small = _mm_setzero_si128();  // Per lane, minus the count of values below the floor.
  for (; u + 8 <= cols; u += 8) {
    const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(best + u));
    const __m128i is_small = _mm_cmplt_epi16(b, limit);
    small = _mm_add_epi16(small, is_small);
    // One bit per lane (the low byte's) of the values at least the floor.
    for (int large = ~_mm_movemask_epi8(is_small) & 0x5555; large != 0; large &= large - 1) {
      ++bins[std::min<int>(kGradientBins - 1, best[u + (__builtin_ctz(large) >> 1)])];
    }
  }
  alignas(16) short lanes[8];
  _mm_store_si128(reinterpret_cast<__m128i*>(lanes), small);
  for (const short lane : lanes) below -= lane;
#endif
  for (; u < cols; ++u) {
    if (best[u] < floor) {
      ++below;
    } else {
      ++bins[std::min<int>(kGradientBins - 1, best[u])];
    }
  }
  bins[floor - 1] += below;
}

}  // namespace

void ColorGradient(const cv::Mat& image, cv::Mat* dx, cv::Mat* dy, std::vector<int>* histogram,
                   int histogram_floor) {
  histogram_floor = std::clamp(histogram_floor, 0, kGradientBins);
  if (image.depth() != CV_8U || image.channels() == 1 || image.channels() > 4) {
    ColorGradientOpenCv(image, dx, dy);
    if (histogram != nullptr) {
      histogram->assign(kGradientBins, 0);
      for (int r = 0; r < dx->rows; ++r) {
        const short* gx = dx->ptr<short>(r);
        const short* gy = dy->ptr<short>(r);
        for (int u = 0; u < dx->cols; ++u) {
          ++(*histogram)[std::min(kGradientBins - 1, std::abs(gx[u]) + std::abs(gy[u]))];
        }
      }
    }
    return;
  }
  const int rows = image.rows, cols = image.cols, n = image.channels();
  // Each image row's channels, split once into one of three planar rows: the rows above, at and
  // below the current one (Reflect101 at the borders) are always in distinct slots, so nothing is
  // split twice and the planes stay in the cache (cv::split of the whole image first is slower:
  // docs/results.md, "Image kernels").
  // Its buffers are the thread's, reused from call to call.
  thread_local GradientScratch thread_scratch;
  GradientScratch& work = thread_scratch;
  std::vector<uchar>& plane_rows = work.plane_rows;
  plane_rows.assign(static_cast<size_t>(3) * n * cols, 0);
  uchar* planes[3][4];
  int slot_row[3] = {-1, -1, -1};
  for (int k = 0; k < 3; ++k) {
    for (int c = 0; c < n; ++c) planes[k][c] = plane_rows.data() + (k * n + c) * cols;
  }
  const DeinterleaveFn deinterleave = ChooseDeinterleave();
  const ChannelsRowFn channels_row = ChooseChannelsRow(n);
  const auto split_row = [&](int r) -> uchar* const* {
    uchar* const* slot = planes[r % 3];
    if (slot_row[r % 3] != r) {
      deinterleave(image.ptr<uchar>(r), cols, n, slot);
      slot_row[r % 3] = r;
    }
    return slot;
  };
  dx->create(rows, cols, CV_16S);
  dy->create(rows, cols, CV_16S);
  if (histogram != nullptr) histogram->assign(kGradientBins, 0);
  // Scratch rows: s and t of each channel (cols + 2 each) and the best |dx| + |dy|.
  std::vector<short>& scratch = work.rows;
  scratch.assign(static_cast<size_t>(2 * n + 1) * (cols + 2), 0);
  short* sums = scratch.data();
  short* best = sums + 2 * n * (cols + 2);
  for (int r = 0; r < rows; ++r) {
    const int above = Reflect101(r - 1, rows), below = Reflect101(r + 1, rows);
    short* bx = dx->ptr<short>(r);
    short* by = dy->ptr<short>(r);
    uchar* const* a = split_row(above);
    uchar* const* m = split_row(r);
    uchar* const* b = split_row(below);
    channels_row(a, m, b, cols, sums, bx, by, best);
    if (histogram != nullptr && histogram_floor > 0) {
      AddRowAboveFloor(best, cols, histogram_floor, histogram->data());
    } else if (histogram != nullptr) {
      int* bins = histogram->data();
      for (int u = 0; u < cols; ++u) ++bins[std::min<int>(kGradientBins - 1, best[u])];
    }
  }
}

double HistogramPercentile(const std::vector<int>& histogram, double total, double p) {
  const double target = p / 100.0 * total;
  double count = 0;
  for (size_t m = 0; m < histogram.size(); ++m) {
    count += histogram[m];
    if (count >= target) return static_cast<double>(m);
  }
  return static_cast<double>(histogram.size()) - 1;
}

}  // namespace corridor
