#include "kernels/channel_plane.h"

#include <cstdint>

#include "core/cpu_features.h"
#include "kernels/three_channels.h"

namespace corridor {
namespace {

// Channel c of a row of `cols` pixels of n channels.
void RowChannel(const uint8_t* pixels, int cols, int n, int c, uint8_t* __restrict out) {
  for (int u = 0; u < cols; ++u) out[u] = pixels[n * u + c];
}

#ifdef CORRIDOR_AVX2_VARIANTS
// The same for three channels, 32 pixels a step by byte shuffles, then pixel by pixel.
__attribute__((target("avx2"))) void RowChannel3Avx2(const uint8_t* pixels, int cols, int c,
                                                     uint8_t* out) {
  using namespace three_channels;
  const __m256i pick[3] = {PickOf(c, 0), PickOf(c, 1), PickOf(c, 2)};
  int u = 0;
  for (; u + 32 <= cols; u += 32) {
    const uint8_t* p = pixels + 3 * u;
    const __m256i parts[3] = {LoadPart(p, 0), LoadPart(p, 1), LoadPart(p, 2)};
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + u), Channel(parts, pick));
  }
  RowChannel(pixels + 3 * u, cols - u, 3, c, out + u);
}
#endif

}  // namespace

void ChannelPlane(const cv::Mat& image, int channel, cv::Mat* plane) {
  const int n = image.channels();
  if (image.depth() != CV_8U || n < 2 || n > 4 || channel < 0 || channel >= n) {
    plane->release();
    return;
  }
  plane->create(image.size(), CV_8U);
#ifdef CORRIDOR_AVX2_VARIANTS
  const bool avx2 = n == 3 && CpuHasAvx2();
#endif
  for (int r = 0; r < image.rows; ++r) {
    const uint8_t* pixels = image.ptr<uint8_t>(r);
    uint8_t* out = plane->ptr<uint8_t>(r);
#ifdef CORRIDOR_AVX2_VARIANTS
    if (avx2) {
      RowChannel3Avx2(pixels, image.cols, channel, out);
      continue;
    }
#endif
    RowChannel(pixels, image.cols, n, channel, out);
  }
}

}  // namespace corridor
