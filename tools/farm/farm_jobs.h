#pragma once
// The farm's three steps as `pyro farm` runs them (docs/farm.md): submit a scene's frames as a
// job array of chunks and a collect job, collect the chunks' frames into the output folder, and
// resubmit only the frames still missing. Each returns the text it reports on standard output;
// notes go to a NoteSink. Throws UserError for what the user can get wrong, IoError when the
// file system fails.
#include <functional>
#include <string>
#include <vector>

#include "engine/io/video_file.h"
#include "tools/farm/farm_record.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

struct FarmSubmitRequest {
  std::string scene, out, frames, partition;
  int chunk = 0;
  FarmScheduler scheduler;  // --time, --mem, --cpus-per-task, --account, --sbatch-arg
  bool dry_run = false;  // print the batch scripts and sbatch commands; submit nothing
  int width = 0, height = 0;
  std::string format = "png";
  bool depth = false;
  RuntimeOptions runtime;
  std::vector<std::string> render_options;  // passed on to each task's `pyro render` as given
};

// Writes the batch scripts and the farm record into the output folder and submits the job array
// and the collect job (or, dry_run, returns the scripts and sbatch commands).
std::string submit_farm(const FarmSubmitRequest& request);

struct FarmCollectRequest {
  std::string dir, video;  // video: the frames also encoded into it; empty: none
  int video_quality = VideoWriter::default_quality;
};

std::string collect_farm_job(const FarmCollectRequest& request, const NoteSink& note);

struct FarmResubmitRequest {
  std::string dir;
  bool dry_run = false;
  // The scene or an asset edited since the submit (or another pyro): render the job again for
  // them as they are now, rather than refuse.
  bool overwrite = false;
  // The job's render options parsed as `pyro farm submit` parses them, for the identity its
  // tasks would compute now.
  std::function<FarmSubmitRequest(const std::vector<std::string>& render_options)> task_request;
};

// Submits again only the frames a farm job is missing (a new array and collect job). First
// computes the identity its tasks would render now: when the scene, an asset or the engine
// changed since the submit, the tasks would render another run, which collect never takes;
// refused (UserError, naming what changed) unless `overwrite`, which makes the job's identity
// the new one (DIR's frames of the earlier one are replaced as they are collected) and submits
// every frame not yet rendered for it.
std::string resubmit_farm(const FarmResubmitRequest& request, const NoteSink& note);

}  // namespace pyro
