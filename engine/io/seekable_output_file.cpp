#include "engine/io/seekable_output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>

#include "engine/core/user_error.h"
#include "engine/io/durable_file.h"
#include "engine/io/io_error.h"
#include "engine/io/rename_fault.h"

namespace pyro {

namespace {

std::filesystem::path folder_of(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::filesystem::path(".") : parent;
}

std::string hidden_name(const std::string& path) {
  return (folder_of(path) / ("." + std::filesystem::path(path).filename().string())).string();
}

}  // namespace

std::string hidden_temporary_name(const std::string& path) {
  return hidden_name(path) + ".partial-" + std::to_string(::getpid());
}

SeekableOutputFile::SeekableOutputFile(std::string path)
    : path_(std::move(path)), temp_(hidden_temporary_name(path_)) {
  remove_stale_temporaries(hidden_name(path_));  // `.NAME.partial-PID` of processes that are gone
  fd_ = ::open(temp_.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0 && (errno == ENOENT || errno == ENOTDIR))
    throw UserError(path_, "", "an existing folder to write the file into, found none");
  if (fd_ < 0) throw IoError(path_, "create the file", errno);
}

SeekableOutputFile::~SeekableOutputFile() {
  if (done_) return;
  if (fd_ >= 0) ::close(fd_);
  ::unlink(temp_.c_str());
}

int SeekableOutputFile::write(const void* data, size_t size) noexcept {
  if (first_error_) return first_error_;
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd_, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return first_error_ = (n < 0 ? errno : EIO);
    p += n;
    size -= static_cast<size_t>(n);
  }
  return 0;
}

int64_t SeekableOutputFile::seek(int64_t offset, int whence) noexcept {
  if (first_error_) return -first_error_;
  const off_t at = ::lseek(fd_, static_cast<off_t>(offset), whence);
  if (at < 0) return -(first_error_ = errno);
  return at;
}

void SeekableOutputFile::fail(const std::string& action, int os_error) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlink(temp_.c_str());
  done_ = true;  // nothing left for the destructor
  throw IoError(path_, action, os_error);
}

void SeekableOutputFile::commit() {
  if (first_error_) fail("write the file", first_error_);
  if (::fsync(fd_) != 0) fail("flush the file to disk (fsync)", errno);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("close the file", errno);
  before_output_rename();
  if (::rename(temp_.c_str(), path_.c_str()) != 0) fail("rename the finished file into place", errno);
  done_ = true;
  sync_folder(folder_of(path_).string());
}

}  // namespace pyro
