#pragma once

// Row kernels of the binomial filters [1 2 1] / 4 and [1 4 6 4 1] / 16 on 8-bit pixels with C
// interleaved channels, in 16-bit integers: the sums down a column of rows, then along the row.
// Also any symmetric 5-tap kernel in 1/256 (Kernel5), as cv::GaussianBlur's fixed point has it.
// Shared by PyrDown (working_image.cc) and BinomialBlur (binomial_blur.cc); always inlined and
// without a target, so that each caller's AVX2 variant vectorises them with AVX2.

#include <cstdint>

#include "core/cpu_features.h"
#include "kernels/avx2_loads.h"
#include "kernels/image_border.h"

#ifdef CORRIDOR_AVX2_VARIANTS
#include <immintrin.h>
#endif

namespace corridor {
namespace binomial {

// v[i] = r0 + 2 r1 + r2 (at most 4 * 255).
CORRIDOR_ALWAYS_INLINE inline void ColumnSums3(const uint8_t* r0, const uint8_t* r1, const uint8_t* r2, int n,
                                               uint16_t* __restrict v) {
  for (int i = 0; i < n; ++i) v[i] = static_cast<uint16_t>(r0[i] + 2 * r1[i] + r2[i]);
}

// v[i] = r0 + 4 r1 + 6 r2 + 4 r3 + r4 (at most 16 * 255).
CORRIDOR_ALWAYS_INLINE inline void ColumnSums5(const uint8_t* r0, const uint8_t* r1, const uint8_t* r2,
                                               const uint8_t* r3, const uint8_t* r4, int n, uint16_t* __restrict v) {
  for (int i = 0; i < n; ++i) {
    v[i] = static_cast<uint16_t>(r0[i] + r4[i] + 4 * (r1[i] + r3[i]) + 6 * r2[i]);
  }
}

// Fills the `pad` pixels before and after a row of `width` C-channel pixels (v[-pad C] ..
// v[(width + pad) C - 1]) with the reflected ones (BORDER_REFLECT_101).
template <int C>
inline void ReflectEnds(uint16_t* v, int width, int pad) {
  for (int k = 1; k <= pad; ++k) {
    const int before = Reflect101(-k, width), after = Reflect101(width - 1 + k, width);
    for (int c = 0; c < C; ++c) {
      v[-k * C + c] = v[before * C + c];
      v[(width - 1 + k) * C + c] = v[after * C + c];
    }
  }
}

// h[i] = (v[i - C] + 2 v[i] + v[i + C] + 8) / 16, rounded half up: the 3x3 filter's pixels.
template <int C>
CORRIDOR_ALWAYS_INLINE inline void RowSums3(const uint16_t* v, int n, uint8_t* __restrict h) {
  for (int i = 0; i < n; ++i) {
    h[i] = static_cast<uint8_t>(static_cast<uint16_t>(v[i - C] + 2 * v[i] + v[i + C] + 8) >> 4);
  }
}

// h[i] = (v[i - 2C] + 4 v[i - C] + 6 v[i] + 4 v[i + C] + v[i + 2C] + 128) / 256, rounded half up
// (at most 256 * 255 + 128 < 2^16): the 5x5 filter's pixels.
template <int C>
CORRIDOR_ALWAYS_INLINE inline void RowSums5(const uint16_t* v, int n, uint8_t* __restrict h) {
  for (int i = 0; i < n; ++i) {
    h[i] = static_cast<uint8_t>(
        static_cast<uint16_t>(v[i - 2 * C] + v[i + 2 * C] + 4 * (v[i - C] + v[i + C]) + 6 * v[i] +
                              128) >>
        8);
  }
}

// A symmetric 5-tap kernel in 1/256: the centre's weight, its neighbours', and the outer pair's;
// centre + 2 near + 2 far = 256.
struct Kernel5 {
  uint16_t centre, near, far;
};

// v[i] = far (r0 + r4) + near (r1 + r3) + centre r2 (at most 256 * 255).
CORRIDOR_ALWAYS_INLINE inline void WeightedColumnSums5(const uint8_t* r0, const uint8_t* r1,
                                                       const uint8_t* r2, const uint8_t* r3,
                                                       const uint8_t* r4, int n, Kernel5 k,
                                                       uint16_t* __restrict v) {
  for (int i = 0; i < n; ++i) {
    v[i] = static_cast<uint16_t>(k.far * (r0[i] + r4[i]) + k.near * (r1[i] + r3[i]) +
                                 k.centre * r2[i]);
  }
}

// h[i] = the same weights along the row, (sum + 2^15) / 2^16 rounded half up. In 16 bits (twice
// the lanes of 32): the sums' high bytes and low bytes are weighed apart, H and L (each at most
// 256 * 255), and (256 H + L + 2^15) >> 16 = (H + (L >> 8) + 128) >> 8, whose sum stays below
// 2^16 as H + L / 256 is the blurred value times 256.
template <int C>
CORRIDOR_ALWAYS_INLINE inline void WeightedRowSums5(const uint16_t* v, int n, Kernel5 k,
                                                    uint8_t* __restrict h) {
  const uint16_t far = k.far, near = k.near, centre = k.centre;
  const auto hi = [](uint16_t x) { return static_cast<uint16_t>(x >> 8); };
  const auto lo = [](uint16_t x) { return static_cast<uint16_t>(x & 255); };
  for (int i = 0; i < n; ++i) {
    const uint16_t a = v[i - 2 * C], b = v[i - C], c = v[i], d = v[i + C], e = v[i + 2 * C];
    const uint16_t high = static_cast<uint16_t>(far * (hi(a) + hi(e)) + near * (hi(b) + hi(d)) +
                                                centre * hi(c));
    const uint16_t low = static_cast<uint16_t>(far * (lo(a) + lo(e)) + near * (lo(b) + lo(d)) +
                                               centre * lo(c));
    h[i] = static_cast<uint8_t>(static_cast<uint16_t>(high + (low >> 8) + 128) >> 8);
  }
}

#ifdef CORRIDOR_AVX2_VARIANTS
using avx2::Load16;
using avx2::Widen16;

// ColumnSums5 sixteen bytes a step, each widened straight from memory (the vectoriser takes 32 at
// a time and splits the upper half out of a register): the same sums. For AVX2 callers only.
__attribute__((target("avx2"))) inline void ColumnSums5Avx2(const uint8_t* r0, const uint8_t* r1,
                                                            const uint8_t* r2, const uint8_t* r3,
                                                            const uint8_t* r4, int n,
                                                            uint16_t* __restrict v) {
  const __m256i six = _mm256_set1_epi16(6);
  int i = 0;
  for (; i + 16 <= n; i += 16) {
    const __m256i outer = _mm256_add_epi16(Widen16(r0 + i), Widen16(r4 + i));
    const __m256i inner = _mm256_slli_epi16(_mm256_add_epi16(Widen16(r1 + i), Widen16(r3 + i)), 2);
    const __m256i centre = _mm256_mullo_epi16(Widen16(r2 + i), six);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(v + i),
                        _mm256_add_epi16(_mm256_add_epi16(outer, inner), centre));
  }
  for (; i < n; ++i) {
    v[i] = static_cast<uint16_t>(r0[i] + r4[i] + 4 * (r1[i] + r3[i]) + 6 * r2[i]);
  }
}

// Sixteen pixels of RowSums5Avx2 at v[i], as 16-bit values.
template <int C>
__attribute__((target("avx2"))) inline __m256i RowSixteen5(const uint16_t* v, int i) {
  const __m256i outer = _mm256_add_epi16(Load16(v + i - 2 * C), Load16(v + i + 2 * C));
  const __m256i inner =
      _mm256_slli_epi16(_mm256_add_epi16(Load16(v + i - C), Load16(v + i + C)), 2);
  const __m256i centre = _mm256_mullo_epi16(Load16(v + i), _mm256_set1_epi16(6));
  const __m256i sum = _mm256_add_epi16(_mm256_add_epi16(outer, inner),
                                       _mm256_add_epi16(centre, _mm256_set1_epi16(128)));
  return _mm256_srli_epi16(sum, 8);
}

// RowSums5 32 pixels a step (the sums, at most 256 * 255 + 128, stay below 2^16), then pixel by
// pixel: the same pixels. For AVX2 callers only.
template <int C>
__attribute__((target("avx2"))) inline void RowSums5Avx2(const uint16_t* v, int n,
                                                         uint8_t* __restrict h) {
  int i = 0;
  for (; i + 32 <= n; i += 32) {
    const __m256i bytes = _mm256_packus_epi16(RowSixteen5<C>(v, i), RowSixteen5<C>(v, i + 16));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(h + i), _mm256_permute4x64_epi64(bytes, 0xd8));
  }
  RowSums5<C>(v + i, n - i, h + i);
}

// WeightedColumnSums5 16 pixels a step (the sums, at most 256 * 255, exact in 16 bits), with the
// sums' top bit flipped (v ^ 0x8000, v - 2^15 as a signed 16-bit integer), as
// WeightedRowSums5BiasedAvx2 reads them.
__attribute__((target("avx2"))) inline void WeightedColumnSums5BiasedAvx2(
    const uint8_t* r0, const uint8_t* r1, const uint8_t* r2, const uint8_t* r3, const uint8_t* r4,
    int n, Kernel5 k, uint16_t* __restrict v) {
  const __m256i far = _mm256_set1_epi16(static_cast<short>(k.far));
  const __m256i near = _mm256_set1_epi16(static_cast<short>(k.near));
  const __m256i centre = _mm256_set1_epi16(static_cast<short>(k.centre));
  const __m256i top_bit = _mm256_set1_epi16(static_cast<short>(0x8000));
  int i = 0;
  for (; i + 16 <= n; i += 16) {
    const __m256i outer = _mm256_mullo_epi16(_mm256_add_epi16(Widen16(r0 + i), Widen16(r4 + i)), far);
    const __m256i inner =
        _mm256_mullo_epi16(_mm256_add_epi16(Widen16(r1 + i), Widen16(r3 + i)), near);
    const __m256i middle = _mm256_mullo_epi16(Widen16(r2 + i), centre);
    _mm256_storeu_si256(
        reinterpret_cast<__m256i*>(v + i),
        _mm256_xor_si256(_mm256_add_epi16(_mm256_add_epi16(outer, inner), middle), top_bit));
  }
  for (; i < n; ++i) {
    v[i] = static_cast<uint16_t>(
        (k.far * (r0[i] + r4[i]) + k.near * (r1[i] + r3[i]) + k.centre * r2[i]) ^ 0x8000);
  }
}

// Sixteen pixels of WeightedRowSums5BiasedAvx2 at v[i], as 16-bit values in order (the in-lane
// unpacks' order packed back): `far`, `near` and `centre` its weight pairs, `restore` its 16448.
template <int C>
__attribute__((target("avx2"))) inline __m256i WeightedSixteenBiased(const uint16_t* v, int i,
                                                                     __m256i far, __m256i near,
                                                                     __m256i centre,
                                                                     __m256i restore) {
  const __m256i a = Load16(v + i - 2 * C), b = Load16(v + i - C), c = Load16(v + i);
  const __m256i d = Load16(v + i + C), e = Load16(v + i + 2 * C);
  const __m256i low = _mm256_add_epi32(
      _mm256_add_epi32(_mm256_madd_epi16(_mm256_unpacklo_epi16(a, e), far),
                       _mm256_madd_epi16(_mm256_unpacklo_epi16(b, d), near)),
      _mm256_madd_epi16(_mm256_unpacklo_epi16(c, restore), centre));
  const __m256i high = _mm256_add_epi32(
      _mm256_add_epi32(_mm256_madd_epi16(_mm256_unpackhi_epi16(a, e), far),
                       _mm256_madd_epi16(_mm256_unpackhi_epi16(b, d), near)),
      _mm256_madd_epi16(_mm256_unpackhi_epi16(c, restore), centre));
  return _mm256_packus_epi32(_mm256_srli_epi32(low, 16), _mm256_srli_epi32(high, 16));
}

// WeightedRowSums5 on the biased sums of WeightedColumnSums5BiasedAvx2, 32 pixels a step: the
// exact sum of weights times sums plus 2^15, shifted down by 16 (which WeightedRowSums5's halves
// give too), in 32-bit lanes by pairs (vpmaddwd): (a, e) and (b, d) by (far, far) and
// (near, near), and (c, 16448) by (centre, 512), whose 16448 * 512 = 2^23 + 2^15 restores the
// bias (256 weights of 2^15) and adds the rounding. The same pixels.
template <int C>
__attribute__((target("avx2"))) inline void WeightedRowSums5BiasedAvx2(const uint16_t* v, int n,
                                                                       Kernel5 k,
                                                                       uint8_t* __restrict h) {
  const __m256i far = _mm256_set1_epi32(static_cast<int>(k.far) * 0x10001);
  const __m256i near = _mm256_set1_epi32(static_cast<int>(k.near) * 0x10001);
  const __m256i centre = _mm256_set1_epi32(static_cast<int>(k.centre) | (512 << 16));
  const __m256i restore = _mm256_set1_epi16(16448);
  int i = 0;
  for (; i + 32 <= n; i += 32) {
    const __m256i bytes =
        _mm256_packus_epi16(WeightedSixteenBiased<C>(v, i, far, near, centre, restore),
                            WeightedSixteenBiased<C>(v, i + 16, far, near, centre, restore));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(h + i), _mm256_permute4x64_epi64(bytes, 0xd8));
  }
  for (; i < n; ++i) {
    const int a = v[i - 2 * C] ^ 0x8000, b = v[i - C] ^ 0x8000, c = v[i] ^ 0x8000;
    const int d = v[i + C] ^ 0x8000, e = v[i + 2 * C] ^ 0x8000;
    const int sum = k.far * (a + e) + k.near * (b + d) + k.centre * c;
    h[i] = static_cast<uint8_t>((sum + (1 << 15)) >> 16);
  }
}
#endif

}  // namespace binomial
}  // namespace corridor
