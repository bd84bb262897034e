#pragma once
// A temporary folder beside an output folder: files are written into it and moved into the
// output folder only by commit(), so a command that fails part-way leaves the output folder as
// it was. The destructor removes the temporary folder and whatever is left in it.
#include <filesystem>
#include <string>

namespace pyro {

class StagingFolder {
 public:
  // Creates `.NAME.partial-PID` in the parent of `out` (creating the parent if needed).
  // Throws UserError naming `out` when it cannot.
  explicit StagingFolder(const std::string& out);
  ~StagingFolder();
  StagingFolder(const StagingFolder&) = delete;
  StagingFolder& operator=(const StagingFolder&) = delete;

  const std::filesystem::path& path() const { return staging_; }

  // Creates `out` if needed and renames every file of the staging folder into it (same file
  // system, so each rename is atomic and replaces a file of the same name).
  void commit();

 private:
  std::string out_;
  std::filesystem::path staging_;
};

}  // namespace pyro
