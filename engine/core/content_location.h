#pragma once

namespace pyro {

// Where this build of the engine finds its content and its default flame flipbook unless
// PYRO_CONTENT_DIR / PYRO_FLIPBOOK_DIR say otherwise. A build tree records the source tree's
// content/ folder and its own flipbooks/fire folder; an installed package compiles
// content_location.cpp again from its PyrocumulusConfig.cmake with <prefix>/share/pyrocumulus,
// so that the installed engine finds the installed content wherever the package was installed.
const char* built_in_content_dir();
const char* built_in_flipbook_dir();

}  // namespace pyro
