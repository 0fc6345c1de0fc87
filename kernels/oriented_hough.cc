#include "kernels/oriented_hough.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include <opencv2/core.hpp>

#include "core/cpu_features.h"
#include "kernels/edge_scan.h"
#include "kernels/fast_atan2.h"
#ifdef __x86_64__
#include <immintrin.h>
#endif

namespace corridor {
namespace {

constexpr int kAngles = 180;  // 1 degree bins of the line normal's direction, [0, 180).
constexpr int kShift = 16;    // Fixed-point bits of the minor coordinate when following a line.

// A pixel's state while lines are drawn.
enum PixelState : uint8_t {
  kNone = 0,       // Not an edge, or removed with a line.
  kWaiting = 1,    // An edge pixel not drawn yet (holds no votes).
  kVoted = 2,      // Drawn: its votes are in the accumulator.
  kGoneVoted = 3,  // Removed on the way of a line too short to keep, its votes still in (as PPHT).
};

// The (angle, rho) vote counts, reused by the calls of one thread and emptied at the end of
// each: allocating and first touching them per call cost a third of the voting; clearing them
// costs less than taking every vote back. Each angle's row holds only the rhos the map's pixels
// reach at that angle (from its corners, where rho = u cos + v sin is extreme): 0.2 MB at 640x248
// rather than 0.6 MB for every angle's full -(w + h) .. w + h, so that the votes' scattered bins
// stay in a core's L2 cache.
class Accumulator {
 public:
  Accumulator() {
    for (int i = 0; i < 3 * kAngles; ++i) {
      const int n = i % kAngles;
      cos_[i] = static_cast<float>(std::cos(n * M_PI / kAngles));
      sin_[i] = static_cast<float>(std::sin(n * M_PI / kAngles));
    }
  }

  // Sizes the accumulator for a width x height map (cleared only when that changes: every call
  // leaves it empty) and sets the voting window, bins on each side.
  void Reset(int width, int height, int window) {
    window_ = window;
    if (width_ != width || height_ != height) {
      width_ = width;
      height_ = height;
      int rows_start[kAngles];
      int total = 0;
      for (int n = 0; n < kAngles; ++n) {
        // Cells computes cvRound(u cos + v sin) in float: the corners bound it, give or take the
        // rounding (one bin of margin each way).
        int lo = 0, hi = 0;
        for (const int u : {0, width - 1}) {
          for (const int v : {0, height - 1}) {
            const int rho =
                cvRound(static_cast<float>(u) * cos_[n] + static_cast<float>(v) * sin_[n]);
            lo = std::min(lo, rho);
            hi = std::max(hi, rho);
          }
        }
        rows_start[n] = total - (lo - 1);  // Index of rho 0 in votes_.
        total += hi - lo + 3;
      }
      // Two bins more, never voted for: zeros for VoteAvx2's lanes past the window, and the
      // upper half of the last bin's 32-bit read.
      votes_.assign(static_cast<size_t>(total) + 2, 0);
      for (int i = 0; i < 3 * kAngles; ++i) row_[i] = rows_start[i % kAngles];
    }
  }

  // Adds a vote to the bins of the lines through (u, v) whose normals lie within the window of
  // `bin`; returns the fullest of them, and its angle in *best_angle (set only when the fullest
  // holds at least `threshold` votes).
  template <bool kAvx2>
  int Vote(int u, int v, int bin, int threshold, int* best_angle) {
#ifdef CORRIDOR_AVX2_VARIANTS
    if constexpr (kAvx2) return VoteAvx2(u, v, bin, threshold, best_angle);
#endif
    (void)threshold;
    const int first = Cells<kAvx2>(u, v, bin);
    int best = 0, best_k = 0;
    for (int k = 0; k <= 2 * window_; ++k) {
      const int cell = ++votes_[cells_[k]];
      // The first fullest bin, without a branch (which the votes' order makes unpredictable).
      const bool fuller = cell > best;
      best = fuller ? cell : best;
      best_k = fuller ? k : best_k;
    }
    *best_angle = (first + best_k) % kAngles;  // A vote adds to at least one bin: best >= 1.
    return best;
  }

  // Takes back the votes Vote(u, v, bin) added.
  template <bool kAvx2>
  void Unvote(int u, int v, int bin) {
    Cells<kAvx2>(u, v, bin);
#pragma GCC unroll 4
    for (int k = 0; k <= 2 * window_; ++k) --votes_[cells_[k]];
  }

  // Empties every bin: sixteen bytes a store where SSE2 is there (std::fill becomes glibc's
  // memset, whose rep stosb at this size valgrind counts byte by byte; the same zeros).
  void Clear() {
    int16_t* v = votes_.data();
    const size_t n = votes_.size();
    size_t i = 0;
#ifdef __SSE2__
    for (; i + 8 <= n; i += 8) {
      _mm_storeu_si128(reinterpret_cast<__m128i*>(v + i), _mm_setzero_si128());
    }
#endif
    for (; i < n; ++i) v[i] = 0;
  }

  float Cos(int n) const { return cos_[n]; }
  float Sin(int n) const { return sin_[n]; }

 private:
  // Fills cells_ with the bins of the lines through (u, v) of normal angles bin - window ...
  // bin + window (wrapped), rho = round(u cos + v sin) in float as cvRound rounds (to nearest,
  // ties to even); returns the first angle's index into the tables (angle + kAngles).
  template <bool kAvx2>
  int Cells(int u, int v, int bin) {
    const int first = bin - window_ + kAngles;
    const int count = 2 * window_ + 1;
    const float fu = static_cast<float>(u), fv = static_cast<float>(v);
    int k = 0;
#ifdef CORRIDOR_AVX2_VARIANTS
    if constexpr (kAvx2) k = CellsAvx2(fu, fv, first, count);
#endif
#ifdef __SSE2__
    // Four angles at a time: the same float products, sum and rounding as the scalar loop.
    const __m128 u4 = _mm_set1_ps(fu), v4 = _mm_set1_ps(fv);
    for (; k + 4 <= count; k += 4) {
      const __m128 rho = _mm_add_ps(_mm_mul_ps(u4, _mm_loadu_ps(cos_ + first + k)),
                                    _mm_mul_ps(v4, _mm_loadu_ps(sin_ + first + k)));
      const __m128i row = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row_ + first + k));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(cells_ + k),
                       _mm_add_epi32(_mm_cvtps_epi32(rho), row));
    }
#endif
    for (; k < count; ++k) {
      cells_[k] = row_[first + k] + cvRound(fu * cos_[first + k] + fv * sin_[first + k]);
    }
    return first;
  }

#ifdef CORRIDOR_AVX2_VARIANTS
  // Vote with the bins' new counts read back eight at a time (a gather of the 32 bits at each
  // bin: its count in the low half) and their maximum taken across the lanes; the first fullest
  // bin is looked for only when it reaches the threshold. The same counts and the same answer.
  __attribute__((target("avx2"))) int VoteAvx2(int u, int v, int bin, int threshold,
                                               int* best_angle) {
    const int first = Cells<true>(u, v, bin);
    const int count = 2 * window_ + 1;
#pragma GCC unroll 4
    for (int k = 0; k < count; ++k) ++votes_[cells_[k]];
    // Lanes past the window read the padding at the end of votes_, which holds zeros.
    const int padding = static_cast<int>(votes_.size()) - 2;
    for (int k = count; k < count + 7; ++k) cells_[k] = padding;
    const int* counts = reinterpret_cast<const int*>(votes_.data());  // Read at 2-byte steps.
    const __m256i low = _mm256_set1_epi32(0xffff);
    __m256i most = _mm256_setzero_si256();
    for (int k = 0; k < count; k += 8) {
      const __m256i index = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(cells_ + k));
      const __m256i pair = _mm256_i32gather_epi32(counts, index, 2);
      most = _mm256_max_epi32(most, _mm256_and_si256(pair, low));
    }
    __m128i m = _mm_max_epi32(_mm256_castsi256_si128(most), _mm256_extracti128_si256(most, 1));
    m = _mm_max_epi32(m, _mm_shuffle_epi32(m, _MM_SHUFFLE(1, 0, 3, 2)));
    m = _mm_max_epi32(m, _mm_shuffle_epi32(m, _MM_SHUFFLE(2, 3, 0, 1)));
    const int best = _mm_cvtsi128_si32(m);
    if (best >= threshold) {
      int k = 0;
      while (votes_[cells_[k]] != best) ++k;  // The first fullest bin.
      *best_angle = (first + k) % kAngles;
    }
    return best;
  }

  // Eight angles at a time: the same float products, sum and rounding (the current rounding
  // mode, to nearest even, as the SSE2 and scalar ones). The last group's lanes past the window
  // fill cells_ beyond it (room for kAngles + 8) from the tables' next angles (the window's last
  // angle lies under 2.5 kAngles into the tables, 3 kAngles long). Returns `count`.
  __attribute__((target("avx2"))) int CellsAvx2(float fu, float fv, int first, int count) {
    const __m256 u8 = _mm256_set1_ps(fu), v8 = _mm256_set1_ps(fv);
    int k = 0;
    for (; k < count; k += 8) {
      const __m256 rho = _mm256_add_ps(_mm256_mul_ps(u8, _mm256_loadu_ps(cos_ + first + k)),
                                       _mm256_mul_ps(v8, _mm256_loadu_ps(sin_ + first + k)));
      const __m256i row = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(row_ + first + k));
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(cells_ + k),
                          _mm256_add_epi32(_mm256_cvtps_epi32(rho), row));
    }
    return count;
  }
#endif

  int window_ = 0;
  int width_ = -1, height_ = -1;  // The map the rows are laid out for.
  std::vector<int16_t> votes_;    // A bin holds at most the pixels of one line: far below 2^15.
  // Angle tables three times over, so that a window is contiguous wherever it wraps.
  float cos_[3 * kAngles], sin_[3 * kAngles];
  int row_[3 * kAngles] = {};  // Index of (angle, rho 0) in votes_.
  int cells_[kAngles + 8];     // The bins of the last Cells call (and VoteAvx2's padding).
};

// Per-thread scratch of OrientedHoughSegments.
struct HoughScratch {
  Accumulator accumulator;
  cv::Mat state, bins;                 // PixelState and gradient bin of every pixel.
  std::vector<cv::Point> pool;         // Edge pixels in raster order.
  std::vector<uint64_t> keys, sorted;  // DrawOrder's keys and radix buffer.
  std::vector<cv::Point> drawn;        // The edge pixels in the order they are drawn.
};

// A pseudo-random 16-bit rank of pixel (u, v): a multiply-xorshift hash of its coordinates.
uint32_t DrawRank(int u, int v) {
  uint32_t h = static_cast<uint32_t>(u) * 0x9E3779B1u ^ static_cast<uint32_t>(v) * 0x85EBCA77u;
  h ^= h >> 15;
  h *= 0x2C1B3C6Du;
  h ^= h >> 12;
  return h >> 16;
}

// Puts the pixels in the order they are drawn: by DrawRank, ties in raster order (a stable radix
// sort of (rank, index in the raster-ordered pool) keys, low byte of the rank, then high byte).
// Each pixel's place among the others depends on its coordinates alone, so one edge pixel more or
// less moves no other pixel's turn: the segments change only around it. (Drawn from the pool by a
// random number generator, as OpenCV draws them, every later pixel gets another turn when one
// pixel is added: a blur one grey level off at a sixth of the pixels changed the width by more
// than 3% on 7% of the evaluation frames, against 2.5% in this order.)
#ifdef CORRIDOR_AVX2_VARIANTS
// DrawOrder's keys eight pixels at a time (the same 32-bit products and shifts in the lanes);
// returns how many it did (a multiple of eight), the caller does the rest.
__attribute__((target("avx2"))) size_t DrawKeysAvx2(const cv::Point* points, size_t n,
                                                    uint64_t* keys) {
  static_assert(sizeof(cv::Point) == 2 * sizeof(int), "cv::Point is (x, y) ints");
  const __m256i c1 = _mm256_set1_epi32(static_cast<int>(0x9E3779B1u));
  const __m256i c2 = _mm256_set1_epi32(static_cast<int>(0x85EBCA77u));
  const __m256i c3 = _mm256_set1_epi32(static_cast<int>(0x2C1B3C6Du));
  const __m256i xs_then_ys = _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7);
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  size_t i = 0;
  for (; i + 8 <= n && i + 8 <= 0xffffffffu; i += 8) {
    const __m256i a = _mm256_permutevar8x32_epi32(
        _mm256_loadu_si256(reinterpret_cast<const __m256i*>(points + i)), xs_then_ys);
    const __m256i b = _mm256_permutevar8x32_epi32(
        _mm256_loadu_si256(reinterpret_cast<const __m256i*>(points + i + 4)), xs_then_ys);
    const __m256i u = _mm256_permute2x128_si256(a, b, 0x20);
    const __m256i v = _mm256_permute2x128_si256(a, b, 0x31);
    __m256i h = _mm256_xor_si256(_mm256_mullo_epi32(u, c1), _mm256_mullo_epi32(v, c2));
    h = _mm256_xor_si256(h, _mm256_srli_epi32(h, 15));
    h = _mm256_mullo_epi32(h, c3);
    h = _mm256_xor_si256(h, _mm256_srli_epi32(h, 12));
    h = _mm256_srli_epi32(h, 16);
    const __m256i index = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(i)), lane);
    // (rank << 32 | index) of pixels 0 1 4 5 and 2 3 6 7; then in order.
    const __m256i low = _mm256_unpacklo_epi32(index, h), high = _mm256_unpackhi_epi32(index, h);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(keys + i),
                        _mm256_permute2x128_si256(low, high, 0x20));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(keys + i + 4),
                        _mm256_permute2x128_si256(low, high, 0x31));
  }
  return i;
}
#endif

void DrawOrder(const std::vector<cv::Point>& raster, std::vector<uint64_t>* keys,
               std::vector<uint64_t>* buffer, std::vector<cv::Point>* drawn) {
  const size_t n = raster.size();
  keys->resize(n);
  buffer->resize(n);
  size_t done = 0;
#ifdef CORRIDOR_AVX2_VARIANTS
  if (CpuHasAvx2()) done = DrawKeysAvx2(raster.data(), n, keys->data());
#endif
  for (size_t i = done; i < n; ++i) {
    (*keys)[i] = uint64_t{DrawRank(raster[i].x, raster[i].y)} << 32 | i;
  }
  for (int shift = 32; shift < 48; shift += 8) {
    size_t start[257] = {};
    for (const uint64_t k : *keys) ++start[((k >> shift) & 255) + 1];
    for (int b = 0; b < 256; ++b) start[b + 1] += start[b];
    for (const uint64_t k : *keys) (*buffer)[start[(k >> shift) & 255]++] = k;
    keys->swap(*buffer);
  }
  drawn->resize(n);
  for (size_t i = 0; i < n; ++i) (*drawn)[i] = raster[(*keys)[i] & 0xffffffffu];
}

// The normal's direction of the line through an edge pixel, from its gradient: a bin in [0, 180).
int GradientBin(short gx, short gy) {
  float degrees = FastAtan2(static_cast<float>(gy), static_cast<float>(gx));  // [0, 360).
  if (degrees >= 180.f) degrees -= 180.f;
  return cvRound(degrees) % kAngles;
}

#ifdef CORRIDOR_AVX2_VARIANTS
// GradientBin of the pool's pixels eight at a time into *bins: FastAtan2's operations in the same
// order in the lanes (no FMA; a division and selects where it branches), cvRound's rounding to
// nearest even; the same bins. Returns the count done: the last pixel is left to the caller, as
// its gradients' 32-bit reads could pass the end of dx and dy.
__attribute__((target("avx2"))) size_t GradientBinsAvx2(const std::vector<cv::Point>& pool,
                                                        const cv::Mat& dx, const cv::Mat& dy,
                                                        cv::Mat* bins) {
  const size_t n = pool.size();
  if (n < 9) return 0;
  constexpr float kDegrees = static_cast<float>(180 / M_PI);
  const __m256 p1 = _mm256_set1_ps(0.9997878412794807f * kDegrees);
  const __m256 p3 = _mm256_set1_ps(-0.3258083974640975f * kDegrees);
  const __m256 p5 = _mm256_set1_ps(0.1555786518463281f * kDegrees);
  const __m256 p7 = _mm256_set1_ps(-0.04432655554792128f * kDegrees);
  const __m256 eps = _mm256_set1_ps(static_cast<float>(DBL_EPSILON));
  const __m256 sign = _mm256_set1_ps(-0.0f), zero = _mm256_setzero_ps();
  const __m256 d90 = _mm256_set1_ps(90.f), d180 = _mm256_set1_ps(180.f);
  const __m256 d360 = _mm256_set1_ps(360.f);
  const __m256i halves = _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7);
  const __m256i dx_step = _mm256_set1_epi32(static_cast<int>(dx.step[0] / sizeof(short)));
  const __m256i dy_step = _mm256_set1_epi32(static_cast<int>(dy.step[0] / sizeof(short)));
  const __m256i last_angle = _mm256_set1_epi32(kAngles - 1), angles = _mm256_set1_epi32(kAngles);
  const int* dx_base = reinterpret_cast<const int*>(dx.data);
  const int* dy_base = reinterpret_cast<const int*>(dy.data);
  const int* points = reinterpret_cast<const int*>(pool.data());  // u, v pairs.
  size_t i = 0;
  for (; i + 8 < n; i += 8) {
    const __m256i a = _mm256_permutevar8x32_epi32(
        _mm256_loadu_si256(reinterpret_cast<const __m256i*>(points + 2 * i)), halves);
    const __m256i b = _mm256_permutevar8x32_epi32(
        _mm256_loadu_si256(reinterpret_cast<const __m256i*>(points + 2 * i + 8)), halves);
    const __m256i us = _mm256_permute2x128_si256(a, b, 0x20);
    const __m256i vs = _mm256_permute2x128_si256(a, b, 0x31);
    // Each gradient is the low half of the 32 bits read at it (little-endian), sign-extended.
    const __m256i gx32 = _mm256_i32gather_epi32(
        dx_base, _mm256_add_epi32(_mm256_mullo_epi32(vs, dx_step), us), 2);
    const __m256i gy32 = _mm256_i32gather_epi32(
        dy_base, _mm256_add_epi32(_mm256_mullo_epi32(vs, dy_step), us), 2);
    const __m256 x = _mm256_cvtepi32_ps(_mm256_srai_epi32(_mm256_slli_epi32(gx32, 16), 16));
    const __m256 y = _mm256_cvtepi32_ps(_mm256_srai_epi32(_mm256_slli_epi32(gy32, 16), 16));
    const __m256 ax = _mm256_andnot_ps(sign, x), ay = _mm256_andnot_ps(sign, y);
    const __m256 wide = _mm256_cmp_ps(ax, ay, _CMP_GE_OQ);  // ax >= ay.
    const __m256 c = _mm256_div_ps(_mm256_blendv_ps(ax, ay, wide),
                                   _mm256_add_ps(_mm256_blendv_ps(ay, ax, wide), eps));
    const __m256 c2 = _mm256_mul_ps(c, c);
    __m256 poly = _mm256_add_ps(_mm256_mul_ps(p7, c2), p5);
    poly = _mm256_add_ps(_mm256_mul_ps(poly, c2), p3);
    poly = _mm256_add_ps(_mm256_mul_ps(poly, c2), p1);
    poly = _mm256_mul_ps(poly, c);
    __m256 deg = _mm256_blendv_ps(_mm256_sub_ps(d90, poly), poly, wide);
    deg = _mm256_blendv_ps(deg, _mm256_sub_ps(d180, deg), _mm256_cmp_ps(x, zero, _CMP_LT_OQ));
    deg = _mm256_blendv_ps(deg, _mm256_sub_ps(d360, deg), _mm256_cmp_ps(y, zero, _CMP_LT_OQ));
    deg = _mm256_blendv_ps(deg, _mm256_sub_ps(deg, d180), _mm256_cmp_ps(deg, d180, _CMP_GE_OQ));
    __m256i bin = _mm256_cvtps_epi32(deg);  // [0, 180]; 180 is bin 0.
    bin = _mm256_sub_epi32(bin, _mm256_and_si256(_mm256_cmpgt_epi32(bin, last_angle), angles));
    alignas(32) int out[8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(out), bin);
    for (int k = 0; k < 8; ++k) {
      const cv::Point& p = pool[i + k];
      bins->ptr<uchar>(p.y)[p.x] = static_cast<uchar>(out[k]);
    }
  }
  return i;
}
#endif

// GradientBin of every pixel of the pool into *bins (AVX2 eight at a time where kAvx2).
template <bool kAvx2>
CORRIDOR_ALWAYS_INLINE inline void GradientBins(const std::vector<cv::Point>& pool,
                                                const cv::Mat& dx, const cv::Mat& dy,
                                                cv::Mat* bins) {
  size_t i = 0;
#ifdef CORRIDOR_AVX2_VARIANTS
  if constexpr (kAvx2) i = GradientBinsAvx2(pool, dx, dy, bins);
#endif
  for (; i < pool.size(); ++i) {
    const cv::Point& p = pool[i];
    bins->at<uchar>(p.y, p.x) =
        static_cast<uchar>(GradientBin(dx.at<short>(p.y, p.x), dy.at<short>(p.y, p.x)));
  }
}

// Steps along the line of normal angle n from (u, v), one pixel along its major axis at a time,
// the minor coordinate in fixed point: the same pixels in both passes.
struct LineWalker {
  bool along_u;  // True when the line is closer to horizontal: u steps by +-1.
  int u0, v0;    // Start, the minor coordinate shifted by kShift (plus a half).
  int du, dv;    // Step of the first direction (the second is its negation).

  LineWalker(int u, int v, float direction_u, float direction_v) {
    along_u = std::abs(direction_u) > std::abs(direction_v);
    if (along_u) {
      du = direction_u > 0 ? 1 : -1;
      dv = static_cast<int>(std::lround(direction_v * (1 << kShift) / std::abs(direction_u)));
      u0 = u;
      v0 = (v << kShift) + (1 << (kShift - 1));
    } else {
      dv = direction_v > 0 ? 1 : -1;
      du = static_cast<int>(std::lround(direction_u * (1 << kShift) / std::abs(direction_v)));
      u0 = (u << kShift) + (1 << (kShift - 1));
      v0 = v;
    }
  }
  int U(int x) const { return along_u ? x : x >> kShift; }
  int V(int y) const { return along_u ? y >> kShift : y; }
};

// A row of pixel states from the edge map's row: kWaiting at its edge (non-zero) pixels, kNone
// elsewhere, sixteen at a time where SSE2 is there; returns the row's edge pixels.
CORRIDOR_ALWAYS_INLINE inline size_t WaitingRow(const uchar* edges, int width, uchar* state) {
  static_assert(kNone == 0 && kWaiting == 1, "the states are the edge test's 0 and 1");
  int u = 0;
  size_t count = 0;
#ifdef __SSE2__
  const __m128i zero = _mm_setzero_si128(), one = _mm_set1_epi8(1);
  __m128i sums = zero;  // Two 64-bit sums of the states.
  for (; u + 16 <= width; u += 16) {
    const __m128i e = _mm_loadu_si128(reinterpret_cast<const __m128i*>(edges + u));
    const __m128i waiting = _mm_andnot_si128(_mm_cmpeq_epi8(e, zero), one);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(state + u), waiting);
    sums = _mm_add_epi64(sums, _mm_sad_epu8(waiting, zero));
  }
  count = static_cast<size_t>(_mm_cvtsi128_si64(sums)) +
          static_cast<size_t>(_mm_cvtsi128_si64(_mm_unpackhi_epi64(sums, sums)));
#endif
  for (; u < width; ++u) {
    state[u] = edges[u] != 0 ? kWaiting : kNone;
    count += state[u];
  }
  return count;
}

// OrientedHoughSegments' body, compiled for the baseline and (kAvx2) for AVX2: the same votes.
template <bool kAvx2>
CORRIDOR_ALWAYS_INLINE inline void HoughBody(const cv::Mat& edges, const cv::Mat& dx,
                                             const cv::Mat& dy, const OrientedHoughOptions& options,
                                             std::vector<cv::Vec4i>* segments) {
  segments->clear();
  if (edges.empty() || edges.type() != CV_8U || dx.type() != CV_16S || dy.type() != CV_16S ||
      dx.size() != edges.size() || dy.size() != edges.size()) {
    return;
  }
  const int width = edges.cols, height = edges.rows;
  // Options clamped in double before any conversion to int (undefined out of int's range; NaN
  // counts as 0).
  const double window_deg = options.angle_window_deg > 0 ? options.angle_window_deg : 0.0;
  const int window = static_cast<int>(std::lround(std::min(window_deg, kAngles / 2 - 1.0)));
  thread_local HoughScratch thread_scratch;
  // Its address made opaque to the optimiser: else it is a constant that gets re-derived inside
  // the loops it reaches, and in a shared object (the Python module) each such use is a
  // __tls_get_addr call (about 6% of a frame's instructions).
  HoughScratch* scratch_address = &thread_scratch;
  asm(""
      : "+r"(scratch_address));
  HoughScratch& scratch = *scratch_address;
  Accumulator& accumulator = scratch.accumulator;
  accumulator.Reset(width, height, window);
  cv::Mat& state = scratch.state;
  cv::Mat& bins = scratch.bins;
  state.create(height, width, CV_8U);
  size_t edge_pixels = 0;
  for (int v = 0; v < height; ++v) {
    edge_pixels += WaitingRow(edges.ptr<uchar>(v), width, state.ptr<uchar>(v));
  }
  bins.create(height, width, CV_8U);
  // Sized once (only growing past an earlier call's count writes anything), then filled through
  // a pointer.
  std::vector<cv::Point>& pool = scratch.pool;
  pool.resize(edge_pixels);
  cv::Point* next = pool.data();
  ForEachEdgePixel(edges, [&](int u, int v) { *next++ = cv::Point(u, v); });
  GradientBins<kAvx2>(pool, dx, dy, &bins);
  DrawOrder(pool, &scratch.keys, &scratch.sorted, &scratch.drawn);
  const int max_gap =
      options.max_gap > 0 ? static_cast<int>(std::min(options.max_gap, 1.0 * (width + height)))
                          : 0;
  for (const cv::Point& p : scratch.drawn) {
    if (state.at<uchar>(p.y, p.x) != kWaiting) continue;  // Removed with a line meanwhile.
    state.at<uchar>(p.y, p.x) = kVoted;
    int angle = 0;
    if (accumulator.Vote<kAvx2>(p.x, p.y, bins.at<uchar>(p.y, p.x), options.threshold, &angle) <
        options.threshold) {
      continue;
    }
    // Follow the line (direction perpendicular to the normal) both ways from p.
    const LineWalker walk(p.x, p.y, -accumulator.Sin(angle), accumulator.Cos(angle));
    cv::Point ends[2] = {p, p};
    for (int k = 0; k < 2; ++k) {
      const int du = k == 0 ? walk.du : -walk.du, dv = k == 0 ? walk.dv : -walk.dv;
      int gap = 0;
      for (int x = walk.u0, y = walk.v0;; x += du, y += dv) {
        const int u = walk.U(x), v = walk.V(y);
        if (u < 0 || u >= width || v < 0 || v >= height) break;
        const uchar s = state.at<uchar>(v, u);
        if (s == kWaiting || s == kVoted) {
          gap = 0;
          ends[k] = cv::Point(u, v);
        } else if (++gap > max_gap) {
          break;
        }
      }
    }
    const bool long_enough = std::abs(ends[1].x - ends[0].x) >= options.min_length ||
                             std::abs(ends[1].y - ends[0].y) >= options.min_length;
    // Remove the pixels on the way (their votes too, for a kept line).
    for (int k = 0; k < 2; ++k) {
      const int du = k == 0 ? walk.du : -walk.du, dv = k == 0 ? walk.dv : -walk.dv;
      for (int x = walk.u0, y = walk.v0;; x += du, y += dv) {
        const int u = walk.U(x), v = walk.V(y);
        uchar& s = state.at<uchar>(v, u);
        if (s == kVoted && long_enough) {
          accumulator.Unvote<kAvx2>(u, v, bins.at<uchar>(v, u));
          s = kNone;
        } else if (s == kVoted) {
          s = kGoneVoted;
        } else if (s == kWaiting) {
          s = kNone;
        }
        if (u == ends[k].x && v == ends[k].y) break;
      }
    }
    if (long_enough) segments->emplace_back(ends[0].x, ends[0].y, ends[1].x, ends[1].y);
  }
  // The next call starts from zero.
  accumulator.Clear();
}

void HoughBaseline(const cv::Mat& edges, const cv::Mat& dx, const cv::Mat& dy,
                   const OrientedHoughOptions& options, std::vector<cv::Vec4i>* segments) {
  HoughBody<false>(edges, dx, dy, options, segments);
}

#ifdef CORRIDOR_AVX2_VARIANTS
__attribute__((target("avx2"))) void HoughAvx2(const cv::Mat& edges, const cv::Mat& dx,
                                               const cv::Mat& dy,
                                               const OrientedHoughOptions& options,
                                               std::vector<cv::Vec4i>* segments) {
  HoughBody<true>(edges, dx, dy, options, segments);
}
#endif

}  // namespace

void OrientedHoughSegments(const cv::Mat& edges, const cv::Mat& dx, const cv::Mat& dy,
                           const OrientedHoughOptions& options, std::vector<cv::Vec4i>* segments) {
#ifdef CORRIDOR_AVX2_VARIANTS
  if (CpuHasAvx2()) return HoughAvx2(edges, dx, dy, options, segments);
#endif
  HoughBaseline(edges, dx, dy, options, segments);
}

}  // namespace corridor
