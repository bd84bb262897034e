#pragma once
// An output folder with one writer and a record of the run it holds.
//  * Lock: an advisory flock on the folder itself, held for the object's life. A second run into
//    the same folder is refused (UserError) or, with `wait`, waits for the first to finish.
//  * Manifest: `.pyro_manifest.json` in the folder records the run's identity (its digest and
//    parts: systems/runtime/scene_runtime/run_identity.h), what the run chose once for all its ranges
//    (a quality pick), the files the folder holds and each file's SHA-256 ("sha256": {name: hex},
//    computed as the file is moved in). A file is held only while its bytes have that digest: one
//    truncated, edited or copied over another is damaged, never held, and commit() removes it
//    unless the run wrote it again.
//    A folder holds one identity: a run of another identity, or into a folder holding frames no
//    manifest accounts for, is refused, naming what differs, unless
//      - the run is made from the same source as the folder's run (the identity's "source": its
//        scene file, the same by device and inode or by path) and the folder holds nothing else:
//        it replaces that earlier run, as with `overwrite`;
//      - `overwrite`: once the run has succeeded, the other run's files that it did not rewrite
//        are removed; files no manifest names stay;
//      - `resume`: the other identity's frames are stale: all are drawn again and the count said.
//    Ranges of one identity add to the folder.
//  * Staging: files are written into staging().path() and moved in by commit()
//    (engine/io/staging_folder.h), which also records them in the manifest. The staging folder
//    holds a record of its run's identity, so that what a killed run left can be told apart.
//  * Resume: a killed run's staging folder holds the frames it finished (each file is renamed
//    into place only once complete: durable_file.h). With `resume`, those of a killed run of the
//    same identity are adopted into this run's staging folder; without it they are removed with
//    the rest of the stale staging (and counted, for a note).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/io/folder_output_kind.h"
#include "engine/io/staging_folder.h"

namespace pyro {

struct OutputFolderOptions {
  bool wait = false;       // wait for another writer instead of refusing
  bool overwrite = false;  // replace a folder holding another run's files
  bool resume = false;     // keep the files killed runs of this identity finished; redraw stale ones
};

class OutputFolder {
 public:
  // Creates `out` if needed, takes its lock and checks the manifest against the run's identity:
  // `identity_json` is a JSON object's text, {"digest": hex, "parts": {...}}. `describe(a, b)`
  // says what differs between two identities' parts, for messages. Throws UserError for a
  // refusal. Nothing is staged until begin().
  using Difference = std::string (*)(const std::string& before_parts, const std::string& now_parts);
  OutputFolder(const std::string& out, const std::string& identity_json, Difference describe,
               OutputFolderOptions options);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  // What this identity's run recorded under `key` (the manifest's, else a killed run's staging
  // record's): a JSON value's text, or empty. Ranges of one run share a choice made once.
  std::string recorded(const std::string& key) const;

  // Creates the staging folder with a record of the identity and `choices_json` (a JSON object
  // of what the run chose, e.g. {"quality": ...}; recorded() reads it back), then adopts (with
  // `resume`) or discards the finished files of killed runs of the same identity and choices.
  void begin(const std::string& choices_json = "{}");

  StagingFolder& staging() { return *staging_; }
  // The file names the folder holds for this identity, each checked against the SHA-256 the
  // manifest records for it: what a resumed run may skip.
  const std::vector<std::string>& held_files() const { return held_; }
  // The file names the manifest lists for this identity whose bytes differ from their recorded
  // SHA-256 (or that have none recorded): never held; removed by commit() unless rewritten.
  const std::vector<std::string>& damaged_files() const { return damaged_; }
  // The SHA-256 of each held file (after commit(): of every file the folder holds for the run).
  const std::map<std::string, std::string>& file_digests() const { return digests_; }
  // With `resume`: the file names adopted from killed runs (now in staging().path()).
  const std::vector<std::string>& adopted_files() const { return adopted_; }
  // Without `resume`: how many finished files of this identity killed runs had left (removed).
  int discarded_files() const { return discarded_; }
  // With `resume` or `overwrite` over another identity: how many of its files are replaced, and
  // what differed (empty when nothing is replaced).
  int replaced_files() const { return static_cast<int>(stale_.size()); }
  const std::string& replaced_because() const { return replaced_because_; }
  // How many leftovers of killed runs of other identities begin() removed.
  int removed_leftovers() const { return removed_leftovers_; }

  // Moves the staged files in, then writes the manifest with every file the folder now holds
  // for this identity. Throws IoError.
  void commit();

 private:
  void lock(bool wait);
  void check_manifest(OutputFolderOptions options);
  void take_killed_runs_files(bool resume);
  bool same_run(const std::filesystem::path& record) const;

  std::string out_, identity_json_, digest_, choices_json_ = "{}";
  Difference describe_;
  bool created_ = false, resume_ = false;
  int lock_fd_ = -1;
  std::string manifest_choices_;  // the manifest's choices when it holds this identity
  std::vector<std::string> held_, adopted_, damaged_;
  std::map<std::string, std::string> digests_;  // held file -> SHA-256
  std::vector<std::string> stale_;  // the files of the run being replaced
  std::string replaced_because_;
  int discarded_ = 0, removed_leftovers_ = 0;
  std::unique_ptr<StagingFolder> staging_;
};

// The manifest's file name inside an output folder.
inline constexpr const char* kOutputManifestName = kFolderOutputManifest;
// The record of a run's identity inside its staging folder.
inline constexpr const char* kStagingRecordName = ".pyro_run.json";

}  // namespace pyro
