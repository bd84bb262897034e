#include "engine/io/replacing_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>

#include "engine/core/file_kind.h"
#include "engine/core/user_error.h"
#include "engine/io/durable_file.h"
#include "engine/io/io_error.h"
#include "engine/io/rename_fault.h"

namespace pyro {

std::string folder_of(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

int write_all(int fd, const void* data, size_t size) noexcept {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : EIO;
    p += n;
    size -= static_cast<size_t>(n);
  }
  return 0;
}

ReplacingFile::ReplacingFile(std::string path, std::string temporary, int open_flags)
    : path_(std::move(path)), temp_(std::move(temporary)) {
  // The last line of the gate (output_gate.h): whatever a caller checked, a device node, FIFO,
  // socket or folder is never renamed over.
  if (const std::string kind = non_regular_file_kind(path_); !kind.empty() && kind != "no file")
    throw UserError(path_, "", "an absent path or a regular file to write; it is " + kind);
  fd_ = ::open(temp_.c_str(), open_flags | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0 && (errno == ENOENT || errno == ENOTDIR))
    throw UserError(path_, "", "an existing folder to write the file into, found none");
  if (fd_ < 0) throw IoError(path_, "create the file", errno);
}

ReplacingFile::~ReplacingFile() {
  if (done_) return;
  if (fd_ >= 0) ::close(fd_);
  ::unlink(temp_.c_str());
}

void ReplacingFile::fail(const std::string& action, int os_error) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlink(temp_.c_str());
  done_ = true;  // nothing left for the destructor
  throw IoError(path_, action, os_error);
}

void ReplacingFile::commit() {
  if (::fsync(fd_) != 0) fail("flush the file to disk (fsync)", errno);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("close the file", errno);
  before_output_rename();
  if (::rename(temp_.c_str(), path_.c_str()) != 0) fail("rename the finished file into place", errno);
  done_ = true;
  sync_folder(folder_of(path_));
}

}  // namespace pyro
