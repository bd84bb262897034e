// pyro farm submit SCENE --out DIR --frames A:B --chunk K [--partition P] [--dry-run]
//                  [--width W] [--height H] [--format png|exr [--depth]] [render options]
// pyro farm collect DIR [--video FILE [--video-quality Q]]
// pyro farm resubmit DIR [--dry-run]
//
// A sequence rendered by a Slurm cluster: a job array with one task per chunk of K frames, each
// task a `pyro render --frames a:b` into its own folder (frames are the same bytes whichever
// range draws them), then a collect job that moves them into DIR, checks them and writes their
// checksums; resubmit sends again only the frames still missing. The Slurm side is
// tools/farm/slurm_script.h, the collection tools/farm/farm_collect.h; docs/farm.md.
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "engine/core/user_error.h"
#include "engine/io/io_error.h"
#include "engine/io/staging_folder.h"
#include "engine/io/text_file.h"
#include "engine/io/video_file.h"
#include "tools/farm/farm_collect.h"
#include "tools/farm/farm_record.h"
#include "tools/farm/frame_chunks.h"
#include "tools/farm/frames_video.h"
#include "tools/farm/sbatch.h"
#include "tools/farm/slurm_script.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/frame_range.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/print_note.h"
#include "systems/runtime/scene_runtime/render_identity.h"
#include "tools/pyro/render_options.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

namespace fs = std::filesystem;

struct SubmitArgs {
  std::string scene, out, frames, partition;
  int chunk = 0;
  bool dry_run = false;
  int width = 0, height = 0;
  std::string format = "png";
  bool depth = false;
  RuntimeOptions runtime;
};

// The farm's own options; every other option given to `farm submit` is a render option, passed
// on to each task as given.
const std::set<std::string> kFarmOptions = {"--out",       "--frames",  "--chunk",
                                            "--partition", "--dry-run", "--help"};

std::vector<std::string> render_options_given(const CLI::App& cmd) {
  std::vector<std::string> args;
  for (const CLI::Option* o : cmd.get_options()) {
    if (o->get_positional() || o->count() == 0) continue;
    const std::string name = o->get_name();
    if (kFarmOptions.count(name)) continue;
    if (o->get_expected_min() == 0) {  // a flag
      args.push_back(name);
      continue;
    }
    for (const std::string& value : o->results()) {
      args.push_back(name);
      args.push_back(value);
    }
  }
  return args;
}

std::string this_program() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec)
    throw UserError("/proc/self/exe", "", "the path of the running pyro, for the tasks to run it");
  return exe.string();
}

// Prints what would be submitted: the scripts and the sbatch command lines.
void print_dry_run(const std::string& render_path, const std::string& render_script,
                   const std::string& collect_path, const std::string& collect_script,
                   const std::vector<std::string>& render_args,
                   const std::vector<std::string>& collect_args) {
  write_stdout(
      "# " + render_path + "\n" + render_script + "\n# " + collect_path + "\n" + collect_script +
      "\n# submitted with (RENDER_JOB: the job id the first prints)\nsbatch " +
      shell_command_text(render_args) + "\nsbatch " + shell_command_text(collect_args) + "\n");
}

// Writes the scripts of submission number record.submissions.size() for `chunks` and submits
// them (or prints them: `dry_run`), recording the jobs in the farm record.
void submit_chunks(FarmRecord& record, const std::string& dir,
                   const std::vector<FrameRange>& chunks, bool dry_run) {
  const std::string n = std::to_string(record.submissions.size());
  const std::string render_path = (farm_folder(dir) / ("render-" + n + ".sh")).string();
  const std::string collect_path = (farm_folder(dir) / ("collect-" + n + ".sh")).string();
  const std::string render_script = render_array_script(record, dir, chunks);
  const std::string collect_script = collect_job_script(record, dir);
  const int tasks = static_cast<int>(chunks.size());
  if (dry_run) {
    print_dry_run(render_path, render_script, collect_path, collect_script,
                  render_array_sbatch_args(record, dir, render_path, tasks),
                  collect_sbatch_args(record, dir, collect_path, "RENDER_JOB"));
    return;
  }
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
  write_stdout("submitted render job array " + s.array_job + " (" + std::to_string(tasks) +
               " task(s): frames " + ranges_text(chunks) + ") and collect job " +
               record.submissions.back().collect_job + "; frames go to " + dir + "\n");
}

// Everything the user can get wrong that needs no reading of the scene.
void check_submit_arguments(const SubmitArgs& a) {
  if (a.scene == "-")
    throw UserError("-", "SCENE",
                    "a scene file every node can read; the tasks cannot read standard input");
  if (a.depth && a.format != "exr")
    throw UserError("--depth", "", "--format exr: only EXR frames carry a depth channel");
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

FarmRecord new_record(const SubmitArgs& a, const CLI::App& cmd, const std::string& dir) {
  FarmRecord record;
  record.scene = fs::absolute(a.scene).lexically_normal().string();
  const SceneDescription scene = load_scene(record.scene);
  RuntimeOptions options = a.runtime;  // as `pyro render` sets them for the identity
  options.readback = false;
  options.width_override = a.width;
  options.height_override = a.height;
  prepare_scene_run(scene, options);  // the default flipbook baked before its folder is digested
  record.identity = render_identity_json(scene, options, record.scene, a.depth);
  refuse_other_run(dir, record.digest());
  record.frames = parse_frame_range(a.frames, "--frames");
  record.chunk = a.chunk;
  record.pyro = this_program();
  record.render_options = render_options_given(cmd);
  record.partition = a.partition;
  record.frames_per_second = scene.frames_per_second;
  return record;
}

void run_submit(const SubmitArgs& a, const CLI::App& cmd) {
  const FrameRange range = parse_frame_range(a.frames, "--frames");
  check_submit_arguments(a);
  const std::string dir = normalized_output_path(a.out).string();
  std::error_code ec;
  const bool created = !fs::exists(dir, ec);
  FarmRecord record = new_record(a, cmd, dir);
  try {
    submit_chunks(record, dir, chunk_frames(range, a.chunk), a.dry_run);
  } catch (...) {
    if (record.submissions.empty()) {  // nothing queued: nothing left behind
      fs::remove_all(farm_folder(dir), ec);
      if (created) fs::remove(dir, ec);
    }
    throw;
  }
}

void add_submit(CLI::App& farm) {
  auto a = std::make_shared<SubmitArgs>();
  CLI::App* cmd = farm.add_subcommand("submit",
                                      "Render a scene's frames on a Slurm cluster: a job "
                                      "array of chunks, then a collect job");
  cmd->add_option("scene", a->scene, "Scene file (JSON) on a file system every node sees")
      ->required();
  cmd->add_option("--out", a->out, "Output folder, on a file system every node sees")->required();
  cmd->add_option("--frames", a->frames, "A:B: frames A..B inclusive (N: frames 0..N-1)")
      ->required();
  cmd->add_option("--chunk", a->chunk, "Frames per array task")
      ->required()
      ->check(CLI::Range(1, 1000000));
  cmd->add_option("--partition", a->partition, "Slurm partition (default: the cluster's)");
  cmd->add_flag("--dry-run", a->dry_run,
                "Print the batch scripts and sbatch commands; submit nothing");
  cmd->add_option("--width", a->width, "Image width in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--height", a->height, "Image height in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--format", a->format, "Frame files: png or exr")
      ->check(CLI::IsMember({"png", "exr"}));
  cmd->add_flag("--depth", a->depth, "With --format exr: a view-depth channel Z");
  add_render_options(cmd, a->runtime);
  cmd->callback([a, cmd] { run_submit(*a, *cmd); });
}

struct CollectArgs {
  std::string dir, video;
  int video_quality = VideoWriter::default_quality;
};

void run_collect(const CollectArgs& a) {
  const FarmRecord record = read_farm_record(a.dir);
  if (!a.video.empty()) check_video_path(a.video, "--video");
  const FarmCollection c = collect_farm(a.dir, record, print_note);
  if (!c.missing.empty())
    throw UserError(a.dir, "",
                    "every frame of " + range_text(record.frames) + "; missing frames " +
                        ranges_text(c.missing) + " (`pyro farm resubmit " + a.dir +
                        "` renders them again)");
  if (!a.video.empty())
    encode_frames_video(a.dir, c.files, a.video, record.frames_per_second, a.video_quality);
  write_stdout("collected frames " + range_text(record.frames) + " into " + a.dir + " (" +
               std::to_string(c.files.size()) + " file(s), " + std::to_string(c.moved) +
               " moved in now); checksums in " + (fs::path(a.dir) / kFarmChecksumsName).string() +
               (a.video.empty() ? "" : "; video " + a.video) + "\n");
}

void add_collect(CLI::App& farm) {
  auto a = std::make_shared<CollectArgs>();
  CLI::App* cmd = farm.add_subcommand("collect",
                                      "Move a farm job's frames into its folder, check "
                                      "every frame is there and write their SHA-256");
  cmd->add_option("dir", a->dir, "The --out folder of `pyro farm submit`")->required();
  cmd->add_option("--video", a->video,
                  "Also encode the PNG frames into FILE (.mp4, .webm or .gif)");
  cmd->add_option("--video-quality", a->video_quality, "0..100 (default 75)")
      ->check(CLI::Range(0, 100));
  cmd->callback([a] { run_collect(*a); });
}

struct ResubmitArgs {
  std::string dir;
  bool dry_run = false;
};

void run_resubmit(const ResubmitArgs& a) {
  const std::string dir = normalized_output_path(a.dir).string();
  FarmRecord record = read_farm_record(dir);
  if (::access(record.pyro.c_str(), X_OK) != 0)
    throw UserError(farm_record_path(dir).string(), "/pyro",
                    "a pyro binary the tasks can run; " + record.pyro + " is not there");
  if (!a.dry_run) require_sbatch();
  const std::vector<FrameRange> missing =
      missing_ranges(record.frames, finished_farm_frames(dir, record));
  if (missing.empty()) {
    write_stdout("nothing to resubmit: every frame of " + range_text(record.frames) +
                 " is finished (`pyro "
                 "farm collect " +
                 dir + "` moves them in)\n");
    return;
  }
  print_note("resubmitting the missing frames " + ranges_text(missing));
  submit_chunks(record, dir, chunk_ranges(missing, record.chunk), a.dry_run);
}

void add_resubmit(CLI::App& farm) {
  auto a = std::make_shared<ResubmitArgs>();
  CLI::App* cmd = farm.add_subcommand("resubmit",
                                      "Submit again only the frames a farm job is missing "
                                      "(a new array and collect job)");
  cmd->add_option("dir", a->dir, "The --out folder of `pyro farm submit`")->required();
  cmd->add_flag("--dry-run", a->dry_run,
                "Print the batch scripts and sbatch commands; submit nothing");
  cmd->callback([a] { run_resubmit(*a); });
}

}  // namespace

void add_farm_command(CLI::App& app) {
  CLI::App* farm =
      app.add_subcommand("farm", "Render a sequence on a Slurm cluster (docs/farm.md)");
  farm->require_subcommand(1);
  add_submit(*farm);
  add_collect(*farm);
  add_resubmit(*farm);
}

}  // namespace pyro::cli
