#include "perception/working_image.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#ifdef __x86_64__
#include <immintrin.h>
#endif

#include <opencv2/imgproc.hpp>

#include "core/cpu_features.h"
#include "kernels/binomial_rows.h"
#include "kernels/image_border.h"
#include "kernels/mat_memory.h"

namespace corridor {
namespace {

#ifdef CORRIDOR_AVX2_VARIANTS
// Every second pixel of a row of C-channel pixels: d[C x + c] = h[2 C x + c], x < out_width.
template <int C>
__attribute__((target("avx2"))) inline void EverySecondPixel(const uint8_t* h, int out_width,
                                                             uint8_t* d) {
  int x = 0;
  if (C == 3) {
    // Three pixels a step: bytes 0-2, 6-8 and 12-14 of 16 (every second pixel), stored as 16
    // bytes of which the last 7 are overwritten by the next step (stopping 16 bytes short of
    // the row's end); then four bytes at a time, the fourth overwritten by the next pixel.
    const __m128i pick = _mm_setr_epi8(0, 1, 2, 6, 7, 8, 12, 13, 14, -1, -1, -1, -1, -1, -1, -1);
    for (; 3 * x + 16 <= 3 * out_width; x += 3) {
      const __m128i six = _mm_loadu_si128(reinterpret_cast<const __m128i*>(h + 6 * x));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(d + 3 * x), _mm_shuffle_epi8(six, pick));
    }
    for (; x + 1 < out_width; ++x) std::memcpy(d + 3 * x, h + 6 * x, 4);
  }
  for (; x < out_width; ++x) {
    for (int c = 0; c < C; ++c) d[C * x + c] = h[2 * C * x + c];
  }
}

// The 5x5 kernel [1 4 6 4 1]^2 / 256 of cv::pyrDown, at every second row and column, in 16-bit
// integers (at most 256 * 255 + 128 < 2^16): first down the five rows into `vertical`, then
// along it at every pixel, then every second pixel kept. Integer sums in any order are the same,
// so the pixels are cv::pyrDown's. Output rows whose source row 2 y lies among `blurred`'s rows
// (the same kernel at every pixel, see PyrDown) are every second pixel of that row instead.
template <int kChannels>
__attribute__((target("avx2"))) void PyrDownAvx2(const cv::Mat& src, const cv::Mat* blurred,
                                                 cv::Mat* dst) {
  constexpr int C = kChannels;
  const int width = src.cols, height = src.rows;
  const int out_width = (width + 1) / 2, out_height = (height + 1) / 2;
  // Into *dst's memory, as cv::pyrDown, unless it holds the source's pixels (`src` may be *dst).
  const cv::Mat source = src;
  if (dst->datastart == source.datastart) *dst = cv::Mat();
  dst->create(out_height, out_width, source.type());
  cv::Mat& out = *dst;
  // Two reflected pixels on each side of the vertical sums; four bytes of slack for the copy.
  // The thread's, reused from call to call.
  thread_local std::vector<uint16_t> thread_vertical;
  thread_local std::vector<uint8_t> thread_horizontal;
  std::vector<uint16_t>& vertical = thread_vertical;
  std::vector<uint8_t>& horizontal = thread_horizontal;
  vertical.resize(static_cast<size_t>(width + 4) * C);
  horizontal.resize(static_cast<size_t>(width) * C + 4);
  uint16_t* v = vertical.data() + 2 * C;
  uint8_t* h = horizontal.data();
  const int n = width * C;
  const int from_blurred = blurred != nullptr ? std::min(out_height, (blurred->rows + 1) / 2) : 0;
  for (int y = 0; y < from_blurred; ++y) {
    EverySecondPixel<C>(blurred->ptr<uint8_t>(2 * y), out_width, out.ptr<uint8_t>(y));
  }
  for (int y = from_blurred; y < out_height; ++y) {
    const uint8_t* r0 = source.ptr<uint8_t>(Reflect101(2 * y - 2, height));
    const uint8_t* r1 = source.ptr<uint8_t>(Reflect101(2 * y - 1, height));
    const uint8_t* r2 = source.ptr<uint8_t>(2 * y);
    const uint8_t* r3 = source.ptr<uint8_t>(Reflect101(2 * y + 1, height));
    const uint8_t* r4 = source.ptr<uint8_t>(Reflect101(2 * y + 2, height));
    binomial::ColumnSums5Avx2(r0, r1, r2, r3, r4, n, v);
    binomial::ReflectEnds<C>(v, width, 2);
    binomial::RowSums5Avx2<C>(v, n, h);
    EverySecondPixel<C>(h, out_width, out.ptr<uint8_t>(y));
  }
}
#endif

}  // namespace

void PyrDown(const cv::Mat& image, cv::Mat* halved, const cv::Mat* blurred) {
#ifdef CORRIDOR_AVX2_VARIANTS
  if (CpuHasAvx2() && image.depth() == CV_8U && image.cols >= 3 && image.rows >= 3) {
    if (blurred != nullptr && (blurred->empty() || blurred->type() != image.type() ||
                               blurred->cols != image.cols || blurred->rows > image.rows)) {
      blurred = nullptr;
    }
    switch (image.channels()) {
      case 1:
        return PyrDownAvx2<1>(image, blurred, halved);
      case 3:
        return PyrDownAvx2<3>(image, blurred, halved);
      case 4:
        return PyrDownAvx2<4>(image, blurred, halved);
      default:
        break;
    }
  }
#endif
  cv::pyrDown(image, *halved);
}

int WorkingScale(int width, int max_width) {
  int scale = 1;
  for (int w = width; max_width > 0 && w > max_width; w = (w + 1) / 2) scale *= 2;
  return scale;
}

WorkingImage HalveToWidth(const cv::Mat& bgr, const Camera& camera, int max_width,
                          const cv::Mat* blurred) {
  WorkingImage work;
  HalveToWidth(bgr, camera, max_width, blurred, &work);
  return work;
}

void HalveToWidth(const cv::Mat& bgr, const Camera& camera, int max_width,
                  const cv::Mat* blurred, WorkingImage* out) {
  const cv::Mat image = bgr;             // `bgr` may be out->bgr.
  cv::Mat memory = std::move(out->bgr);  // For the first halving.
  ReleaseUnlessSole(&memory);
  WorkingImage& work = *out;
  work = WorkingImage{image, camera, 1};
  const int scale = WorkingScale(image.cols, max_width);
  while (work.scale < scale && work.bgr.rows > 1) {
    if (work.scale == 1) {
      PyrDown(image, &memory, blurred);
      work.bgr = std::move(memory);
    } else {
      PyrDown(work.bgr, &work.bgr);
    }
    work.scale *= 2;
    Camera& c = work.camera;
    c.image_width = work.bgr.cols;
    c.image_height = work.bgr.rows;
    c.fx *= 0.5;
    c.fy *= 0.5;
    c.cx *= 0.5;
    c.cy *= 0.5;
  }
}

}  // namespace corridor
