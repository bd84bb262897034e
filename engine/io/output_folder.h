#pragma once
// An output folder with one writer and a record of what it holds.
//  * Lock: an advisory flock on the folder itself, held for the object's life. A second run into
//    the same folder is refused (UserError) or, with `wait`, waits for the first to finish.
//  * Manifest: `.pyro_manifest.json` in the folder names the scene, the settings (a JSON object
//    from the caller: whatever changes the pixels) and the files the folder holds. A run whose
//    scene or settings differ from the manifest's, or into a folder holding frames no manifest
//    accounts for, is refused unless `overwrite` is set; then, once the run has succeeded, the
//    files it did not rewrite are removed, so the folder never mixes two runs.
//  * Staging: files are written into staging().path() and moved in by commit()
//    (engine/io/staging_folder.h), which also records them in the manifest. The staging folder
//    holds a record of its scene and settings, so that what a killed run left can be told apart.
//  * Resume: a killed run's staging folder holds the frames it finished (each file is renamed
//    into place only once complete: durable_file.h). With `resume`, those of a killed run with
//    the same scene and settings are adopted into this run's staging folder; without it they
//    are removed with the rest of the stale staging (and counted, for a note).
#include <memory>
#include <string>
#include <vector>

#include "engine/io/staging_folder.h"

namespace pyro {

struct OutputFolderOptions {
  bool wait = false;       // wait for another writer instead of refusing
  bool overwrite = false;  // replace a folder holding another scene's or settings' files
  bool resume = false;     // keep the files killed runs of this scene and settings finished
};

class OutputFolder {
 public:
  // Creates `out` if needed, takes its lock, checks the manifest, then creates the staging
  // folder. `settings_json` is a JSON object's text. Throws UserError for a refusal.
  OutputFolder(const std::string& out, const std::string& scene, const std::string& settings_json,
               OutputFolderOptions options);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  StagingFolder& staging() { return *staging_; }
  // The file names the folder holds for this scene and settings (empty after a refusal-free
  // overwrite or for a new folder): what a resumed run may skip.
  const std::vector<std::string>& held_files() const { return held_; }
  // With `resume`: the file names adopted from killed runs (now in staging().path()).
  const std::vector<std::string>& adopted_files() const { return adopted_; }
  // Without `resume`: how many finished files of this scene and settings killed runs had left
  // (removed now).
  int discarded_files() const { return discarded_; }

  // Moves the staged files in, then writes the manifest with every file the folder now holds
  // for this scene and settings. Throws IoError.
  void commit();

 private:
  void lock(bool wait);
  void check_manifest(bool overwrite);
  void write_run_record();
  void take_killed_runs_files(bool resume);
  bool same_run(const std::filesystem::path& record) const;

  std::string out_, scene_, settings_json_;
  int lock_fd_ = -1;
  std::vector<std::string> held_, adopted_;
  std::vector<std::string> stale_;  // with overwrite: the files of the run being replaced
  int discarded_ = 0;
  std::unique_ptr<StagingFolder> staging_;
};

// The manifest's file name inside an output folder.
inline constexpr const char* kOutputManifestName = ".pyro_manifest.json";
// The record of a run's scene and settings inside its staging folder.
inline constexpr const char* kStagingRecordName = ".pyro_run.json";

}  // namespace pyro
