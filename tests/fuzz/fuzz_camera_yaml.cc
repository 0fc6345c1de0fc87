// libFuzzer target: the calibration parser (ParseCameraYaml, the in-memory half of
// ReadCameraYaml) on arbitrary bytes; fuzz_checks.h says which contracts are checked. A broken
// contract traps, like a sanitizer finding, so libFuzzer saves the input.

#include <cstdio>

#include "tests/fuzz/fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string broken = corridor::fuzz::CheckCameraYamlInput(data, size);
  if (!broken.empty()) {
    std::fprintf(stderr, "fuzz_camera_yaml: %s\n", broken.c_str());
    __builtin_trap();
  }
  return 0;
}
