#pragma once
// What `pyro farm submit` writes into the output folder so that `pyro farm collect` and
// `pyro farm resubmit` (run later, by hand or as a Slurm job, on any node) know the job:
// DIR/.farm/farm.json holds the scene, the frames, the chunk size, the run's identity (what
// `pyro render` keys output folders on: systems/runtime/scene_runtime/run_identity.h), the absolute path
// of the pyro binary every task runs and the render options passed on to each task, plus the
// Slurm jobs submitted so far. Beside it: the batch scripts and the tasks' logs, and chunks/A-B,
// the output folder of the task rendering frames A..B.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "systems/runtime/scene_runtime/frame_range.h"

namespace pyro {

struct FarmSubmission {
  std::string array_job;           // the render job array's Slurm job id
  std::string collect_job;         // the collect job's, run after every task of the array
  std::vector<FrameRange> chunks;  // one per array task, in task order
};

// What the job asks of Slurm besides the partition (`pyro farm submit`'s scheduler options,
// checked by tools/farm/slurm_options.h): empty or 0 leaves the cluster's default.
struct FarmScheduler {
  std::string time;     // the render tasks' time limit, in one of Slurm's formats
  std::string mem;      // memory per render task, e.g. 4G
  int cpus_per_task = 0;  // CPUs per render task, also its render and llvmpipe threads
  std::string account;  // the account every job of the farm is charged to
  std::vector<std::string> sbatch_args;  // passed to every sbatch of the job, as given
};

struct FarmRecord {
  std::string scene;  // absolute path: every node reads it there
  FrameRange frames;
  int chunk = 1;
  nlohmann::json identity;  // {"digest", "parts", "scene_file"}, as `pyro render` computes it
  std::string pyro;         // absolute path of the binary the tasks and the collect job run
  std::vector<std::string> render_options;  // e.g. {"--width", "160", "--format", "png"}
  std::string partition;                    // empty: the cluster's default partition
  FarmScheduler scheduler;
  double frames_per_second = 24.0;          // the scene's, for collect --video
  std::vector<FarmSubmission> submissions;
  // The digests of the job's earlier identities (its scene or assets edited, then the job rendered
  // again: `pyro farm resubmit --overwrite`): DIR's frames of those are this job's to replace.
  std::vector<std::string> superseded;

  std::string digest() const { return identity.at("digest").get<std::string>(); }
};

// DIR/.farm and the paths in it.
std::filesystem::path farm_folder(const std::string& dir);
std::filesystem::path farm_record_path(const std::string& dir);
// The output folder of the task rendering `chunk`: DIR/.farm/chunks/A-B.
std::filesystem::path chunk_folder(const std::string& dir, const FrameRange& chunk);

nlohmann::json farm_record_json(const FarmRecord& record);
// Throws UserError naming `file` and the JSON pointer of what is missing or malformed.
FarmRecord farm_record_from_json(const nlohmann::json& j, const std::string& file);

// The record of the farm job whose output folder is `dir`. Throws UserError naming the folder
// when it does not exist and the record file when there is none or it is damaged.
FarmRecord read_farm_record(const std::string& dir);
// Writes DIR/.farm/farm.json durably (a reader never sees half a record). Throws IoError.
void write_farm_record(const std::string& dir, const FarmRecord& record);

}  // namespace pyro
