#include "tools/farm/farm_jobs.h"

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/user_error.h"
#include "engine/io/io_error.h"
#include "engine/io/output_gate.h"
#include "engine/io/staging_folder.h"
#include "engine/io/text_file.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/frame_range.h"
#include "systems/runtime/scene_runtime/render_identity.h"
#include "systems/runtime/scene_runtime/run_identity.h"
#include "systems/runtime/scene_runtime/scene_inputs.h"
#include "tools/farm/farm_collect.h"
#include "tools/farm/farm_record.h"
#include "tools/farm/frame_chunks.h"
#include "tools/farm/frames_video.h"
#include "tools/farm/sbatch.h"
#include "tools/farm/slurm_options.h"
#include "tools/farm/slurm_script.h"

namespace pyro {

namespace {

namespace fs = std::filesystem;

std::string this_program() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec)
    throw UserError("/proc/self/exe", "", "the path of the running pyro, for the tasks to run it");
  return exe.string();
}

// What would be submitted: the scripts and the sbatch command lines.
std::string dry_run_text(const std::string& render_path, const std::string& render_script,
                         const std::string& collect_path, const std::string& collect_script,
                         const std::vector<std::string>& render_args,
                         const std::vector<std::string>& collect_args) {
  return "# " + render_path + "\n" + render_script + "\n# " + collect_path + "\n" +
         collect_script + "\n# submitted with (RENDER_JOB: the job id the first prints)\nsbatch " +
         shell_command_text(render_args) + "\nsbatch " + shell_command_text(collect_args) + "\n";
}

// Writes the scripts of submission number record.submissions.size() for `chunks` and submits
// them (or returns them: `dry_run`), recording the jobs in the farm record.
std::string submit_chunks(FarmRecord& record, const std::string& dir,
                          const std::vector<FrameRange>& chunks, bool dry_run) {
  const std::string n = std::to_string(record.submissions.size());
  const std::string render_path = (farm_folder(dir) / ("render-" + n + ".sh")).string();
  const std::string collect_path = (farm_folder(dir) / ("collect-" + n + ".sh")).string();
  const std::string render_script = render_array_script(record, dir, chunks);
  const std::string collect_script = collect_job_script(record, dir);
  const int tasks = static_cast<int>(chunks.size());
  if (dry_run)
    return dry_run_text(render_path, render_script, collect_path, collect_script,
                        render_array_sbatch_args(record, dir, render_path, tasks),
                        collect_sbatch_args(record, dir, collect_path, "RENDER_JOB"));
  std::error_code ec;
  fs::create_directories(farm_folder(dir) / "logs", ec);  // Slurm does not create a log's folder
  if (ec)
    throw IoError((farm_folder(dir) / "logs").string(), "create the farm's folders", ec.value());
  write_text_file(render_path, render_script);
  write_text_file(collect_path, collect_script);
  write_farm_record(dir, record);  // before any job runs: collect reads it
  FarmSubmission s{run_sbatch(render_array_sbatch_args(record, dir, render_path, tasks)), "",
                   chunks};
  record.submissions.push_back(s);
  try {
    record.submissions.back().collect_job =
        run_sbatch(collect_sbatch_args(record, dir, collect_path, s.array_job));
  } catch (...) {
    write_farm_record(dir, record);  // the array runs: collect or resubmit can still find it
    throw;
  }
  write_farm_record(dir, record);
  return "submitted render job array " + s.array_job + " (" + std::to_string(tasks) +
         " task(s): frames " + ranges_text(chunks) + ") and collect job " +
         record.submissions.back().collect_job + "; frames go to " + dir + "\n";
}

// Everything the user can get wrong that needs no reading of the scene.
void check_submit_request(const FarmSubmitRequest& a) {
  if (a.scene == "-")
    throw UserError("-", "SCENE",
                    "a scene file every node can read; the tasks cannot read standard input");
  if (a.depth && a.format != "exr")
    throw UserError("--depth", "", "--format exr: only EXR frames carry a depth channel");
  check_farm_scheduler(a.scheduler);
  std::error_code ec;
  if (fs::exists(a.out, ec) && !fs::is_directory(a.out, ec))
    throw UserError(a.out, "--out", "expected a folder for the frames, found a file");
  if (fs::exists(farm_record_path(a.out), ec))
    throw UserError(a.out, "--out",
                    "a folder with no farm job yet; it holds one (" +
                        farm_record_path(a.out).string() + "): `pyro farm resubmit " + a.out +
                        "` renders what it is missing");
  if (!a.dry_run) require_sbatch();
}

// The identity each task's `pyro render` computes for the request's options on `scene`, read
// from `scene_path`.
nlohmann::json task_identity(const FarmSubmitRequest& a, const SceneDescription& scene,
                             const std::string& scene_path) {
  RuntimeOptions options = a.runtime;  // as `pyro render` sets them for the identity
  options.readback = false;
  options.width_override = a.width;
  options.height_override = a.height;
  prepare_scene_run(scene, options);  // the default flipbook baked before its folder is digested
  return render_identity_json(scene, options, scene_path, a.depth);
}

FarmRecord new_record(const FarmSubmitRequest& a, const std::string& dir) {
  FarmRecord record;
  record.scene = fs::absolute(a.scene).lexically_normal().string();
  const SceneDescription scene = load_scene(record.scene);
  OutputGate()
      .reads(scene_inputs(record.scene, scene))
      .writes({dir, "--out", OutputShape::folder, render_output_kind()})
      .check();
  record.identity = task_identity(a, scene, record.scene);
  refuse_other_run(dir, record.digest());
  record.frames = parse_frame_range(a.frames, "--frames");
  record.chunk = a.chunk;
  record.pyro = this_program();
  record.render_options = a.render_options;
  record.partition = a.partition;
  record.scheduler = a.scheduler;
  record.frames_per_second = scene.frames_per_second;
  return record;
}

// Checks that the job's tasks would render its identity now (see resubmit_farm); with
// `overwrite`, makes the identity they would render the job's.
void follow_scene_edits(FarmRecord& record, const FarmResubmitRequest& a, const NoteSink& note) {
  const SceneDescription scene = load_scene(record.scene);
  const nlohmann::json now = task_identity(a.task_request(record.render_options), scene, record.scene);
  if (now.at("digest") == record.identity.at("digest")) return;
  const std::string what =
      identity_difference(record.identity.value("parts", nlohmann::json()), now.at("parts"));
  if (!a.overwrite)
    throw UserError(record.scene, "",
                    "the scene, assets, settings and engine of the farm job in " + a.dir +
                        "; " + what + " changed since `pyro farm submit`, so its tasks would "
                        "render another run, which collect never takes (pass --overwrite to "
                        "render the job's frames again as they are now, or restore what changed)");
  if (note)
    note(what + " changed since the job was submitted: rendering again every frame not yet "
                "rendered as they are now; " + a.dir + "'s frames of the earlier version are "
                "replaced as they are collected");
  record.superseded.push_back(record.digest());
  record.identity = now;
  record.pyro = this_program();
  record.frames_per_second = scene.frames_per_second;
}

// The refusal of a collection with damaged or missing frames, naming each.
UserError incomplete_job(const std::string& dir, const FarmRecord& record, const FarmCollection& c) {
  std::string damaged;
  for (const std::string& name : c.damaged) damaged += (damaged.empty() ? "" : ", ") + name;
  std::string what = "every frame of " + range_text(record.frames) + ", each with its recorded SHA-256";
  if (!damaged.empty())
    what += "; damaged frames (bytes differ from the SHA-256 recorded when rendered; removed): " +
            damaged.substr(0, 800);
  if (!c.missing.empty()) what += "; missing frames " + ranges_text(c.missing);
  return UserError(dir, "", what + " (`pyro farm resubmit " + dir + "` renders them again)");
}

}  // namespace

std::string submit_farm(const FarmSubmitRequest& a) {
  const FrameRange range = parse_frame_range(a.frames, "--frames");
  check_submit_request(a);
  const std::string dir = normalized_output_path(a.out).string();
  std::error_code ec;
  const bool created = !fs::exists(dir, ec);
  FarmRecord record = new_record(a, dir);
  try {
    return submit_chunks(record, dir, chunk_frames(range, a.chunk), a.dry_run);
  } catch (...) {
    if (record.submissions.empty()) {  // nothing queued: nothing left behind
      fs::remove_all(farm_folder(dir), ec);
      if (created) fs::remove(dir, ec);
    }
    throw;
  }
}

std::string collect_farm_job(const FarmCollectRequest& a, const NoteSink& note) {
  const FarmRecord record = read_farm_record(a.dir);
  if (!a.video.empty()) check_video_path(a.video, "--video");
  // The frames' folder is the farm's own (checked as an output without its contents).
  OutputGate()
      .writes({a.dir, "DIR", OutputShape::folder, render_output_kind(), true})
      .writes_file(a.video, "--video")
      .check();
  const FarmCollection c = collect_farm(a.dir, record, note);
  if (!c.missing.empty() || !c.damaged.empty()) throw incomplete_job(a.dir, record, c);
  if (!a.video.empty())
    encode_frames_video(a.dir, c.files, a.video, record.frames_per_second, a.video_quality);
  return "collected frames " + range_text(record.frames) + " into " + a.dir + " (" +
         std::to_string(c.files.size()) + " file(s), " + std::to_string(c.moved) +
         " moved in now); checksums in " + (fs::path(a.dir) / kFarmChecksumsName).string() +
         (a.video.empty() ? "" : "; video " + a.video) + "\n";
}

std::string resubmit_farm(const FarmResubmitRequest& a, const NoteSink& note) {
  const std::string dir = normalized_output_path(a.dir).string();
  FarmRecord record = read_farm_record(dir);
  follow_scene_edits(record, a, note);
  if (::access(record.pyro.c_str(), X_OK) != 0)
    throw UserError(farm_record_path(dir).string(), "/pyro",
                    "a pyro binary the tasks can run; " + record.pyro + " is not there");
  if (!a.dry_run) require_sbatch();
  const std::vector<FrameRange> missing =
      missing_ranges(record.frames, finished_farm_frames(dir, record));
  if (missing.empty() && !a.dry_run) write_farm_record(dir, record);  // a changed identity
  if (missing.empty())
    return "nothing to resubmit: every frame of " + range_text(record.frames) +
           " is finished (`pyro farm collect " + dir + "` moves them in)\n";
  note("resubmitting the missing frames " + ranges_text(missing));
  return submit_chunks(record, dir, chunk_ranges(missing, record.chunk), a.dry_run);
}

}  // namespace pyro
