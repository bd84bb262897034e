#pragma once
// The running program's build: the GNU build ID that the linker writes into the executable (a
// hash of its contents), so that a rebuilt engine is another engine for a run's identity and the
// caches, while the same build on another machine or path is the same one.
#include <string>

namespace pyro {

// The main program's build ID in hex; empty when it has none (linked without --build-id).
std::string program_build_id();

}  // namespace pyro
