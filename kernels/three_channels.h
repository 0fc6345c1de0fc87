#pragma once

// Byte shuffles that split 8-bit three-channel pixels into planes with AVX2, 32 pixels a step
// (private header of the kernels; for AVX2 callers only).

#include <cstdint>

#include "core/cpu_features.h"

#ifdef CORRIDOR_AVX2_VARIANTS
#include <immintrin.h>

namespace corridor {
namespace three_channels {

// kPick.bytes[c][part][i]: the byte of the 16-byte part `part` of 16 pixels (48 bytes) that holds
// channel c of pixel i, or -1 (a zero from the shuffle) where another part holds it.
struct Pick {
  alignas(16) signed char bytes[3][3][16];
  constexpr Pick() : bytes() {
    for (int c = 0; c < 3; ++c) {
      for (int part = 0; part < 3; ++part) {
        for (int i = 0; i < 16; ++i) {
          const int at = 3 * i + c - 16 * part;
          bytes[c][part][i] = static_cast<signed char>(at >= 0 && at < 16 ? at : -1);
        }
      }
    }
  }
};
inline constexpr Pick kPick;

// Part `part` of pixels [0, 16) at `pixels` in the low lane, of pixels [16, 32) in the high one.
__attribute__((target("avx2"))) inline __m256i LoadPart(const uint8_t* pixels, int part) {
  const uint8_t* p = pixels + 16 * part;
  return _mm256_inserti128_si256(
      _mm256_castsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p))),
      _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 48)), 1);
}

// The shuffle of channel c from part `part`, in both lanes.
__attribute__((target("avx2"))) inline __m256i PickOf(int c, int part) {
  return _mm256_broadcastsi128_si256(
      _mm_load_si128(reinterpret_cast<const __m128i*>(kPick.bytes[c][part])));
}

// Channel c of 32 pixels from their three loaded parts and c's three shuffles.
__attribute__((target("avx2"))) inline __m256i Channel(const __m256i* parts, const __m256i* pick) {
  return _mm256_or_si256(_mm256_or_si256(_mm256_shuffle_epi8(parts[0], pick[0]),
                                         _mm256_shuffle_epi8(parts[1], pick[1])),
                         _mm256_shuffle_epi8(parts[2], pick[2]));
}

}  // namespace three_channels
}  // namespace corridor
#endif
