#pragma once
// A temporary folder inside an output folder: files are written into it and moved into the
// output folder only by commit(), so a command that fails part-way leaves the output folder as
// it was. Being inside the output folder, it is on the same file system (checked: st_dev), so
// every move is an atomic rename even when the output folder is a mount point. The destructor
// removes the temporary folder and whatever is left in it, and the output folder too when this
// object created it and it is still empty.
#include <filesystem>
#include <string>
#include <vector>

namespace pyro {

class StagingFolder {
 public:
  // Creates `out` if needed, removes staging folders left in it by processes that are gone
  // (remove_stale_staging; unless `remove_stale` is false, for a caller that first adopts what
  // they hold) and creates `out/.partial-PID`. Throws UserError naming `out` when `out` is a
  // file or cannot be created, IoError when the staging folder cannot.
  explicit StagingFolder(const std::string& out, bool remove_stale = true);
  ~StagingFolder();
  StagingFolder(const StagingFolder&) = delete;
  StagingFolder& operator=(const StagingFolder&) = delete;

  const std::filesystem::path& path() const { return staging_; }

  // Renames every file of the staging folder into `out` (replacing a file of the same name),
  // but for those whose names start with '.' (the staging folder's own records, removed last),
  // removes the staging folder and fsyncs `out`. Throws IoError.
  void commit();

  // Moves `file` (on the same file system: another staging folder of `out`) into this staging
  // folder under its own name. Throws IoError.
  void adopt(const std::filesystem::path& file);

 private:
  std::filesystem::path out_, staging_;
  bool created_out_ = false;
};

// `out` as an absolute, normal path naming the folder itself ("out/" names "out").
std::filesystem::path normalized_output_path(const std::string& out);

// Creates the output folder `out` (and its parents) unless it exists; returns whether it did.
// Throws UserError(out, option, ...) when `out` is a file or its parent is missing or a file
// (the user's to fix), IoError when the file system refuses (read-only, full, no permission).
bool create_output_folder(const std::string& out, const std::string& option);

// The process id a staging folder's name ends with (`.partial-PID`, `.NAME.partial-PID`), or 0.
int staging_owner(const std::string& name);

// The staging folders inside `out` whose process is gone: what killed runs left.
std::vector<std::filesystem::path> stale_staging_folders(const std::filesystem::path& out);

// Removes, inside `out` and beside it, every staging folder of `out` whose process is gone (no
// /proc/PID), and inside `out` the temporary files (`.NAME.partial-PID`) of such processes:
// what a killed run left. Returns how many were removed.
int remove_stale_staging(const std::filesystem::path& out);

}  // namespace pyro
