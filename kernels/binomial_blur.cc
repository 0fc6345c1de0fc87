#include "kernels/binomial_blur.h"

#include <cstdint>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/cpu_features.h"
#include "kernels/binomial_rows.h"
#include "kernels/image_border.h"

namespace corridor {
namespace {

// kTaps of the weighted 5-tap kernel (binomial::Kernel5).
constexpr int kWeighted5 = 0;

// The rows' loops; inlined into each variant below, so that the AVX2 one vectorises them.
// `k`: the weights when kTaps is kWeighted5. kAvx2: the five-row sums through their AVX2 loops.
template <int C, int kTaps, bool kAvx2>
CORRIDOR_ALWAYS_INLINE inline void BlurBody(const cv::Mat& image, int from, int to,
                                            binomial::Kernel5 k, cv::Mat* out) {
  constexpr int kPad = kTaps == 3 ? 1 : 2;
  const int width = image.cols, height = image.rows, n = width * C;
  // The column sums of a row, with the reflected pixels each side: the thread's, reused.
  thread_local std::vector<uint16_t> thread_sums;
  std::vector<uint16_t>& sums = thread_sums;
  sums.resize(static_cast<size_t>(width + 2 * kPad) * C);
  uint16_t* v = sums.data() + kPad * C;
  for (int y = from; y < to; ++y) {
    const auto row = [&](int dy) { return image.ptr<uint8_t>(Reflect101(y + dy, height)); };
    if (kTaps == 3) {
      binomial::ColumnSums3(row(-1), row(0), row(1), n, v);
    } else if (kTaps == 5) {
#ifdef CORRIDOR_AVX2_VARIANTS
      if constexpr (kAvx2) {
        binomial::ColumnSums5Avx2(row(-2), row(-1), row(0), row(1), row(2), n, v);
      } else {
        binomial::ColumnSums5(row(-2), row(-1), row(0), row(1), row(2), n, v);
      }
#else
      binomial::ColumnSums5(row(-2), row(-1), row(0), row(1), row(2), n, v);
#endif
    } else {
#ifdef CORRIDOR_AVX2_VARIANTS
      if constexpr (kAvx2) {
        // Biased sums, for the row pass's 32-bit pairs (WeightedRowSums5BiasedAvx2).
        binomial::WeightedColumnSums5BiasedAvx2(row(-2), row(-1), row(0), row(1), row(2), n, k,
                                                v);
      } else {
        binomial::WeightedColumnSums5(row(-2), row(-1), row(0), row(1), row(2), n, k, v);
      }
#else
      binomial::WeightedColumnSums5(row(-2), row(-1), row(0), row(1), row(2), n, k, v);
#endif
    }
    binomial::ReflectEnds<C>(v, width, kPad);
    uint8_t* h = out->ptr<uint8_t>(y - from);
    if (kTaps == 3) {
      binomial::RowSums3<C>(v, n, h);
    } else if (kTaps == 5) {
#ifdef CORRIDOR_AVX2_VARIANTS
      if constexpr (kAvx2) {
        binomial::RowSums5Avx2<C>(v, n, h);
      } else {
        binomial::RowSums5<C>(v, n, h);
      }
#else
      binomial::RowSums5<C>(v, n, h);
#endif
    } else {
#ifdef CORRIDOR_AVX2_VARIANTS
      if constexpr (kAvx2) {
        binomial::WeightedRowSums5BiasedAvx2<C>(v, n, k, h);
      } else {
        binomial::WeightedRowSums5<C>(v, n, k, h);
      }
#else
      binomial::WeightedRowSums5<C>(v, n, k, h);
#endif
    }
  }
}

using BlurFn = void (*)(const cv::Mat&, int, int, binomial::Kernel5, cv::Mat*);

template <int C, int kTaps>
void Blur(const cv::Mat& image, int from, int to, binomial::Kernel5 k, cv::Mat* out) {
  BlurBody<C, kTaps, false>(image, from, to, k, out);
}

#ifdef CORRIDOR_AVX2_VARIANTS
// The same loops compiled for AVX2: integer arithmetic, the same results.
template <int C, int kTaps>
__attribute__((target("avx2"))) void BlurAvx2(const cv::Mat& image, int from, int to,
                                              binomial::Kernel5 k, cv::Mat* out) {
  BlurBody<C, kTaps, true>(image, from, to, k, out);
}
#endif

template <int C, int kTaps>
BlurFn ChooseVariant() {
#ifdef CORRIDOR_AVX2_VARIANTS
  if (CpuHasAvx2()) return BlurAvx2<C, kTaps>;
#endif
  return Blur<C, kTaps>;
}

template <int kTaps>
BlurFn ChooseBlur(int channels) {
  switch (channels) {
    case 1:
      return ChooseVariant<1, kTaps>();
    case 2:
      return ChooseVariant<2, kTaps>();
    case 3:
      return ChooseVariant<3, kTaps>();
    default:
      return ChooseVariant<4, kTaps>();
  }
}

// Blurs rows [from, to) of `image` into *out (a new matrix when it shares the image's pixels,
// even as another view of them: rows are read after others are written).
void RunBlur(BlurFn blur, const cv::Mat& image, int from, int to, binomial::Kernel5 k,
             cv::Mat* out) {
  const cv::Mat source = image;  // Keeps the pixels (`image` may be *out itself).
  if (out->datastart == source.datastart) *out = cv::Mat();
  out->create(to - from, source.cols, source.type());
  blur(source, from, to, k, out);
}

// cv::GaussianBlur's fixed-point kernel for 8-bit images and `sigma`, when it has at most five
// taps. OpenCV blurs 8-bit pixels with weights in 1/256, the exact sums rounded half up once:
// an impulse of 255 on one row comes out as round(255 w / 256), which is w for w <= 128, so the
// outer weights are read off it and the centre is what they leave of 256. The kernel is then
// checked on a random image against cv::GaussianBlur itself; false when anything differs (a wider
// or asymmetric kernel, another rounding in another OpenCV).
bool OpenCvKernel5(double sigma, binomial::Kernel5* k) {
  constexpr int kMid = 8;
  cv::Mat impulse = cv::Mat::zeros(1, 2 * kMid + 1, CV_8U), spread;
  impulse.at<uchar>(0, kMid) = 255;
  cv::GaussianBlur(impulse, spread, cv::Size(0, 0), sigma);
  const auto at = [&](int i) { return static_cast<int>(spread.at<uchar>(0, kMid + i)); };
  for (int i = 3; i <= kMid; ++i) {
    if (at(i) != 0 || at(-i) != 0) return false;
  }
  if (at(1) != at(-1) || at(2) != at(-2) || at(1) >= 128 || at(2) >= 128) return false;
  const int centre = 256 - 2 * (at(1) + at(2));
  if (centre < 0) return false;
  *k = {static_cast<uint16_t>(centre), static_cast<uint16_t>(at(1)), static_cast<uint16_t>(at(2))};
  cv::Mat probe(11, 23, CV_8UC3), expected, blurred;
  cv::RNG(17).fill(probe, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(probe, expected, cv::Size(0, 0), sigma);
  RunBlur(ChooseBlur<kWeighted5>(3), probe, 0, probe.rows, *k, &blurred);
  return cv::norm(blurred, expected, cv::NORM_INF) == 0;
}

}  // namespace

void GaussianBlurView(const cv::Mat& view, double sigma, cv::Mat* out) {
  // The kernel of the last sigma this thread asked for (a recoverer asks for one).
  thread_local double cached_sigma = -1;
  thread_local bool cached_fits = false;
  thread_local binomial::Kernel5 cached_kernel{};
  if (sigma != cached_sigma) {
    cached_fits = sigma > 0 && OpenCvKernel5(sigma, &cached_kernel);
    cached_sigma = sigma;
  }
  cv::Size whole;
  cv::Point offset;
  if (!view.empty()) view.locateROI(whole, offset);
  if (!cached_fits || view.empty() || view.depth() != CV_8U || view.channels() > 4 ||
      whole.width != view.cols) {
    cv::GaussianBlur(view, *out, cv::Size(0, 0), sigma);
    return;
  }
  // The rows around the view are read where its matrix has them, as cv::GaussianBlur reads them.
  cv::Mat rows = view;
  rows.adjustROI(offset.y, whole.height - offset.y - view.rows, 0, 0);
  RunBlur(ChooseBlur<kWeighted5>(view.channels()), rows, offset.y, offset.y + view.rows,
          cached_kernel, out);
}

Status BinomialBlur(const cv::Mat& image, int from, int to, int taps, cv::Mat* out) {
  if (image.empty() || image.depth() != CV_8U || image.channels() > 4) {
    return Status::InvalidArgument("binomial blur: the image must be 8-bit with 1 to 4 channels");
  }
  if (taps != 3 && taps != 5) {
    return Status::InvalidArgument("binomial blur: taps must be 3 or 5");
  }
  if (from < 0 || to > image.rows || from >= to) {
    return Status::InvalidArgument(
        "binomial blur: rows [from, to) must be a non-empty range of "
        "the image's");
  }
  RunBlur(taps == 3 ? ChooseBlur<3>(image.channels()) : ChooseBlur<5>(image.channels()), image,
          from, to, {}, out);
  return Status::Ok();
}

}  // namespace corridor
