#pragma once

// Visiting the pixels of an edge map (private header of perception).

#include <cstdint>
#include <cstring>

#include <opencv2/core.hpp>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace corridor {

// Bit 0 of each byte of the result is set where that byte of `word` is not zero (the shifts move
// each byte's bits down within the byte: bit 8k + s to 8k for s < 8).
inline uint64_t NonZeroBytes(uint64_t word) {
  uint64_t any = word | (word >> 4);
  any |= any >> 2;
  any |= any >> 1;
  return any & 0x0101010101010101ULL;
}

// Calls visit(u) for every u in [begin, end) where row[u] is not zero, in increasing order:
// sixteen bytes at a time with SSE2 (a compare with zero and its bit mask), then eight (a word),
// and within those only the non-zero bytes, without a branch per byte.
template <typename Visit>
inline void ForEachNonZeroByte(const uchar* row, int begin, int end, Visit&& visit) {
  int u = begin;
#ifdef __SSE2__
  const __m128i zero = _mm_setzero_si128();
  for (; u + 16 <= end; u += 16) {
    const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + u));
    for (unsigned set = ~static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(bytes, zero))) &
                        0xffffu;
         set != 0; set &= set - 1) {
      visit(u + __builtin_ctz(set));
    }
  }
#endif
  for (; u + 8 <= end; u += 8) {
    uint64_t word;
    std::memcpy(&word, row + u, 8);
    for (uint64_t set = NonZeroBytes(word); set != 0; set &= set - 1) {
      visit(u + (__builtin_ctzll(set) >> 3));
    }
  }
  for (; u < end; ++u) {
    if (row[u] != 0) visit(u);
  }
}

// Calls visit(u, v) for every non-zero pixel of the CV_8U map `edges`, in row-major order (as
// cv::findNonZero lists them). Edge maps are mostly empty: ForEachNonZeroByte along each row.
template <typename Visit>
inline void ForEachEdgePixel(const cv::Mat& edges, Visit&& visit) {
  for (int v = 0; v < edges.rows; ++v) {
    ForEachNonZeroByte(edges.ptr<uchar>(v), 0, edges.cols, [&](int u) { visit(u, v); });
  }
}

}  // namespace corridor
