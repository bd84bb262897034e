#include "engine/io/staging_folder.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <system_error>

#include "engine/core/user_error.h"
#include "engine/io/durable_file.h"
#include "engine/io/io_error.h"
#include "engine/io/rename_fault.h"

namespace pyro {

namespace fs = std::filesystem;

namespace {

dev_t device_of(const fs::path& p) {
  struct stat st {};
  if (::stat(p.c_str(), &st) != 0) throw IoError(p.string(), "stat", errno);
  return st.st_dev;
}

bool process_alive(int pid) {
  std::error_code ec;
  return pid == ::getpid() || fs::exists("/proc/" + std::to_string(pid), ec);
}

// The folders in `folder` whose names start with `prefix` and end with the id of a process
// that is gone.
std::vector<fs::path> stale_in(const fs::path& folder, const std::string& prefix) {
  std::vector<fs::path> stale;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const int pid = staging_owner(name);
    if (pid > 0 && !process_alive(pid)) stale.push_back(it->path());
  }
  return stale;
}

int remove_all_of(const std::vector<fs::path>& folders) {
  int removed = 0;
  for (const fs::path& f : folders) {
    std::error_code rm;
    fs::remove_all(f, rm);
    if (!rm) ++removed;
  }
  return removed;
}

}  // namespace

fs::path normalized_output_path(const std::string& out) {
  fs::path target = fs::absolute(fs::path(out)).lexically_normal();
  if (target.filename().empty()) target = target.parent_path();  // "out/" names "out"
  return target;
}

int staging_owner(const std::string& name) {
  const size_t at = name.rfind(".partial-");
  if (name.empty() || name[0] != '.' || at == std::string::npos) return 0;
  const std::string digits = name.substr(at + 9);
  if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
    return 0;
  return std::atoi(digits.c_str());
}

std::vector<fs::path> stale_staging_folders(const fs::path& out) {
  std::vector<fs::path> folders;
  std::error_code ec;
  for (const fs::path& p : stale_in(normalized_output_path(out.string()), ".partial-"))
    if (fs::is_directory(p, ec)) folders.push_back(p);
  return folders;
}

int remove_stale_staging(const fs::path& out) {
  const fs::path target = normalized_output_path(out.string());
  // Inside `out`: staging folders (`.partial-PID`) and a durable file's temporary file cut by the
  // kill (`.pyro_manifest.json.partial-PID`). Beside `out`: the name older versions used
  // (`.NAME.partial-PID`).
  return remove_all_of(stale_in(target, ".")) +
         remove_all_of(stale_in(target.parent_path(), "." + target.filename().string() + ".partial-"));
}

bool create_output_folder(const std::string& out, const std::string& option) {
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec))
    throw UserError(out, option, "expected a folder for the output, found a file");
  if (fs::is_directory(out, ec)) return false;
  fs::create_directories(out, ec);
  if (!ec) return true;
  if (ec == std::errc::no_such_file_or_directory || ec == std::errc::not_a_directory ||
      ec == std::errc::file_exists)
    throw UserError(out, option, "cannot create the output folder: " + ec.message());
  throw IoError(out, "create the output folder", ec.value());
}

StagingFolder::StagingFolder(const std::string& out, bool remove_stale) : out_(normalized_output_path(out)) {
  std::error_code ec;
  created_out_ = create_output_folder(out, "--out");
  if (remove_stale) remove_stale_staging(out_);
  staging_ = out_ / (".partial-" + std::to_string(::getpid()));
  fs::remove_all(staging_, ec);  // left by an earlier process with the same id, killed
  if (::mkdir(staging_.c_str(), 0755) != 0) {
    const int err = errno;
    if (created_out_) fs::remove(out_, ec);
    throw IoError(staging_.string(), "create the temporary folder inside the output folder", err);
  }
  if (device_of(staging_) != device_of(out_))
    throw IoError(staging_.string(), "stage on the output folder's file system", EXDEV);
}

StagingFolder::~StagingFolder() {
  std::error_code ec;
  fs::remove_all(staging_, ec);
  if (created_out_ && fs::is_empty(out_, ec)) fs::remove(out_, ec);
}

void StagingFolder::commit() {
  std::error_code ec;
  std::vector<fs::path> records;
  for (fs::directory_iterator it(staging_, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().filename().string()[0] == '.') {
      records.push_back(it->path());
      continue;
    }
    const fs::path to = out_ / it->path().filename();
    before_output_rename();
    if (::rename(it->path().c_str(), to.c_str()) != 0)
      throw IoError(to.string(), "move the finished file into the output folder", errno);
  }
  if (ec) throw IoError(staging_.string(), "list the temporary folder", ec.value());
  for (const fs::path& record : records)
    if (::unlink(record.c_str()) != 0) throw IoError(record.string(), "remove", errno);
  if (::rmdir(staging_.c_str()) != 0)
    throw IoError(staging_.string(), "remove the emptied temporary folder", errno);
  created_out_ = false;  // holds the output now
  sync_folder(out_.string());
}

void StagingFolder::adopt(const fs::path& file) {
  const fs::path to = staging_ / file.filename();
  if (::rename(file.c_str(), to.c_str()) != 0)
    throw IoError(file.string(), "move a killed run's finished file into the temporary folder", errno);
}

}  // namespace pyro
