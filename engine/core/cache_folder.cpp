#include "engine/core/cache_folder.h"

#include <cstdlib>
#include <filesystem>

namespace pyro {

std::string cache_folder() {
  namespace fs = std::filesystem;
  if (const char* d = std::getenv("PYRO_CACHE_DIR"); d && *d) return d;
  if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d) return (fs::path(d) / "pyrocumulus").string();
  if (const char* d = std::getenv("HOME"); d && *d) return (fs::path(d) / ".cache" / "pyrocumulus").string();
  return {};
}

}  // namespace pyro
