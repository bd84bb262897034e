// libFuzzer entry point for the png target (tests/fuzz/fuzz_targets.h; tools/fuzz.sh png SECONDS).
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  pyro::fuzz::png(data, size);
  return 0;
}
