#include "kernels/sobel_row.h"

#include <algorithm>
#include <cstdlib>

#include "core/cpu_features.h"

#ifdef CORRIDOR_AVX2_VARIANTS
#include <immintrin.h>

#include "kernels/avx2_loads.h"
#endif

namespace corridor {
namespace {

// Columns [x, end) one at a time.
void SobelXTail(const uint8_t* up, const uint8_t* mid, const uint8_t* down, int x, int end,
                int threshold, int16_t* g, uint8_t* strong) {
  for (; x < end; ++x) {
    g[x] = static_cast<int16_t>((up[x + 1] - up[x - 1]) + 2 * (mid[x + 1] - mid[x - 1]) +
                                (down[x + 1] - down[x - 1]));
    strong[x] = std::abs(g[x]) >= threshold;
  }
}

#ifdef CORRIDOR_AVX2_VARIANTS
// Sixteen columns a step in 16-bit lanes (no sum leaves [-1020, 1020]), then the rest one at a
// time: the same values.
__attribute__((target("avx2"))) void SobelXRowAvx2(const uint8_t* up, const uint8_t* mid,
                                                   const uint8_t* down, int begin, int end,
                                                   int threshold, int16_t* g, uint8_t* strong) {
  using avx2::Widen16;
  const __m256i at_most = _mm256_set1_epi16(static_cast<int16_t>(threshold - 1));
  int x = begin;
  for (; x + 16 <= end; x += 16) {
    const __m256i above = _mm256_sub_epi16(Widen16(up + x + 1), Widen16(up + x - 1));
    const __m256i below = _mm256_sub_epi16(Widen16(down + x + 1), Widen16(down + x - 1));
    const __m256i outer = _mm256_add_epi16(above, below);
    const __m256i centre = _mm256_sub_epi16(Widen16(mid + x + 1), Widen16(mid + x - 1));
    const __m256i sum = _mm256_add_epi16(outer, _mm256_add_epi16(centre, centre));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(g + x), sum);
    const __m256i is_strong = _mm256_cmpgt_epi16(_mm256_abs_epi16(sum), at_most);
    const __m128i bytes = _mm_packs_epi16(_mm256_castsi256_si128(is_strong),
                                          _mm256_extracti128_si256(is_strong, 1));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(strong + x), bytes);
  }
  SobelXTail(up, mid, down, x, end, threshold, g, strong);
}
#endif

}  // namespace

void SobelXRow(const uint8_t* up, const uint8_t* mid, const uint8_t* down, int begin, int end,
               int threshold, int16_t* g, uint8_t* strong) {
  threshold = std::clamp(threshold, -1, 1021);  // No lane overflows in the comparison.
#ifdef CORRIDOR_AVX2_VARIANTS
  if (CpuHasAvx2()) return SobelXRowAvx2(up, mid, down, begin, end, threshold, g, strong);
#endif
  SobelXTail(up, mid, down, begin, end, threshold, g, strong);
}

}  // namespace corridor
