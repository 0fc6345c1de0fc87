#pragma once

// Visiting the pixels of an edge map (private header of perception).

#include <cstdint>
#include <cstring>

#include <opencv2/core.hpp>

namespace corridor {

// Calls visit(u, v) for every non-zero pixel of the CV_8U map `edges`, in row-major order (as
// cv::findNonZero lists them). Edge maps are mostly empty: eight zero bytes are skipped at once.
template <typename Visit>
inline void ForEachEdgePixel(const cv::Mat& edges, Visit&& visit) {
  const int width = edges.cols;
  for (int v = 0; v < edges.rows; ++v) {
    const uchar* e = edges.ptr<uchar>(v);
    for (int u = 0; u < width; ++u) {
      uint64_t eight = 0;
      if (u + 8 <= width && (std::memcpy(&eight, e + u, 8), eight == 0)) {
        u += 7;
        continue;
      }
      if (e[u] != 0) visit(u, v);
    }
  }
}

}  // namespace corridor
