// libFuzzer entry point for the cli target (tests/fuzz/fuzz_targets.h; tools/fuzz.sh cli SECONDS).
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  pyro::fuzz::cli(data, size);
  return 0;
}
