#include "kernels/max_filter.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#ifdef __x86_64__
#include <immintrin.h>
#endif

#include "core/cpu_features.h"

namespace corridor {
namespace {

// The largest reach the unrolled filters take; wider windows go through the generic one (R = 0,
// the reach read at run time).
constexpr int kMaxUnrolled = 5;

#ifdef CORRIDOR_AVX2_VARIANTS
// MaxAcrossBody's loop 32 columns a step, for to - from >= 32.
template <int kCount>
__attribute__((target("avx2"))) void MaxAcross32(const uint8_t* const* p, int count, int from,
                                                 int to, uint8_t* out) {
  const int n = kCount > 0 ? kCount : count;
  int c = from;
  for (bool last = false; !last; c += 32) {
    if (c + 32 > to) c = to - 32, last = true;  // The last 32, overlapping those done.
    __m256i m = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p[0] + c));
    for (int i = 1; i < n; ++i) {
      m = _mm256_max_epu8(m, _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p[i] + c)));
    }
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + c), m);
    last = last || c + 32 == to;
  }
}
#endif

// out[c] = the largest of p[0][c], .., p[count - 1][c] for c in [from, to), sixteen columns a step
// with SSE2 (32 with AVX2 when kAvx2); kCount: the count when not zero (then the row pointers are
// held in registers, not reloaded after each store).
template <int kCount, bool kAvx2>
CORRIDOR_ALWAYS_INLINE inline void MaxAcrossBody(const uint8_t* const* rows, int count, int from,
                                                 int to, uint8_t* out) {
  const int n = kCount > 0 ? kCount : count;
  const uint8_t* fixed[kCount > 0 ? kCount : 1];
  const uint8_t* const* p = rows;
  if constexpr (kCount > 0) {
    for (int i = 0; i < kCount; ++i) fixed[i] = rows[i];
    p = fixed;
  }
  int c = from;
#ifdef CORRIDOR_AVX2_VARIANTS
  if constexpr (kAvx2) {
    if (to - from >= 32) return MaxAcross32<kCount>(p, n, from, to, out);
  }
#endif
#ifdef __SSE2__
  if (to - from >= 16) {
    for (bool last = false; !last; c += 16) {
      if (c + 16 > to) c = to - 16, last = true;  // The last sixteen, overlapping those done.
      __m128i m = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p[0] + c));
      for (int i = 1; i < n; ++i) {
        m = _mm_max_epu8(m, _mm_loadu_si128(reinterpret_cast<const __m128i*>(p[i] + c)));
      }
      _mm_storeu_si128(reinterpret_cast<__m128i*>(out + c), m);
      last = last || c + 16 == to;
    }
    return;
  }
#endif
  for (; c < to; ++c) {
    uint8_t m = p[0][c];
    for (int i = 1; i < n; ++i) m = std::max(m, p[i][c]);
    out[c] = m;
  }
}

template <int kCount>
void MaxAcross(const uint8_t* const* rows, int count, int from, int to, uint8_t* out) {
  MaxAcrossBody<kCount, false>(rows, count, from, to, out);
}

#ifdef CORRIDOR_AVX2_VARIANTS
template <int kCount>
__attribute__((target("avx2"))) void MaxAcrossAvx2(const uint8_t* const* rows, int count,
                                                   int from, int to, uint8_t* out) {
  MaxAcrossBody<kCount, true>(rows, count, from, to, out);
}
#endif

using MaxAcrossFn = void (*)(const uint8_t* const*, int, int, int, uint8_t*);

template <int kCount>
MaxAcrossFn ChooseMaxAcross() {
#ifdef CORRIDOR_AVX2_VARIANTS
  if (CpuHasAvx2()) return MaxAcrossAvx2<kCount>;
#endif
  return MaxAcross<kCount>;
}

// row_max[c] = the largest of row[c - reach .. c + reach] inside [0, cols). kReach: the reach
// when not zero.
template <int kReach>
void RowMax(const uint8_t* row, int cols, int reach_at_run_time, MaxAcrossFn max_across,
            uint8_t* row_max) {
  const int reach = kReach > 0 ? kReach : reach_at_run_time;
  const int inner_from = std::min(reach, cols), inner_to = std::max(inner_from, cols - reach);
  for (int u = 0; u < inner_from; ++u) {  // Left end: the window is cut by the border.
    uint8_t m = 0;
    for (int k = 0; k <= std::min(cols - 1, u + reach); ++k) m = std::max(m, row[k]);
    row_max[u] = m;
  }
  // Interior: whole windows, the row shifted by each offset (to the window's start).
  const uint8_t* shifted[2 * kMaxUnrolled + 1];
  std::vector<const uint8_t*> wide;
  const uint8_t** p = shifted;
  if (reach > kMaxUnrolled) {
    wide.resize(2 * reach + 1);
    p = wide.data();
  }
  for (int k = 0; k <= 2 * reach; ++k) p[k] = row + k - reach;
  max_across(p, 2 * reach + 1, inner_from, inner_to, row_max);
  for (int u = std::max(inner_to, inner_from); u < cols; ++u) {  // Right end.
    uint8_t m = 0;
    for (int k = std::max(0, u - reach); k < cols; ++k) m = std::max(m, row[k]);
    row_max[u] = m;
  }
}

template <int kReach>
void Filter(const cv::Mat& source, int reach_at_run_time, cv::Mat* out) {
  const int reach = kReach > 0 ? kReach : reach_at_run_time;
  const int rows = source.rows, cols = source.cols;
  // Each row's maxima along it, in the thread's ring of 2 reach + 1 rows (reused from call to
  // call); then each output row is the largest of the rows' maxima within reach.
  const int window = 2 * reach + 1;
  const size_t stride = static_cast<size_t>(cols);
  thread_local std::vector<uint8_t> thread_ring;
  std::vector<uint8_t>& ring = thread_ring;
  ring.resize(static_cast<size_t>(window) * stride);
  const auto ring_row = [&](int r) {
    return ring.data() + static_cast<size_t>(r % window) * stride;
  };
  thread_local std::vector<const uint8_t*> thread_in_reach;  // The rows' maxima within reach.
  std::vector<const uint8_t*>& in_reach = thread_in_reach;
  in_reach.resize(window);
  constexpr int kWindow = kReach > 0 ? 2 * kReach + 1 : 0;
  const MaxAcrossFn max_across = ChooseMaxAcross<kWindow>();
  const MaxAcrossFn max_across_cut = ChooseMaxAcross<0>();  // Near the top and bottom.
  for (int r = 0; r < std::min(reach, rows); ++r) {
    RowMax<kReach>(source.ptr<uint8_t>(r), cols, reach, max_across, ring_row(r));
  }
  for (int r = 0; r < rows; ++r) {
    const int below = r + reach;
    if (below < rows) {
      RowMax<kReach>(source.ptr<uint8_t>(below), cols, reach, max_across, ring_row(below));
    }
    const int from = std::max(0, r - reach), to = std::min(rows - 1, r + reach);
    const int count = to - from + 1;
    for (int s = from; s <= to; ++s) in_reach[s - from] = ring_row(s);
    uint8_t* o = out->ptr<uint8_t>(r);
    (count == window ? max_across : max_across_cut)(in_reach.data(), count, 0, cols, o);
  }
}

}  // namespace

void MaxFilterSquare(const cv::Mat& image, int reach, cv::Mat* out) {
  CV_Assert(image.type() == CV_8UC1 && reach >= 0);
  const cv::Mat source = image;  // Keeps the pixels (`image` may be *out itself).
  if (out->datastart == source.datastart) *out = cv::Mat();
  out->create(source.rows, source.cols, CV_8UC1);
  if (source.empty()) return;
  switch (reach) {
    case 1:
      return Filter<1>(source, reach, out);
    case 2:
      return Filter<2>(source, reach, out);
    case 3:
      return Filter<3>(source, reach, out);
    default:
      return Filter<0>(source, reach, out);
  }
}

}  // namespace corridor
