#include "perception/canny_edges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "core/cpu_features.h"

namespace corridor {
namespace {

// tan(22.5 degrees) in 15-bit fixed point: the direction test compares |dy| << 15 with it.
constexpr int64_t kTan22 = 13573;
constexpr int kShift = 15;

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
    const uint32_t magnitude = kL2 ? static_cast<uint32_t>(x * x) + static_cast<uint32_t>(y * y)
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
template <bool kL2>
__attribute__((target("avx2"))) void MagnitudeRowAvx2(const int16_t* dx, const int16_t* dy, int n,
                                                      uint32_t least, uint32_t* m,
                                                      uint8_t* candidate) {
  MagnitudeBody<kL2>(dx, dy, n, least, m, candidate);
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
  if (CpuHasAvx2()) {
    magnitude = l2 ? MagnitudeRowAvx2<true> : MagnitudeRowAvx2<false>;
    edge_row = EdgeRowAvx2;
  }
#endif

  // Three rows of magnitudes, each with a zero before and after; a row outside the image is zero.
  // Beside them, the centre and next rows' candidates (magnitude above `low`), padded to whole
  // words of 8 so that the scan below reads 8 at a time.
  std::vector<uint32_t> ring(3 * static_cast<size_t>(step), 0);
  uint32_t* row_mag[3] = {ring.data() + 1, ring.data() + step + 1, ring.data() + 2 * step + 1};
  const int words = (cols + 7) / 8;
  std::vector<uint8_t> candidates(2 * 8 * static_cast<size_t>(words), 0);
  uint8_t* row_candidate[2] = {candidates.data(), candidates.data() + 8 * words};
  const uint32_t least = static_cast<uint32_t>(low_m + 1);
  // The map has a border of kNever around the image, so that hysteresis stops there.
  std::vector<uint8_t> map(static_cast<size_t>(rows + 2) * step, kNever);
  std::vector<int> stack;
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
    const int16_t* x = dx.ptr<int16_t>(i);
    const int16_t* y = dy.ptr<int16_t>(i);
    const int base = (i + 1) * step + 1;
    const uint8_t* candidate = row_candidate[0];
    for (int w = 0; w < words; ++w) {
      uint64_t word;
      std::memcpy(&word, candidate + 8 * w, 8);
      for (; word != 0; word &= word - 1) {
        const int j = 8 * w + (__builtin_ctzll(word) >> 3);
        const uint32_t m = centre[j];
        if (!IsMaximum(m, x[j], y[j], above, centre, below, j)) continue;
        if (static_cast<int64_t>(m) > high_m) {
          map[base + j] = kEdge;
          stack.push_back(base + j);
        } else {
          map[base + j] = kMaybe;
        }
      }
    }
    // Scroll: the centre row becomes the one above, the row below the centre.
    row_mag[0] = centre;
    row_mag[1] = below;
    row_mag[2] = above;
    std::swap(row_candidate[0], row_candidate[1]);
  }

  // Hysteresis: every candidate 8-connected to an edge becomes one.
  const int neighbours[8] = {-1, 1, -step - 1, -step, -step + 1, step - 1, step, step + 1};
  while (!stack.empty()) {
    const int p = stack.back();
    stack.pop_back();
    for (int d : neighbours) {
      if (map[p + d] == kMaybe) {
        map[p + d] = kEdge;
        stack.push_back(p + d);
      }
    }
  }

  edges->create(rows, cols, CV_8UC1);
  for (int i = 0; i < rows; ++i) {
    edge_row(map.data() + (i + 1) * step + 1, cols, edges->ptr<uint8_t>(i));
  }
  return Status::Ok();
}

}  // namespace corridor
