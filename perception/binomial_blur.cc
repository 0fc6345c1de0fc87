#include "perception/binomial_blur.h"

#include <cstdint>
#include <vector>

#include "core/cpu_features.h"
#include "perception/binomial_rows.h"
#include "perception/image_border.h"

namespace corridor {
namespace {

// The rows' loops; inlined into each variant below, so that the AVX2 one vectorises them.
template <int C, int kTaps>
CORRIDOR_ALWAYS_INLINE inline void BlurBody(const cv::Mat& image, int from, int to, cv::Mat* out) {
  constexpr int kPad = kTaps / 2;
  const int width = image.cols, height = image.rows, n = width * C;
  std::vector<uint16_t> sums((width + 2 * kPad) * C);
  uint16_t* v = sums.data() + kPad * C;
  for (int y = from; y < to; ++y) {
    const auto row = [&](int dy) { return image.ptr<uint8_t>(Reflect101(y + dy, height)); };
    if (kTaps == 3) {
      binomial::ColumnSums3(row(-1), row(0), row(1), n, v);
    } else {
      binomial::ColumnSums5(row(-2), row(-1), row(0), row(1), row(2), n, v);
    }
    binomial::ReflectEnds<C>(v, width, kPad);
    uint8_t* h = out->ptr<uint8_t>(y - from);
    if (kTaps == 3) {
      binomial::RowSums3<C>(v, n, h);
    } else {
      binomial::RowSums5<C>(v, n, h);
    }
  }
}

using BlurFn = void (*)(const cv::Mat&, int, int, cv::Mat*);

template <int C, int kTaps>
void Blur(const cv::Mat& image, int from, int to, cv::Mat* out) {
  BlurBody<C, kTaps>(image, from, to, out);
}

#ifdef CORRIDOR_AVX2_VARIANTS
// The same loops compiled for AVX2: integer arithmetic, the same results.
template <int C, int kTaps>
__attribute__((target("avx2"))) void BlurAvx2(const cv::Mat& image, int from, int to,
                                             cv::Mat* out) {
  BlurBody<C, kTaps>(image, from, to, out);
}
#endif

template <int C>
BlurFn ChooseBlur(int taps) {
#ifdef CORRIDOR_AVX2_VARIANTS
  if (CpuHasAvx2()) return taps == 3 ? BlurAvx2<C, 3> : BlurAvx2<C, 5>;
#endif
  return taps == 3 ? Blur<C, 3> : Blur<C, 5>;
}

}  // namespace

Status BinomialBlur(const cv::Mat& image, int from, int to, int taps, cv::Mat* out) {
  if (image.empty() || image.depth() != CV_8U || image.channels() > 4) {
    return Status::InvalidArgument("binomial blur: the image must be 8-bit with 1 to 4 channels");
  }
  if (taps != 3 && taps != 5) {
    return Status::InvalidArgument("binomial blur: taps must be 3 or 5");
  }
  if (from < 0 || to > image.rows || from >= to) {
    return Status::InvalidArgument("binomial blur: rows [from, to) must be a non-empty range of "
                                   "the image's");
  }
  BlurFn blur = nullptr;
  switch (image.channels()) {
    case 1: blur = ChooseBlur<1>(taps); break;
    case 2: blur = ChooseBlur<2>(taps); break;
    case 3: blur = ChooseBlur<3>(taps); break;
    default: blur = ChooseBlur<4>(taps); break;
  }
  // A new matrix when `out` shares the image's pixels, even as another view of them (rows are read
  // after others are written); `source` keeps them (`image` may be *out itself).
  const cv::Mat source = image;
  if (out->datastart == source.datastart) *out = cv::Mat();
  out->create(to - from, source.cols, source.type());
  blur(source, from, to, out);
  return Status::Ok();
}

}  // namespace corridor
