#include "engine/io/seekable_output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>

#include "engine/io/durable_file.h"

namespace pyro {

namespace {

std::string hidden_name(const std::string& path) {
  return (std::filesystem::path(folder_of(path)) / ("." + std::filesystem::path(path).filename().string()))
      .string();
}

std::string fresh_hidden_temporary(const std::string& path) {
  remove_stale_temporaries(hidden_name(path));  // `.NAME.partial-PID` of processes that are gone
  return hidden_temporary_name(path);
}

}  // namespace

std::string hidden_temporary_name(const std::string& path) {
  return hidden_name(path) + ".partial-" + std::to_string(::getpid());
}

SeekableOutputFile::SeekableOutputFile(const std::string& path)
    : file_(path, fresh_hidden_temporary(path), O_RDWR) {}

int SeekableOutputFile::write(const void* data, size_t size) noexcept {
  if (first_error_) return first_error_;
  return first_error_ = write_all(file_.fd(), data, size);
}

int64_t SeekableOutputFile::seek(int64_t offset, int whence) noexcept {
  if (first_error_) return -first_error_;
  const off_t at = ::lseek(file_.fd(), static_cast<off_t>(offset), whence);
  if (at < 0) return -(first_error_ = errno);
  return at;
}

void SeekableOutputFile::commit() {
  if (first_error_) file_.fail("write the file", first_error_);
  file_.commit();
}

}  // namespace pyro
