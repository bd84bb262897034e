#pragma once
// Where Pyrocumulus keeps what it can measure again (quality picks, content digests):
// $PYRO_CACHE_DIR, else $XDG_CACHE_HOME/pyrocumulus, else $HOME/.cache/pyrocumulus. A cache is
// an input like any other: what is read from it is checked, a damaged entry is dropped with a
// note, and a cache that cannot be written never fails a command.
#include <string>

namespace pyro {

// The cache folder; empty when no variable names one.
std::string cache_folder();

}  // namespace pyro
