// libFuzzer target: RecoverDepth on arbitrary small images with arbitrary options and cameras
// (fuzz_input.h says how the bytes are read; fuzz_checks.h which contracts are checked). A
// broken contract traps, like a sanitizer finding, so libFuzzer saves the input.

#include <cstdio>

#include "tests/fuzz/fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string broken = corridor::fuzz::CheckRecoverDepthInput(data, size);
  if (!broken.empty()) {
    std::fprintf(stderr, "fuzz_recover_depth: %s\n", broken.c_str());
    __builtin_trap();
  }
  return 0;
}
