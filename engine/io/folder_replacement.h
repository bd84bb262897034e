#pragma once
// A folder output replaced as a whole (a baked flipbook, a chart set): the new folder is written
// beside the old one, on the same file system, as `.NAME.partial-PID`, and exchanged with it in
// one atomic rename (renameat2 with RENAME_EXCHANGE), so that a reader, or a kill at any moment,
// finds the old folder or the new one, never a mix, and no file of the old output survives into
// the new one (a bake of fewer frames leaves exactly its frames). Where the file system cannot
// exchange, the old folder is renamed aside first and the next run puts it back if it was killed
// in between. Leftovers of killed runs beside the folder are removed by the next run.
#include <filesystem>
#include <string>

namespace pyro {

class FolderReplacement {
 public:
  // Creates the folder's parent folders if needed, removes (or restores) what killed runs left,
  // and creates the staging folder. Throws UserError naming `out` (with `option`) when it is a
  // file or cannot be created, IoError when the file system refuses.
  explicit FolderReplacement(const std::string& out, const std::string& option = "--out");
  ~FolderReplacement();  // removes the staging folder unless committed
  FolderReplacement(const FolderReplacement&) = delete;
  FolderReplacement& operator=(const FolderReplacement&) = delete;

  const std::filesystem::path& path() const { return staging_; }
  int removed_leftovers() const { return removed_leftovers_; }
  bool restored_old_folder() const { return restored_; }

  // Syncs the staging folder, puts it in the place of `out` and removes the old folder. Throws
  // IoError.
  void commit();

 private:
  std::filesystem::path out_, staging_;
  int removed_leftovers_ = 0;
  bool restored_ = false, committed_ = false;
};

}  // namespace pyro
