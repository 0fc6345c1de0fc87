#include "core/cpu_features.h"

namespace corridor {

bool CpuHasAvx2() {
#ifdef CORRIDOR_AVX2_VARIANTS
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
#else
  return false;
#endif
}

}  // namespace corridor
