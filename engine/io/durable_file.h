#pragma once
// Durable, atomic file output. Bytes go to a temporary file beside the destination
// (`NAME.partial-PID`); every write, the fsync and the close are checked, then the file is
// renamed into place and its folder fsynced. A reader never sees a half-written file under the
// final name, and once commit() returns the file survives a crash. Any failure throws IoError
// (the file and strerror) and removes the temporary file; a destination folder that does not
// exist is the user's mistake (UserError).
#include <cstddef>
#include <string>
#include <string_view>

#include "engine/io/replacing_file.h"

namespace pyro {

class DurableFile {
 public:
  // Removes the temporaries of `path` that dead processes left, then creates its own; the
  // destructor removes it unless committed (replacing_file.h).
  explicit DurableFile(const std::string& path);

  void write(const void* data, size_t size);
  void write(std::string_view bytes) { write(bytes.data(), bytes.size()); }
  // fsync, close, rename over `path`, fsync of the folder.
  void commit() { file_.commit(); }

 private:
  ReplacingFile file_;
};

// Removes the temporary files (`NAME.partial-PID`) of `path` that killed processes left (no
// /proc/PID); returns how many. DurableFile's constructor calls it for its own destination.
int remove_stale_temporaries(const std::string& path);

// DurableFile in one call.
void write_file_durably(const std::string& path, std::string_view bytes);

// fsync of a folder, so that the renames and creations inside it are on disk. Throws IoError.
void sync_folder(const std::string& folder);

}  // namespace pyro
