#pragma once
// A folder output replaced as a whole (a baked flipbook, a chart set): the new folder is written
// beside the old one, on the same file system, as `.NAME.partial-PID`, and exchanged with it in
// one atomic rename (renameat2 with RENAME_EXCHANGE), so that a reader, or a kill at any moment,
// finds the old folder or the new one, never a mix, and no file of the old output survives into
// the new one (a bake of fewer frames leaves exactly its frames). Where the file system cannot
// exchange, the old folder is renamed aside first and the next run puts it back if it was killed
// in between. Leftovers of killed runs beside the folder are removed by the next run.
// The folder is an output of a kind (folder_output_kind.h): the new folder records it in its
// manifest, and passes the gate (output_gate.h) first: a folder holding files no output of the
// kind wrote is refused unless `overwrite`. Those files are never lost: each is linked into the
// new folder before the exchange.
#include <filesystem>
#include <string>

#include "engine/io/folder_output_kind.h"

namespace pyro {

class FolderReplacement {
 public:
  // Creates the folder's parent folders if needed, checks `out` at the gate, removes (or
  // restores) what killed runs left, and creates the staging folder. Throws UserError naming
  // `out` (with `option`) for a refusal, IoError when the file system refuses.
  FolderReplacement(const std::string& out, FolderOutputKind kind, bool overwrite = false,
                    const std::string& option = "--out");
  ~FolderReplacement();  // removes the staging folder unless committed
  FolderReplacement(const FolderReplacement&) = delete;
  FolderReplacement& operator=(const FolderReplacement&) = delete;

  const std::filesystem::path& path() const { return staging_; }
  int removed_leftovers() const { return removed_leftovers_; }
  bool restored_old_folder() const { return restored_; }

  // Writes the manifest, links in the old folder's files that no output wrote, syncs the
  // staging folder, puts it in the place of `out` and removes the old folder. Throws IoError.
  void commit();

 private:
  void keep_files_beside();

  std::filesystem::path out_, staging_;
  FolderOutputKind kind_;
  int removed_leftovers_ = 0;
  bool restored_ = false, committed_ = false;
};

}  // namespace pyro
