#include "engine/core/content_location.h"

// Compiled by the build with the build tree's paths and by PyrocumulusConfig.cmake with the
// installed ones (engine/core/content_location.h).
#if !defined(PYRO_CONTENT_LOCATION) || !defined(PYRO_FLIPBOOK_LOCATION)
#error "content_location.cpp needs PYRO_CONTENT_LOCATION and PYRO_FLIPBOOK_LOCATION"
#endif

namespace pyro {

const char* built_in_content_dir() { return PYRO_CONTENT_LOCATION; }
const char* built_in_flipbook_dir() { return PYRO_FLIPBOOK_LOCATION; }

}  // namespace pyro
