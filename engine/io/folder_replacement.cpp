#include "engine/io/folder_replacement.h"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

#include "engine/core/user_error.h"
#include "engine/io/durable_file.h"
#include "engine/io/io_error.h"
#include "engine/io/output_gate.h"
#include "engine/io/rename_fault.h"
#include "engine/io/staging_folder.h"

namespace pyro {

namespace fs = std::filesystem;

namespace {

// Where the fallback keeps the old folder while the new one moves in.
fs::path aside_name(const fs::path& out, int pid) {
  return out.parent_path() / ("." + out.filename().string() + ".replaced-" + std::to_string(pid));
}

// Puts back an old folder that a killed fallback had moved aside (the folder itself is then
// missing); removes such folders of dead processes otherwise. Returns whether one was restored.
bool restore_or_remove_aside(const fs::path& out) {
  const std::string prefix = "." + out.filename().string() + ".replaced-";
  bool restored = false;
  std::error_code ec;
  for (fs::directory_iterator it(out.parent_path(), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string pid = name.substr(prefix.size());
    if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    std::error_code gone;
    if (fs::exists("/proc/" + pid, gone)) continue;  // its process still runs
    if (!fs::exists(out, gone) && ::rename(it->path().c_str(), out.c_str()) == 0) {
      restored = true;
      continue;
    }
    fs::remove_all(it->path(), gone);
  }
  return restored;
}

}  // namespace

FolderReplacement::FolderReplacement(const std::string& out, FolderOutputKind kind, bool overwrite,
                                     const std::string& option)
    : out_(normalized_output_path(out)), kind_(std::move(kind)) {
  std::error_code ec;
  if (fs::exists(out_, ec) && !fs::is_directory(out_, ec))
    throw UserError(out, option, "expected a folder for the output, found a file");
  create_output_folder(out_.parent_path().string(), option);
  restored_ = restore_or_remove_aside(out_);
  OutputGate().writes({out, option, OutputShape::folder, kind_, overwrite}).check();
  if (fs::is_directory(out_, ec)) removed_leftovers_ = remove_stale_staging(out_);
  staging_ = out_.parent_path() / ("." + out_.filename().string() + ".partial-" + std::to_string(::getpid()));
  fs::remove_all(staging_, ec);  // left by an earlier process with the same id, killed
  if (::mkdir(staging_.c_str(), 0755) != 0)
    throw IoError(staging_.string(), "create the temporary folder beside the output folder", errno);
}

FolderReplacement::~FolderReplacement() {
  std::error_code ec;
  if (!committed_) fs::remove_all(staging_, ec);
}

// The old folder's files that no output wrote (the user's), linked into the new folder (copied
// where the file system has no hard links), unless the new output wrote a file of that name.
void FolderReplacement::keep_files_beside() {
  for (const std::string& file : read_folder_output(out_, kind_).foreign) {
    const fs::path from = out_ / file, to = staging_ / file;
    std::error_code ec;
    if (fs::exists(to, ec)) continue;
    fs::create_directories(to.parent_path(), ec);
    if (::link(from.c_str(), to.c_str()) == 0) continue;
    if (!fs::copy_file(from, to, ec))
      throw IoError(from.string(), "keep the file in the replaced folder", ec.value());
  }
}

void FolderReplacement::commit() {
  write_folder_output_manifest(staging_, kind_);
  keep_files_beside();
  sync_folder(staging_.string());
  std::error_code ec;
  before_output_rename();
  if (!fs::exists(out_, ec)) {
    if (::rename(staging_.c_str(), out_.c_str()) != 0)
      throw IoError(out_.string(), "move the finished folder into place", errno);
  } else if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, out_.c_str(), RENAME_EXCHANGE) == 0) {
    fs::remove_all(staging_, ec);  // the old folder, now under the staging name
  } else if (errno == EINVAL || errno == ENOSYS || errno == ENOTSUP) {
    // No exchange on this file system: the old folder aside, the new one in, the old one gone.
    const fs::path aside = aside_name(out_, ::getpid());
    if (::rename(out_.c_str(), aside.c_str()) != 0)
      throw IoError(out_.string(), "move the old folder aside", errno);
    before_output_rename();
    if (::rename(staging_.c_str(), out_.c_str()) != 0) {
      const int error = errno;
      ::rename(aside.c_str(), out_.c_str());
      throw IoError(out_.string(), "move the finished folder into place", error);
    }
    fs::remove_all(aside, ec);
  } else {
    throw IoError(out_.string(), "exchange the finished folder with the old one", errno);
  }
  committed_ = true;
  sync_folder(out_.parent_path().string());
}

}  // namespace pyro
