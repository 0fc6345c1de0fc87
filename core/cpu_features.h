#pragma once

// Hot loops (the exact rasteriser's rows, the colour Sobel, the halving, the ceiling search's
// projections) are compiled twice where the compiler can target AVX2 per function: once for the
// baseline, once with __attribute__((target("avx2"))), each variant doing the same operations
// (no FMA) so that both give the same results. The AVX2 one runs where the CPU has it.
#if defined(__GNUC__) && defined(__x86_64__)
#define CORRIDOR_AVX2_VARIANTS 1
#endif

// On the loop bodies the baseline and AVX2 variants share (the rasteriser's rows, the colour
// Sobel, the binomial rows): the compiler must inline them, for an out-of-line body is compiled
// for the baseline only and its "AVX2" variant would not be one (GCC kept BinomialBlur's out).
#if defined(__GNUC__)
#define CORRIDOR_ALWAYS_INLINE __attribute__((always_inline))
#else
#define CORRIDOR_ALWAYS_INLINE
#endif

namespace corridor {

// True when AVX2 variants are compiled in and the CPU runs them (checked once).
bool CpuHasAvx2();

}  // namespace corridor
