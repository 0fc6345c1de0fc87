#pragma once

// Unaligned AVX2 loads the row kernels share (private header of the kernels; for AVX2 callers
// only).

#include <cstdint>

#include "core/cpu_features.h"

#ifdef CORRIDOR_AVX2_VARIANTS
#include <immintrin.h>

namespace corridor {
namespace avx2 {

// Sixteen bytes widened to 16 bits, straight from memory.
__attribute__((target("avx2"))) inline __m256i Widen16(const uint8_t* p) {
  return _mm256_cvtepu8_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)));
}

// Sixteen 16-bit values from memory.
__attribute__((target("avx2"))) inline __m256i Load16(const uint16_t* p) {
  return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
}

}  // namespace avx2
}  // namespace corridor
#endif
