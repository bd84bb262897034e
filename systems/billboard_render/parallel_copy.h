#pragma once
// memcpy split over the calling arena's threads in 1 MiB pieces: filling a mapped GPU buffer
// from several cores.
#include <cstddef>

namespace pyro {

void parallel_copy(void* to, const void* from, std::size_t bytes);

}  // namespace pyro
