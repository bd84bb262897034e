#include "engine/io/durable_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>

#include "engine/core/user_error.h"
#include "engine/io/io_error.h"
#include "engine/io/rename_fault.h"

namespace pyro {

namespace {

std::string folder_of(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

bool process_gone(const std::string& digits) {
  if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
    return false;
  std::error_code ec;
  return !std::filesystem::exists("/proc/" + digits, ec);
}

}  // namespace

int remove_stale_temporaries(const std::string& path) {
  namespace fs = std::filesystem;
  const std::string prefix = fs::path(path).filename().string() + ".partial-";
  int removed = 0;
  std::error_code ec;
  for (fs::directory_iterator it(folder_of(path), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) != 0 || !process_gone(name.substr(prefix.size()))) continue;
    std::error_code rm;
    if (it->is_regular_file(rm) && fs::remove(it->path(), rm)) ++removed;
  }
  return removed;
}

DurableFile::DurableFile(std::string path)
    : path_(std::move(path)), temp_(path_ + ".partial-" + std::to_string(::getpid())) {
  remove_stale_temporaries(path_);
  fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0 && (errno == ENOENT || errno == ENOTDIR))
    throw UserError(path_, "", "an existing folder to write the file into, found none");
  if (fd_ < 0) throw IoError(path_, "create the file", errno);
}

DurableFile::~DurableFile() {
  if (committed_) return;
  if (fd_ >= 0) ::close(fd_);
  ::unlink(temp_.c_str());
}

void DurableFile::fail(const std::string& action, int os_error) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlink(temp_.c_str());
  committed_ = true;  // nothing left for the destructor
  throw IoError(path_, action, os_error);
}

void DurableFile::write(const void* data, size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd_, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail("write", errno);
    if (n == 0) fail("write", EIO);
    p += n;
    size -= static_cast<size_t>(n);
  }
}

void DurableFile::commit() {
  if (::fsync(fd_) != 0) fail("flush the file to disk (fsync)", errno);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("close the file", errno);
  before_output_rename();
  if (::rename(temp_.c_str(), path_.c_str()) != 0) fail("rename the finished file into place", errno);
  committed_ = true;
  sync_folder(folder_of(path_));
}

void write_file_durably(const std::string& path, std::string_view bytes) {
  DurableFile file(path);
  file.write(bytes);
  file.commit();
}

void sync_folder(const std::string& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw IoError(folder, "open the folder to flush it (fsync)", errno);
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0 && err != EINVAL) throw IoError(folder, "flush the folder to disk (fsync)", err);
}

}  // namespace pyro
