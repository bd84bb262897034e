#include "engine/io/staging_folder.h"

#include <unistd.h>

#include <system_error>

#include "engine/core/user_error.h"

namespace pyro {

namespace fs = std::filesystem;

StagingFolder::StagingFolder(const std::string& out) : out_(out) {
  fs::path target = fs::absolute(fs::path(out)).lexically_normal();
  if (target.filename().empty()) target = target.parent_path();  // "out/" names "out"
  staging_ = target.parent_path() /
             ("." + target.filename().string() + ".partial-" + std::to_string(::getpid()));
  std::error_code ec;
  fs::remove_all(staging_, ec);  // left by an earlier process with the same id, killed
  fs::create_directories(staging_, ec);
  if (ec)
    throw UserError(out, "--out", "cannot create the temporary folder " + staging_.string() +
                                      " beside the output folder: " + ec.message());
}

StagingFolder::~StagingFolder() {
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

void StagingFolder::commit() {
  std::error_code ec;
  fs::create_directories(out_, ec);
  if (ec) throw UserError(out_, "--out", "cannot create the output folder: " + ec.message());
  for (const fs::directory_entry& entry : fs::directory_iterator(staging_)) {
    fs::rename(entry.path(), fs::path(out_) / entry.path().filename(), ec);
    if (ec)
      throw UserError(out_, "--out", "cannot move " + entry.path().string() +
                                         " into the output folder: " + ec.message());
  }
}

}  // namespace pyro
