#pragma once
#include <string>

namespace pyro {

// The folder holding scenes and shaders: $PYRO_CONTENT_DIR when set, else the one this build
// records (engine/core/content_location.h: the source tree's content/ folder in a build tree,
// <prefix>/share/pyrocumulus once installed).
std::string content_dir();
std::string content_path(const std::string& relative);

// Reads a whole file; throws pyro::UserError naming the file when it cannot be read.
std::string read_text_file(const std::string& path);

}  // namespace pyro
