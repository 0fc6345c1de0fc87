#pragma once

// Visiting the pixels of an edge map (private header of perception).

#include <cstdint>
#include <cstring>

#include <opencv2/core.hpp>

namespace corridor {

// Bit 0 of each byte of the result is set where that byte of `word` is not zero (the shifts move
// each byte's bits down within the byte: bit 8k + s to 8k for s < 8).
inline uint64_t NonZeroBytes(uint64_t word) {
  uint64_t any = word | (word >> 4);
  any |= any >> 2;
  any |= any >> 1;
  return any & 0x0101010101010101ULL;
}

// Calls visit(u, v) for every non-zero pixel of the CV_8U map `edges`, in row-major order (as
// cv::findNonZero lists them). Edge maps are mostly empty: eight pixels (a word) at a time, and
// within a word only its non-zero bytes, without a branch per pixel.
template <typename Visit>
inline void ForEachEdgePixel(const cv::Mat& edges, Visit&& visit) {
  const int width = edges.cols;
  for (int v = 0; v < edges.rows; ++v) {
    const uchar* e = edges.ptr<uchar>(v);
    int u = 0;
    for (; u + 8 <= width; u += 8) {
      uint64_t word;
      std::memcpy(&word, e + u, 8);
      for (uint64_t set = NonZeroBytes(word); set != 0; set &= set - 1) {
        visit(u + (__builtin_ctzll(set) >> 3), v);
      }
    }
    for (; u < width; ++u) {
      if (e[u] != 0) visit(u, v);
    }
  }
}

}  // namespace corridor
