#include "engine/core/content_path.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/core/content_location.h"
#include "engine/core/user_error.h"

namespace pyro {

std::string content_dir() {
  if (const char* env = std::getenv("PYRO_CONTENT_DIR"); env && *env) return env;
  return built_in_content_dir();
}

std::string content_path(const std::string& relative) {
  return (std::filesystem::path(content_dir()) / relative).string();
}

std::string read_text_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw UserError(path, "", "expected a file, found a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UserError(path, "", std::string("cannot open file: ") + std::strerror(errno));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace pyro
