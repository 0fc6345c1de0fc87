#include "perception/oriented_edges.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#ifdef __x86_64__
#include <immintrin.h>
#endif

#include "core/cpu_features.h"

#include "kernels/binomial_blur.h"
#include "kernels/canny_edges.h"
#include "kernels/color_gradient.h"
#include "kernels/edge_scan.h"

namespace corridor {
namespace {

// Rows of edges computed beyond the band, for the blur and Canny's gradients and hysteresis.
constexpr int kBandMargin = 8;
// Rows a cache of edges reaches below the band that filled it, in hundredths of the image's
// height: a later search of the frame, with the walls moved, reaches a little farther down.
constexpr int kCacheSlackPercent = 4;

// The OR of three bytes across (a[u - 1] | a[u] | a[u + 1]) for u in [from, cols - 1), 16 at a
// time where SSE2 is there; returns the first u not done.
inline int OrAcross(const uchar* a, int from, int cols, uchar* out) {
  int u = from;
#ifdef __SSE2__
  for (; u + 17 <= cols; u += 16) {
    const __m128i left = _mm_loadu_si128(reinterpret_cast<const __m128i*>(a + u - 1));
    const __m128i mid = _mm_loadu_si128(reinterpret_cast<const __m128i*>(a + u));
    const __m128i right = _mm_loadu_si128(reinterpret_cast<const __m128i*>(a + u + 1));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + u),
                     _mm_or_si128(_mm_or_si128(left, mid), right));
  }
#endif
  for (; u + 1 < cols; ++u) out[u] = static_cast<uchar>(a[u - 1] | a[u] | a[u + 1]);
  return u;
}

// out[u] = a[u] | b[u] | c[u] for u in [from, cols), 16 at a time where SSE2 is there.
inline void OrDown(const uchar* a, const uchar* b, const uchar* c, int from, int cols,
                   uchar* out) {
  int u = from;
#ifdef __SSE2__
  for (; u + 16 <= cols; u += 16) {
    const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(a + u));
    const __m128i y = _mm_loadu_si128(reinterpret_cast<const __m128i*>(b + u));
    const __m128i z = _mm_loadu_si128(reinterpret_cast<const __m128i*>(c + u));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + u), _mm_or_si128(_mm_or_si128(x, y), z));
  }
#endif
  for (; u < cols; ++u) out[u] = static_cast<uchar>(a[u] | b[u] | c[u]);
}

#ifdef CORRIDOR_AVX2_VARIANTS
// OrAcross and OrDown 32 bytes at a time, the rest as they do: the same bytes.
__attribute__((target("avx2"))) int OrAcrossAvx2(const uchar* a, int cols, uchar* out) {
  int u = 1;
  for (; u + 33 <= cols; u += 32) {
    const __m256i left = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a + u - 1));
    const __m256i mid = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a + u));
    const __m256i right = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a + u + 1));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + u),
                        _mm256_or_si256(_mm256_or_si256(left, mid), right));
  }
  return OrAcross(a, u, cols, out);
}
__attribute__((target("avx2"))) void OrDownAvx2(const uchar* a, const uchar* b, const uchar* c,
                                                int cols, uchar* out) {
  int u = 0;
  for (; u + 32 <= cols; u += 32) {
    const __m256i x = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a + u));
    const __m256i y = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(b + u));
    const __m256i z = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(c + u));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + u),
                        _mm256_or_si256(_mm256_or_si256(x, y), z));
  }
  OrDown(a, b, c, u, cols, out);
}
#endif

// out(r, u) = the OR of bits over the 3x3 pixels around (r, u) inside the image: the OR of three
// neighbours along each row, then of three such rows. `along` is scratch.
void OrNeighbourhoods(const cv::Mat& bits, std::vector<uchar>* along_rows, cv::Mat* out) {
  const int rows = bits.rows, cols = bits.cols;
  const size_t stride = static_cast<size_t>(cols);
#ifdef CORRIDOR_AVX2_VARIANTS
  const bool avx2 = CpuHasAvx2();
#endif
  // A zero row each end; every other byte is written below.
  along_rows->resize((rows + 2) * stride);
  uchar* along = along_rows->data();
  std::fill(along, along + stride, 0);
  std::fill(along + (rows + 1) * stride, along + (rows + 2) * stride, 0);
  for (int r = 0; r < rows; ++r) {
    const uchar* b = bits.ptr<uchar>(r);
    uchar* h = along + (r + 1) * stride;
    h[0] = static_cast<uchar>(b[0] | (cols > 1 ? b[1] : 0));
#ifdef CORRIDOR_AVX2_VARIANTS
    if (avx2) {
      OrAcrossAvx2(b, cols, h);
    } else {
      OrAcross(b, 1, cols, h);
    }
#else
    OrAcross(b, 1, cols, h);
#endif
    if (cols > 1) h[cols - 1] = static_cast<uchar>(b[cols - 2] | b[cols - 1]);
  }
  for (int r = 0; r < rows; ++r) {
    const uchar* above = along + r * stride;
    uchar* o = out->ptr<uchar>(r);
#ifdef CORRIDOR_AVX2_VARIANTS
    if (avx2) {
      OrDownAvx2(above, above + stride, above + 2 * stride, cols, o);
      continue;
    }
#endif
    OrDown(above, above + stride, above + 2 * stride, 0, cols, o);
  }
}

// OrientationBin, inlined into the band loop below.
CORRIDOR_ALWAYS_INLINE inline int Bin(int gx, int gy) {
  // Turned into [0, 180] degrees: an edge and its reverse are the same edge (gy = 0 with gx < 0
  // stays at 180 degrees, the last bin, as atan2 puts it). In double: no integer overflow.
  const double flip = gy < 0 ? -1.0 : 1.0;
  const double x = flip * gx, y = flip * gy, ax = std::abs(x);
  // The bin edges' tangents: tan(22.5 deg) = sqrt(2) - 1, tan(67.5 deg) = sqrt(2) + 1; at 45 and
  // 135 degrees the comparison is exact (integers in double). Both halves are counted and one
  // selected, without branches (edge orientations do not follow a pattern a branch predictor
  // could learn): right of vertical, the edges y crosses; left of it, 7 less those y exceeds.
  constexpr double kTan22 = 0.41421356237309504880, kTan67 = 2.41421356237309504880;
  const int right = (y >= kTan22 * ax) + (y >= ax) + (y >= kTan67 * ax);
  const int left = 7 - (y > kTan22 * ax) - (y > ax) - (y > kTan67 * ax);
  const int vertical = y == 0 ? 0 : 4;
  return x > 0 ? right : (x < 0 ? left : vertical);
}

// ColorCannyEdges' Canny thresholds on the colour gradient (and its extension's, which must give
// the same edges).
constexpr double kColorCannyLow = 20, kColorCannyHigh = 60;

}  // namespace

int OrientationBin(int gx, int gy) { return Bin(gx, gy); }

bool ColorCannyEdges(const cv::Mat& bgr, int from, int to, cv::Mat* dx, cv::Mat* dy,
                     cv::Mat* edges, cv::Mat* smooth) {
  cv::Mat own;
  cv::Mat& blurred = smooth != nullptr ? *smooth : own;
  if (!BinomialBlur(bgr, from, to, 5, &blurred).ok()) return false;
  ColorGradient(blurred, dx, dy, nullptr);
  return CannyFromGradients(*dx, *dy, kColorCannyLow, kColorCannyHigh, true, edges).ok();
}

bool ImageEdges::Covers(const cv::Mat& image, int bottom) const {
  if (edges.empty() || image_rows != image.rows || edges.cols != image.cols ||
      dx.size() != edges.size() || dy.size() != edges.size()) {
    return false;
  }
  return edges.rows == image.rows || bottom + kBandMargin <= edges.rows;
}

namespace {

// The image's rows [0, to) into *out; false (and *out empty) as ColorCannyEdges.
bool EdgesFromTop(const cv::Mat& bgr, int to, ImageEdges* out) {
  *out = ImageEdges();
  if (!bgr.empty() && to > 0 && to < bgr.rows) {
    // Room for every row of the image: an extension down (ExtendEdgesDown) writes in place.
    out->smooth.create(bgr.rows, bgr.cols, bgr.type());
    out->dx.create(bgr.rows, bgr.cols, CV_16S);
    out->dy.create(bgr.rows, bgr.cols, CV_16S);
    out->smooth = out->smooth.rowRange(0, to);
    out->dx = out->dx.rowRange(0, to);
    out->dy = out->dy.rowRange(0, to);
  }
  if (bgr.empty() || !ColorCannyEdges(bgr, 0, to, &out->dx, &out->dy, &out->edges, &out->smooth)) {
    *out = ImageEdges();
    return false;
  }
  out->image_rows = bgr.rows;
  return true;
}

// Makes *m, rows at the top of a larger matrix, `extra` rows longer; false when the matrix it is
// part of has no such rows.
bool GrowDown(int extra, cv::Mat* m) {
  cv::Size whole;
  cv::Point offset;
  m->locateROI(whole, offset);
  if (offset.x != 0 || whole.width != m->cols || offset.y + m->rows + extra > whole.height) {
    return false;
  }
  m->adjustROI(0, extra, 0, 0);
  return true;
}

// Extends *cache, the image's rows [0, from) (EdgesFromTop), to rows [0, to): the same edges as
// EdgesFromTop(bgr, to, cache), without blurring the rows it has again or taking their gradient
// again. The blurred rows read the image's rows around them (they are the same at any `to`), and
// so does each gradient row but the last, whose row below was a reflection: the rows from `from`
// are blurred and the gradient of those from from - 1 taken, into the room below the rows had
// (EdgesFromTop's matrices have it); Canny runs over all of them, its hysteresis joining edges
// across rows, into a new matrix (views of the old edges stay valid). False (*cache untouched)
// when the cache is not such rows of this image, or `to` is not below them.
bool ExtendEdgesDown(const cv::Mat& bgr, int to, ImageEdges* cache) {
  const int from = cache->edges.rows;
  if (from < 2 || to <= from || to > bgr.rows || cache->image_rows != bgr.rows ||
      cache->edges.cols != bgr.cols || cache->smooth.rows != from ||
      cache->smooth.cols != bgr.cols || cache->smooth.type() != bgr.type() ||
      cache->dx.rows != from || cache->dy.rows != from) {
    return false;
  }
  cv::Mat smooth = cache->smooth, dx = cache->dx, dy = cache->dy;
  if (!GrowDown(to - from, &smooth) || !GrowDown(to - from, &dx) || !GrowDown(to - from, &dy)) {
    return false;
  }
  cv::Mat more = smooth.rowRange(from, to);
  const uchar* const room = more.data;
  if (!BinomialBlur(bgr, from, to, 5, &more).ok()) return false;
  if (more.data != room) more.copyTo(smooth.rowRange(from, to));  // Not in place: copied.
  // The gradient of rows [from - 2, to) taken alone: its first row (a reflection above) dropped.
  cv::Mat gx, gy;
  ColorGradient(smooth.rowRange(from - 2, to), &gx, &gy, nullptr);
  gx.rowRange(1, gx.rows).copyTo(dx.rowRange(from - 1, to));
  gy.rowRange(1, gy.rows).copyTo(dy.rowRange(from - 1, to));
  cv::Mat edges;
  if (!CannyFromGradients(dx, dy, kColorCannyLow, kColorCannyHigh, true, &edges).ok()) return false;
  cache->smooth = smooth;
  cache->dx = dx;
  cache->dy = dy;
  cache->edges = edges;
  return true;
}

}  // namespace

bool ComputeImageEdges(const cv::Mat& bgr, ImageEdges* out) {
  return EdgesFromTop(bgr, bgr.rows, out);
}

OrientedEdges ComputeOrientedEdges(const cv::Mat& bgr, int top, int bottom, ImageEdges* cache) {
  OrientedEdges out;
  top = std::clamp(top, 0, bgr.rows);
  bottom = std::clamp(bottom, top, bgr.rows);
  out.top = top;
  if (bottom <= top) return out;
  int from = 0;
  cv::Mat dx, dy, edges;
  if (cache != nullptr) {
    if (!cache->Covers(bgr, bottom)) {
      const int slack = kCacheSlackPercent * bgr.rows / 100;
      const int to = std::min(bgr.rows, bottom + kBandMargin + slack);
      if (!ExtendEdgesDown(bgr, to, cache) && !EdgesFromTop(bgr, to, cache)) {
        return out;  // Not 8-bit: no edges.
      }
    }
    dx = cache->dx;
    dy = cache->dy;
    edges = cache->edges;
  } else {
    from = std::max(0, top - kBandMargin);
    const int to = std::min(bgr.rows, bottom + kBandMargin);
    if (!ColorCannyEdges(bgr, from, to, &dx, &dy, &edges)) return out;  // Not 8-bit: no edges.
  }
  const cv::Rect band(0, top - from, bgr.cols, bottom - top);
  // A view of the band, not a copy: it stays valid when the cache is filled again, for
  // EdgesFromTop empties the cache first (its matrices get new buffers; the view keeps the old).
  out.edges = edges(band);
  // Each edge pixel's orientation bit, OR-ed over its 3x3 neighbourhood. The scratch is the
  // thread's, reused from search to search.
  thread_local std::vector<uchar> thread_bits, thread_along;
  std::vector<uchar>& bit_rows = thread_bits;
  bit_rows.resize(static_cast<size_t>(band.area()));
  cv::Mat bits(band.size(), CV_8U, bit_rows.data());
  for (int r = 0; r < band.height; ++r) {  // Each row zeroed, then its edge pixels' bits.
    uchar* b = bits.ptr<uchar>(r);
    std::fill(b, b + band.width, 0);
    const short* gx = dx.ptr<short>(r + band.y);
    const short* gy = dy.ptr<short>(r + band.y);
    ForEachNonZeroByte(out.edges.ptr<uchar>(r), 0, band.width, [&](int u) {
      b[u] = static_cast<uchar>(1u << Bin(gx[u], gy[u]));
    });
  }
  // One row more than the band, not part of `near`: OrientedLineHits reads four bytes at a pixel.
  cv::Mat near_rows(band.height + 1, band.width, CV_8U);
  out.near = near_rows.rowRange(0, band.height);
  OrNeighbourhoods(bits, &thread_along, &out.near);
  return out;
}

namespace {

// The orientation bins within one of the line's normal, from its two visible ends (straight up to
// the lens distortion).
uchar NormalMask(const cv::Point& first, const cv::Point& last) {
  const cv::Point d = last - first;
  const int bin = OrientationBin(-d.y, d.x);
  uchar mask = 0;
  for (int k = -1; k <= 1; ++k) {
    mask |= static_cast<uchar>(1u << ((bin + k + kOrientationBins) % kOrientationBins));
  }
  return mask;
}

#ifdef CORRIDOR_AVX2_VARIANTS
// OrientedLineHits eight samples at a time: each one's neighbourhood bits gathered (the 32 bits at
// its pixel, the low byte kept; 0 where not visible), kept in sample order with the visible ones'
// count and first and last; then the hits counted among them. The same counts. From the first
// group whose four-byte reads would pass the matrix's data limit on, sample by sample (never with
// ComputeOrientedEdges' bands, which have a row to spare).
__attribute__((target("avx2"))) LineHits OrientedLineHitsAvx2(const cv::Point* line, int samples,
                                                              const OrientedEdges& edges) {
  LineHits out;
  const cv::Mat& near = edges.near;
  const int rows = near.rows, cols = near.cols;
  constexpr int kOnStack = 256;
  alignas(32) int stack_bits[kOnStack];
  std::vector<int> heap_bits;
  int* bits = stack_bits;
  if (samples > kOnStack) {
    heap_bits.resize(samples);
    bits = heap_bits.data();
  }
  const uchar* base = near.data;
  const long readable = near.empty() ? 0 : static_cast<long>(near.datalimit - near.data) - 4;
  const __m256i halves = _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7);
  const __m256i minus_one = _mm256_set1_epi32(-1), low_byte = _mm256_set1_epi32(255);
  const __m256i col_end = _mm256_set1_epi32(cols), row_end = _mm256_set1_epi32(rows);
  const __m256i top = _mm256_set1_epi32(edges.top);
  const __m256i step = _mm256_set1_epi32(static_cast<int>(near.step[0]));
  const int* points = reinterpret_cast<const int*>(line);  // x, y pairs.
  int first = -1, last = -1, visible = 0;
  int i = 0;
  if (!near.empty() && static_cast<long>(near.step[0]) * rows < (1L << 31)) {
    for (; i + 8 <= samples; i += 8) {
      const __m256i a = _mm256_permutevar8x32_epi32(
          _mm256_loadu_si256(reinterpret_cast<const __m256i*>(points + 2 * i)), halves);
      const __m256i b = _mm256_permutevar8x32_epi32(
          _mm256_loadu_si256(reinterpret_cast<const __m256i*>(points + 2 * i + 8)), halves);
      const __m256i x = _mm256_permute2x128_si256(a, b, 0x20);
      const __m256i r = _mm256_sub_epi32(_mm256_permute2x128_si256(a, b, 0x31), top);
      const __m256i inside =
          _mm256_and_si256(_mm256_and_si256(_mm256_cmpgt_epi32(x, minus_one),
                                            _mm256_cmpgt_epi32(col_end, x)),
                           _mm256_and_si256(_mm256_cmpgt_epi32(r, minus_one),
                                            _mm256_cmpgt_epi32(row_end, r)));
      const int lanes = _mm256_movemask_ps(_mm256_castsi256_ps(inside));
      const __m256i offset = _mm256_add_epi32(_mm256_mullo_epi32(r, step), x);
      if (lanes != 0) {
        alignas(32) int offsets[8];
        _mm256_store_si256(reinterpret_cast<__m256i*>(offsets), offset);
        bool fits = true;
        for (int k = 0; k < 8; ++k) fits &= !((lanes >> k) & 1) || offsets[k] <= readable;
        if (!fits) break;  // The rest sample by sample.
        if (first < 0) first = i + __builtin_ctz(static_cast<unsigned>(lanes));
        last = i + 31 - __builtin_clz(static_cast<unsigned>(lanes));
        visible += __builtin_popcount(static_cast<unsigned>(lanes));
      }
      const __m256i got = _mm256_mask_i32gather_epi32(_mm256_setzero_si256(),
                                                      reinterpret_cast<const int*>(base), offset,
                                                      inside, 1);
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(bits + i), _mm256_and_si256(got, low_byte));
    }
  }
  for (; i < samples; ++i) {
    const int x = line[i].x, r = line[i].y - edges.top;
    if (!(x >= 0 && x < cols && r >= 0 && r < rows)) {
      bits[i] = 0;
      continue;
    }
    if (first < 0) first = i;
    last = i;
    ++visible;
    bits[i] = near.ptr<uchar>(r)[x];
  }
  out.visible = visible;
  if (visible < 8) return out;
  const __m256i mask = _mm256_set1_epi32(NormalMask(line[first], line[last]));
  int hits = 0;
  int k = 0;
  for (; k + 8 <= samples; k += 8) {
    const __m256i hit = _mm256_and_si256(
        _mm256_loadu_si256(reinterpret_cast<const __m256i*>(bits + k)), mask);
    const int zero = _mm256_movemask_ps(
        _mm256_castsi256_ps(_mm256_cmpeq_epi32(hit, _mm256_setzero_si256())));
    hits += 8 - __builtin_popcount(static_cast<unsigned>(zero));
  }
  const int m = _mm256_cvtsi256_si32(mask);
  for (; k < samples; ++k) hits += (bits[k] & m) != 0;
  out.hits = hits;
  return out;
}
#endif

}  // namespace

LineHits OrientedLineHits(const cv::Point* line, int samples, const OrientedEdges& edges) {
#ifdef CORRIDOR_AVX2_VARIANTS
  if (CpuHasAvx2()) return OrientedLineHitsAvx2(line, samples, edges);
#endif
  LineHits out;
  const int rows = edges.near.rows, cols = edges.near.cols;
  // One pass over the samples: the visible ones' neighbourhood bits, in order (the orientation
  // mask needs the visible ends first); then the hits among them.
  constexpr int kOnStack = 256;
  uchar stack_bits[kOnStack];
  std::vector<uchar> heap_bits;
  uchar* bits = stack_bits;
  if (samples > kOnStack) {
    heap_bits.resize(samples);
    bits = heap_bits.data();
  }
  int first = -1, last = -1, visible = 0;
  for (int i = 0; i < samples; ++i) {
    const int x = line[i].x, r = line[i].y - edges.top;
    if (!(x >= 0 && x < cols && r >= 0 && r < rows)) continue;
    if (first < 0) first = i;
    last = i;
    bits[visible++] = edges.near.ptr<uchar>(r)[x];
  }
  out.visible = visible;
  if (visible < 8) return out;
  const uchar mask = NormalMask(line[first], line[last]);
  int hits = 0;
  for (int i = 0; i < visible; ++i) hits += (bits[i] & mask) != 0;
  out.hits = hits;
  return out;
}

double LineHits::Fraction(int at_least) const {
  if (visible < 8) return 0.0;
  return static_cast<double>(hits) / std::max(visible, at_least);
}

}  // namespace corridor
