#include "systems/runtime/scene_runtime/default_flipbook.h"

#include <cstdlib>
#include <filesystem>

#include "engine/core/content_location.h"

namespace pyro {

std::string default_flipbook_folder() {
  if (const char* env = std::getenv("PYRO_FLIPBOOK_DIR"); env && *env) return env;
  return built_in_flipbook_dir();
}

bool default_flipbook_baked() {
  std::error_code ec;
  return std::filesystem::is_regular_file(
      std::filesystem::path(default_flipbook_folder()) / "flipbook.json", ec);
}

}  // namespace pyro
