#pragma once
// The one mechanism behind every file that replaces its destination whole: the bytes go to a
// temporary file beside the destination; commit() fsyncs and closes it (both checked), renames
// it over the destination and fsyncs the folder. Until commit() returns the destination is
// untouched; a failure removes the temporary and throws IoError (the destination and strerror);
// the destructor removes an uncommitted temporary. DurableFile (durable_file.h, throwing writes)
// and SeekableOutputFile (seekable_output_file.h, errno-returning writes and seeks for C
// libraries' callbacks) are its two faces; they choose the temporary's name.
#include <cstddef>
#include <string>

namespace pyro {

class ReplacingFile {
 public:
  // Creates `temporary` with `open_flags` (O_CREAT | O_TRUNC | O_CLOEXEC are added). Throws
  // UserError when the destination's folder does not exist or the destination is neither absent
  // nor a regular file (a device node, FIFO, socket or folder), IoError when the file cannot be
  // made.
  ReplacingFile(std::string path, std::string temporary, int open_flags);
  ~ReplacingFile();
  ReplacingFile(const ReplacingFile&) = delete;
  ReplacingFile& operator=(const ReplacingFile&) = delete;

  int fd() const { return fd_; }
  const std::string& path() const { return path_; }
  const std::string& temporary() const { return temp_; }

  // Closes and removes the temporary, then throws IoError(path, action, os_error).
  [[noreturn]] void fail(const std::string& action, int os_error);
  // fsync, close, rename over the destination, fsync of the folder.
  void commit();

 private:
  std::string path_, temp_;
  int fd_ = -1;
  bool done_ = false;
};

// Writes all `size` bytes to `fd`, continuing short writes and retrying EINTR: 0, or the errno of
// the failure (EIO for a write that wrote nothing).
int write_all(int fd, const void* data, size_t size) noexcept;

// The folder a destination path lies in ("." for a bare file name).
std::string folder_of(const std::string& path);

}  // namespace pyro
