#pragma once
// DurableFile's mechanism (engine/io/durable_file.h) for writers that go back to fill in sizes
// and indexes (video muxers) and that call it from a C library's callbacks: write() and seek()
// report a failure as an errno value instead of throwing. The bytes go to a hidden temporary
// file beside the destination, `.NAME.partial-PID` (the name remove_stale_staging in
// staging_folder.h removes inside an output folder once its process is gone); commit() fsyncs
// and closes it, renames it over the destination and fsyncs the folder; the destructor removes
// an uncommitted temporary, so a failed or abandoned write leaves nothing under either name.
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/io/replacing_file.h"

namespace pyro {

class SeekableOutputFile {
 public:
  // Removes the temporaries of `path` that dead processes left, then creates its own. Throws
  // UserError when the folder does not exist, IoError when the file cannot be created.
  explicit SeekableOutputFile(const std::string& path);

  // Writes all `size` bytes at the current position: 0, or the errno of the failure.
  int write(const void* data, size_t size) noexcept;
  // lseek: the new position, or minus the errno of the failure.
  int64_t seek(int64_t offset, int whence) noexcept;
  // The errno of the first write or seek that failed, or 0.
  int first_error() const { return first_error_; }

  // fsync, close, rename over the destination, fsync of the folder. Throws IoError (also for an
  // earlier failed write or seek) and then leaves nothing behind.
  void commit();

  const std::string& path() const { return file_.path(); }
  const std::string& temporary() const { return file_.temporary(); }

 private:
  ReplacingFile file_;
  int first_error_ = 0;
};

// The hidden temporary name of `path` for this process: `FOLDER/.NAME.partial-PID`.
std::string hidden_temporary_name(const std::string& path);

}  // namespace pyro
