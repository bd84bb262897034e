// libFuzzer entry point for the particles target (tests/fuzz/fuzz_targets.h; tools/fuzz.sh
// particles SECONDS).
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  pyro::fuzz::particles(data, size);
  return 0;
}
