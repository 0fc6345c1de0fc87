#include "kernels/canny_edges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "core/cpu_features.h"
#include "kernels/edge_scan.h"

#ifdef CORRIDOR_AVX2_VARIANTS
#include <immintrin.h>
#endif

namespace corridor {
namespace {

// tan(22.5 degrees) in 15-bit fixed point: the direction test compares |dy| << 15 with it.
constexpr int64_t kTan22 = 13573;
constexpr int kShift = 15;

constexpr uint32_t kMaxMagnitude = 0x7fffffff;

// The map's states, as OpenCV's: 0 a pixel that may join an edge, 1 one that cannot, 2 an edge.
constexpr uint8_t kMaybe = 0, kNever = 1, kEdge = 2;

// One row of magnitudes (|dx| + |dy|, or dx^2 + dy^2) into m[0, n), and whether each is at least
// `least` into candidate[0, n) (1 or 0); always inlined, so that the AVX2 variant below
// vectorises it.
template <bool kL2>
CORRIDOR_ALWAYS_INLINE inline void MagnitudeBody(const int16_t* dx, const int16_t* dy, int n,
                                                 uint32_t least, uint32_t* __restrict m,
                                                 uint8_t* __restrict candidate) {
  for (int j = 0; j < n; ++j) {
    const int32_t x = dx[j], y = dy[j];
    // At most 2^31 - 1 (only dx = dy = -32768 would reach 2^31): a signed 32-bit integer.
    const uint32_t magnitude =
        kL2 ? std::min(static_cast<uint32_t>(x * x) + static_cast<uint32_t>(y * y), kMaxMagnitude)
            : static_cast<uint32_t>(std::abs(x) + std::abs(y));
    m[j] = magnitude;
    candidate[j] = magnitude >= least ? 1 : 0;
  }
}

// The final image: 255 where the map says edge, 0 elsewhere.
CORRIDOR_ALWAYS_INLINE inline void EdgeRowBody(const uint8_t* map, int n, uint8_t* __restrict out) {
  for (int j = 0; j < n; ++j) out[j] = static_cast<uint8_t>(-(map[j] >> 1));
}

template <bool kL2>
void MagnitudeRow(const int16_t* dx, const int16_t* dy, int n, uint32_t least, uint32_t* m,
                  uint8_t* candidate) {
  MagnitudeBody<kL2>(dx, dy, n, least, m, candidate);
}
void EdgeRow(const uint8_t* map, int n, uint8_t* out) { EdgeRowBody(map, n, out); }

#ifdef CORRIDOR_AVX2_VARIANTS
// Sixteen pixels' magnitudes, in 32-bit lanes in the in-lane unpacks' order: *lo pixels 0-3 and
// 8-11, *hi pixels 4-7 and 12-15. L2: one multiply-add of each (x, y) pair, x^2 + y^2 <= 2^31
// read as unsigned (only dx = dy = -32768 reaches 2^31, which the cap makes 2^31 - 1). L1: |x| and
// |y| widened before they are added (|-32768| is 32768 as an unsigned 16-bit value).
template <bool kL2>
__attribute__((target("avx2"))) inline void SixteenMagnitudes(const int16_t* dx, const int16_t* dy,
                                                              __m256i* lo, __m256i* hi) {
  const __m256i x = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(dx));
  const __m256i y = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(dy));
  if constexpr (kL2) {
    const __m256i cap = _mm256_set1_epi32(static_cast<int32_t>(kMaxMagnitude));
    const __m256i pairs_lo = _mm256_unpacklo_epi16(x, y), pairs_hi = _mm256_unpackhi_epi16(x, y);
    *lo = _mm256_min_epu32(_mm256_madd_epi16(pairs_lo, pairs_lo), cap);
    *hi = _mm256_min_epu32(_mm256_madd_epi16(pairs_hi, pairs_hi), cap);
  } else {
    const __m256i zero = _mm256_setzero_si256();
    const __m256i ax = _mm256_abs_epi16(x), ay = _mm256_abs_epi16(y);
    *lo = _mm256_add_epi32(_mm256_unpacklo_epi16(ax, zero), _mm256_unpacklo_epi16(ay, zero));
    *hi = _mm256_add_epi32(_mm256_unpackhi_epi16(ax, zero), _mm256_unpackhi_epi16(ay, zero));
  }
}

// MagnitudeBody 32 pixels a step (the magnitudes stored in pixel order; the candidates' masks
// packed, whose in-lane order the packs restore), then pixel by pixel: the same values.
template <bool kL2>
__attribute__((target("avx2"))) void MagnitudeRowAvx2(const int16_t* dx, const int16_t* dy, int n,
                                                      uint32_t least, uint32_t* m,
                                                      uint8_t* candidate) {
  const __m256i least_v = _mm256_set1_epi32(static_cast<int32_t>(least));
  const __m256i one = _mm256_set1_epi8(1);
  int j = 0;
  for (; j + 32 <= n; j += 32) {
    __m256i masks[2];
    for (int half = 0; half < 2; ++half) {
      const int at = j + 16 * half;
      __m256i lo, hi;
      SixteenMagnitudes<kL2>(dx + at, dy + at, &lo, &hi);
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(m + at),
                          _mm256_permute2x128_si256(lo, hi, 0x20));
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(m + at + 8),
                          _mm256_permute2x128_si256(lo, hi, 0x31));
      // magnitude >= least, unsigned: max(magnitude, least) == magnitude.
      const __m256i at_least_lo = _mm256_cmpeq_epi32(_mm256_max_epu32(lo, least_v), lo);
      const __m256i at_least_hi = _mm256_cmpeq_epi32(_mm256_max_epu32(hi, least_v), hi);
      masks[half] = _mm256_packs_epi32(at_least_lo, at_least_hi);  // Pixels 0-15 in order.
    }
    const __m256i bytes =
        _mm256_permute4x64_epi64(_mm256_packs_epi16(masks[0], masks[1]), 0xd8);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(candidate + j), _mm256_and_si256(bytes, one));
  }
  MagnitudeBody<kL2>(dx + j, dy + j, n - j, least, m + j, candidate + j);
}
__attribute__((target("avx2"))) void EdgeRowAvx2(const uint8_t* map, int n, uint8_t* out) {
  EdgeRowBody(map, n, out);
}
#endif

using MagnitudeFn = void (*)(const int16_t*, const int16_t*, int, uint32_t, uint32_t*, uint8_t*);
using EdgeRowFn = void (*)(const uint8_t*, int, uint8_t*);

// The threshold a magnitude must exceed: OpenCV squares the L2 ones (after capping them at 32767)
// and floors both, so that "m > threshold" holds for the same integer magnitudes (in [-1, 2^31]).
int64_t IntegerThreshold(double t, bool l2) {
  if (l2) {
    t = std::min(32767.0, t);
    if (t > 0) t *= t;
  }
  return static_cast<int64_t>(std::clamp(std::floor(t), -1.0, 2147483648.0));
}

// Whether pixel j of the middle row (magnitude m, derivatives x, y) is a maximum along its
// gradient: against its left and right neighbours for a gradient within 22.5 degrees of
// horizontal, above and below within 22.5 degrees of vertical, and the diagonal neighbours
// otherwise. Ties go to the pixel after (right, below) as OpenCV's; diagonals keep no tie.
inline bool IsMaximum(uint32_t m, int16_t x, int16_t y, const uint32_t* above,
                      const uint32_t* centre, const uint32_t* below, int j) {
  const int64_t ax = std::abs(static_cast<int64_t>(x));
  const int64_t ay = std::abs(static_cast<int64_t>(y)) << kShift;
  const int64_t tan22x = ax * kTan22;
  if (ay < tan22x) return m > centre[j - 1] && m >= centre[j + 1];
  const int64_t tan67x = tan22x + (ax << (kShift + 1));
  if (ay > tan67x) return m > above[j] && m >= below[j];
  const int s = (x ^ y) < 0 ? -1 : 1;
  return m > above[j - s] && m > below[j + s];
}

// The rows around the one being suppressed: magnitudes above, at and below it (each readable
// one pixel before the image's and eight after), its derivatives, and which of its pixels
// exceed the low threshold (candidate[j] = 1, else 0).
struct RowView {
  const uint32_t* above;
  const uint32_t* centre;
  const uint32_t* below;
  const int16_t* x;
  const int16_t* y;
  const uint8_t* candidate;
};

// Pixel j of the row, a candidate and a maximum: into the map as an edge (pushed on the stack)
// when above `high`, as a maybe otherwise.
inline void Keep(uint32_t m, int64_t high, int at, uint8_t* map, std::vector<int>* stack) {
  if (static_cast<int64_t>(m) > high) {
    map[at] = kEdge;
    stack->push_back(at);
  } else {
    map[at] = kMaybe;
  }
}

// Non-maximum suppression of the candidates of pixels [from, cols), one at a time; `base` is
// pixel 0's index in the map.
void SuppressRow(const RowView& r, int from, int cols, int64_t high, int base, uint8_t* map,
                 std::vector<int>* stack) {
  ForEachNonZeroByte(r.candidate, from, cols, [&](int j) {
    const uint32_t m = r.centre[j];
    if (IsMaximum(m, r.x[j], r.y[j], r.above, r.centre, r.below, j)) {
      Keep(m, high, base + j, map, stack);
    }
  });
}

#ifdef CORRIDOR_AVX2_VARIANTS
__attribute__((target("avx2"))) inline __m256i Load(const uint32_t* p) {
  return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
}

// Eight 16-bit values widened to 32 bits.
__attribute__((target("avx2"))) inline __m256i LoadWidened(const int16_t* p) {
  return _mm256_cvtepi16_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)));
}

// m > a && m >= b, lane by lane, as masks.
__attribute__((target("avx2"))) inline __m256i GreaterThenAtLeast(__m256i m, __m256i a, __m256i b) {
  return _mm256_andnot_si256(_mm256_cmpgt_epi32(b, m), _mm256_cmpgt_epi32(m, a));
}

// The same, eight pixels a step in AVX2 registers with IsMaximum's tests (32-bit: |dy| << 15 and
// |dx| * tan22 fit; |dx| << 16 is taken of min(|dx|, 32767), which changes no comparison), then
// the remaining pixels one at a time.
__attribute__((target("avx2"))) void SuppressRowAvx2(const RowView& r, int cols, int64_t low,
                                                     int64_t high, int base, uint8_t* map,
                                                     std::vector<int>* stack) {
  const __m256i low_v =
      _mm256_set1_epi32(static_cast<int32_t>(std::min<int64_t>(low, kMaxMagnitude)));
  const __m256i high_v =
      _mm256_set1_epi32(static_cast<int32_t>(std::min<int64_t>(high, kMaxMagnitude)));
  const __m256i tan22 = _mm256_set1_epi32(static_cast<int32_t>(kTan22));
  const __m256i max_dx = _mm256_set1_epi32(32767), zero = _mm256_setzero_si256();
  int j = 0;
  for (; j + 8 <= cols; j += 8) {
    uint64_t word;
    std::memcpy(&word, r.candidate + j, 8);
    if (word == 0) continue;
    const __m256i m = Load(r.centre + j);
    const __m256i x = LoadWidened(r.x + j);
    const __m256i y = LoadWidened(r.y + j);
    const __m256i ax = _mm256_abs_epi32(x);
    const __m256i ay = _mm256_slli_epi32(_mm256_abs_epi32(y), kShift);
    const __m256i tan22x = _mm256_mullo_epi32(ax, tan22);
    const __m256i horizontal = _mm256_cmpgt_epi32(tan22x, ay);  // ay < tan22x
    const __m256i ax_high = _mm256_slli_epi32(_mm256_min_epi32(ax, max_dx), kShift + 1);
    const __m256i vertical = _mm256_andnot_si256(
        horizontal, _mm256_cmpgt_epi32(_mm256_sub_epi32(ay, tan22x), ax_high));
    const __m256i along_row =
        GreaterThenAtLeast(m, Load(r.centre + j - 1), Load(r.centre + j + 1));
    const __m256i along_column = GreaterThenAtLeast(m, Load(r.above + j), Load(r.below + j));
    // Diagonals: s = -1 where dx and dy differ in sign (above right, below left), else +1.
    const __m256i opposite = _mm256_cmpgt_epi32(zero, _mm256_xor_si256(x, y));
    const __m256i diagonal_above =
        _mm256_blendv_epi8(Load(r.above + j - 1), Load(r.above + j + 1), opposite);
    const __m256i diagonal_below =
        _mm256_blendv_epi8(Load(r.below + j + 1), Load(r.below + j - 1), opposite);
    const __m256i diagonal = _mm256_and_si256(_mm256_cmpgt_epi32(m, diagonal_above),
                                              _mm256_cmpgt_epi32(m, diagonal_below));
    const __m256i maximum = _mm256_blendv_epi8(
        _mm256_blendv_epi8(diagonal, along_column, vertical), along_row, horizontal);
    const __m256i kept = _mm256_and_si256(maximum, _mm256_cmpgt_epi32(m, low_v));
    int kept_bits = _mm256_movemask_ps(_mm256_castsi256_ps(kept));
    if (kept_bits == 0) continue;
    int strong_bits = _mm256_movemask_ps(
        _mm256_castsi256_ps(_mm256_and_si256(kept, _mm256_cmpgt_epi32(m, high_v))));
    // Every kept pixel a maybe, then the strong ones (a subset) edges: no branch on which is which.
    for (; kept_bits != 0; kept_bits &= kept_bits - 1) {
      map[base + j + __builtin_ctz(kept_bits)] = kMaybe;
    }
    for (; strong_bits != 0; strong_bits &= strong_bits - 1) {
      const int at = base + j + __builtin_ctz(strong_bits);
      map[at] = kEdge;
      stack->push_back(at);
    }
  }
  SuppressRow(r, j, cols, high, base, map, stack);
}
#endif

// Bit 8k set (k < 3) where byte k of the four at `p` (little-endian) is not kMaybe (the map holds
// only 0, 1 and 2, so a byte's two low bits OR-ed say so; the fourth byte is not looked at).
inline uint32_t NotMaybe(const uint8_t* p) {
  uint32_t word;
  std::memcpy(&word, p, 4);
  return (word | (word >> 1)) & 0x010101u;
}

// CannyFromGradients' working memory.
struct CannyScratch {
  std::vector<uint32_t> ring;
  std::vector<uint8_t> candidates, map;
  std::vector<int> stack;
};

}  // namespace

Status CannyFromGradients(const cv::Mat& dx, const cv::Mat& dy, double low, double high, bool l2,
                          cv::Mat* edges) {
  if (dx.empty() || dx.type() != CV_16SC1 || dy.type() != CV_16SC1 || dx.size() != dy.size()) {
    return Status::InvalidArgument("Canny: dx and dy must be non-empty CV_16SC1 of one size");
  }
  if (low > high) std::swap(low, high);
  const int64_t low_m = IntegerThreshold(low, l2), high_m = IntegerThreshold(high, l2);
  const int rows = dx.rows, cols = dx.cols, step = cols + 2;

  MagnitudeFn magnitude = l2 ? MagnitudeRow<true> : MagnitudeRow<false>;
  EdgeRowFn edge_row = EdgeRow;
#ifdef CORRIDOR_AVX2_VARIANTS
  const bool avx2 = CpuHasAvx2();
  if (avx2) {
    magnitude = l2 ? MagnitudeRowAvx2<true> : MagnitudeRowAvx2<false>;
    edge_row = EdgeRowAvx2;
  }
#endif

  // Three rows of magnitudes, each with a zero before and eight after (the last pixel's
  // neighbours in a register); a row outside the image is zero. Beside them, the centre and next
  // rows' candidates (magnitude above `low`).
  // The buffers are the thread's, reused from call to call (each filled here as if new).
  thread_local CannyScratch thread_scratch;
  CannyScratch& scratch = thread_scratch;
  const int ring_step = cols + 9;
  std::vector<uint32_t>& ring = scratch.ring;
  ring.assign(3 * static_cast<size_t>(ring_step), 0);
  uint32_t* row_mag[3] = {ring.data() + 1, ring.data() + ring_step + 1,
                          ring.data() + 2 * ring_step + 1};
  std::vector<uint8_t>& candidates = scratch.candidates;
  candidates.assign(2 * static_cast<size_t>(cols), 0);
  uint8_t* row_candidate[2] = {candidates.data(), candidates.data() + cols};
  const uint32_t least = static_cast<uint32_t>(low_m + 1);
  // The map has a border of kNever around the image, so that hysteresis stops there.
  std::vector<uint8_t>& map = scratch.map;
  // The border rows now, each image row (with its border columns) just before it is suppressed:
  // every cell is kNever until a candidate is marked. (Row by row instead of one fill of the
  // whole map up front: the same bytes, written while the row is in the cache.)
  // The buffer only grows: a resize up after a smaller image's call would zero the bytes added,
  // which are all written here anyway.
  const size_t map_size = static_cast<size_t>(rows + 2) * step;
  // One byte more: NotMaybe reads four bytes from the last pixel's lower left neighbour.
  if (map.size() < map_size + 1) map.resize(map_size + 1);
  std::fill(map.data(), map.data() + step, kNever);
  std::fill(map.data() + map_size - step, map.data() + map_size, kNever);
  // The stack in a local vector (the scratch's memory, given back at the end), so that the
  // hysteresis loop keeps it in registers rather than reading the thread's storage each time.
  std::vector<int> stack;
  stack.swap(scratch.stack);
  stack.clear();
  stack.reserve(1024);

  magnitude(dx.ptr<int16_t>(0), dy.ptr<int16_t>(0), cols, least, row_mag[1], row_candidate[0]);
  for (int i = 0; i < rows; ++i) {
    uint32_t* above = row_mag[0];
    uint32_t* centre = row_mag[1];
    uint32_t* below = row_mag[2];
    if (i + 1 < rows) {
      magnitude(dx.ptr<int16_t>(i + 1), dy.ptr<int16_t>(i + 1), cols, least, below,
                row_candidate[1]);
    } else {
      std::fill(below, below + cols, 0u);
    }
    const RowView view{above, centre, below, dx.ptr<int16_t>(i), dy.ptr<int16_t>(i),
                       row_candidate[0]};
    const int base = (i + 1) * step + 1;
    std::fill(map.data() + base - 1, map.data() + base - 1 + step, kNever);
#ifdef CORRIDOR_AVX2_VARIANTS
    if (avx2) {
      SuppressRowAvx2(view, cols, low_m, high_m, base, map.data(), &stack);
    } else {
      SuppressRow(view, 0, cols, high_m, base, map.data(), &stack);
    }
#else
    SuppressRow(view, 0, cols, high_m, base, map.data(), &stack);
#endif
    // Scroll: the centre row becomes the one above, the row below the centre.
    row_mag[0] = centre;
    row_mag[1] = below;
    row_mag[2] = above;
    std::swap(row_candidate[0], row_candidate[1]);
  }

  // Hysteresis: every candidate 8-connected to an edge becomes one.
  const int neighbours[8] = {-1, 1, -step - 1, -step, -step + 1, step - 1, step, step + 1};
  uint8_t* const cells = map.data();
  while (!stack.empty()) {
    const int p = stack.back();
    stack.pop_back();
    // Most edge pixels have no maybe among their eight neighbours: tested for the three rows'
    // three bytes at once.
    if ((NotMaybe(cells + p - step - 1) & NotMaybe(cells + p - 1) &
         NotMaybe(cells + p + step - 1)) == 0x010101u) {
      continue;
    }
    for (int d : neighbours) {
      if (cells[p + d] == kMaybe) {
        cells[p + d] = kEdge;
        stack.push_back(p + d);
      }
    }
  }

  stack.swap(scratch.stack);
  edges->create(rows, cols, CV_8UC1);
  for (int i = 0; i < rows; ++i) {
    edge_row(map.data() + (i + 1) * step + 1, cols, edges->ptr<uint8_t>(i));
  }
  return Status::Ok();
}

}  // namespace corridor
