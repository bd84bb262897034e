#include "engine/io/scratch_folder.h"

#include <stdlib.h>

#include <system_error>

#include "engine/core/user_error.h"

namespace pyro {

std::filesystem::path ScratchFolder::make(const std::string& prefix) {
  std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
  if (!mkdtemp(pattern.data())) throw UserError(pattern, "a scratch folder", "a writable temporary folder");
  return pattern;
}

ScratchFolder::ScratchFolder(const std::string& prefix) : path(make(prefix)) {}

ScratchFolder::~ScratchFolder() {
  std::error_code ec;
  std::filesystem::remove_all(path, ec);
}

}  // namespace pyro
