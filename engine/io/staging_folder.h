#pragma once
// A temporary folder inside an output folder: files are written into it and moved into the
// output folder only by commit(), so a command that fails part-way leaves the output folder as
// it was. Being inside the output folder, it is on the same file system (checked: st_dev), so
// every move is an atomic rename even when the output folder is a mount point. The destructor
// removes the temporary folder and whatever is left in it, and the output folder too when this
// object created it and it is still empty.
#include <filesystem>
#include <string>

namespace pyro {

class StagingFolder {
 public:
  // Creates `out` if needed, removes staging folders left in it by processes that are gone
  // (remove_stale_staging) and creates `out/.partial-PID`. Throws UserError naming `out` when
  // `out` is a file or cannot be created, IoError when the staging folder cannot.
  explicit StagingFolder(const std::string& out);
  ~StagingFolder();
  StagingFolder(const StagingFolder&) = delete;
  StagingFolder& operator=(const StagingFolder&) = delete;

  const std::filesystem::path& path() const { return staging_; }
  const std::filesystem::path& out() const { return out_; }

  // Renames every file of the staging folder into `out` (replacing a file of the same name),
  // removes the staging folder and fsyncs `out`. Throws IoError.
  void commit();

 private:
  std::filesystem::path out_, staging_;
  bool created_out_ = false;
};

// The process id a staging folder's name ends with (`.partial-PID`, `.NAME.partial-PID`), or 0.
int staging_owner(const std::string& name);

// Removes, inside `out` and beside it, every staging folder of `out` whose process is gone (no
// /proc/PID): what a killed run left. Returns how many were removed.
int remove_stale_staging(const std::filesystem::path& out);

}  // namespace pyro
