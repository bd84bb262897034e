// pyro farm submit SCENE --out DIR --frames A:B --chunk K [--partition P] [--dry-run]
//                  [--time T] [--mem M] [--cpus-per-task N] [--account A] [--sbatch-arg=ARG ...]
//                  [--width W] [--height H] [--format png|exr [--depth]] [render options]
// pyro farm collect DIR [--video FILE [--video-quality Q]]
// pyro farm resubmit DIR [--dry-run] [--overwrite]
//
// A sequence rendered by a Slurm cluster: a job array with one task per chunk of K frames, each
// task a `pyro render --frames a:b` into its own folder (frames are the same bytes whichever
// range draws them), then a collect job that moves them into DIR, checks them and writes their
// checksums; resubmit sends again only the frames still missing. The steps are
// tools/farm/farm_jobs.h, the Slurm side tools/farm/slurm_script.h, the collection
// tools/farm/farm_collect.h; docs/farm.md.
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "engine/core/user_error.h"
#include "tools/farm/farm_jobs.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/print_note.h"
#include "tools/pyro/render_options.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

// The farm's own options; every other option given to `farm submit` is a render option, passed
// on to each task as given.
const std::set<std::string> kFarmOptions = {
    "--out",  "--frames",        "--chunk",   "--partition",  "--dry-run", "--help",
    "--time", "--cpus-per-task", "--account", "--sbatch-arg", "--mem"};

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

void run_submit(FarmSubmitRequest a, const CLI::App& cmd) {
  a.render_options = render_options_given(cmd);
  write_stdout(submit_farm(a));
}

// The options each task's `pyro render` takes: size, format and the render options.
void add_task_options(CLI::App* cmd, FarmSubmitRequest& a) {
  cmd->add_option("--width", a.width, "Image width in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--height", a.height, "Image height in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--format", a.format, "Frame files: png or exr")
      ->check(CLI::IsMember({"png", "exr"}));
  cmd->add_flag("--depth", a.depth, "With --format exr: a view-depth channel Z");
  add_render_options(cmd, a.runtime);
}

// What Slurm is asked for besides the partition (checked by tools/farm/slurm_options.h).
void add_scheduler_options(CLI::App* cmd, FarmScheduler& s) {
  cmd->add_option("--time", s.time,
                  "Time limit of each render task, in Slurm's forms (90, 2:30:00, 1-12, ...)");
  cmd->add_option("--mem", s.mem, "Memory per render task, e.g. 4G (no unit: megabytes)");
  cmd->add_option("--cpus-per-task", s.cpus_per_task,
                  "CPUs per render task; its render and llvmpipe use that many threads")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--account", s.account, "Slurm account every job of the farm is charged to");
  cmd->add_option("--sbatch-arg", s.sbatch_args,
                  "One more sbatch option for every job of the farm, as --sbatch-arg=--qos=high "
                  "(repeatable)");
}

void add_submit(CLI::App& farm) {
  auto a = std::make_shared<FarmSubmitRequest>();
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
  add_scheduler_options(cmd, a->scheduler);
  add_task_options(cmd, *a);
  cmd->callback([a, cmd] { run_submit(*a, *cmd); });
}

void run_collect(const FarmCollectRequest& a) { write_stdout(collect_farm_job(a, print_note)); }

void add_collect(CLI::App& farm) {
  auto a = std::make_shared<FarmCollectRequest>();
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

// A farm job's render options (as its record keeps them) parsed as `farm submit` parsed them.
FarmSubmitRequest task_request(const std::vector<std::string>& render_options) {
  FarmSubmitRequest a;
  CLI::App app;
  add_task_options(&app, a);
  std::vector<std::string> args(render_options.rbegin(), render_options.rend());
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    throw UserError("", "/render_options",
                    std::string("render options this pyro takes (") + e.what() + ")");
  }
  return a;
}

void add_resubmit(CLI::App& farm) {
  auto a = std::make_shared<FarmResubmitRequest>();
  a->task_request = task_request;
  CLI::App* cmd = farm.add_subcommand("resubmit",
                                      "Submit again only the frames a farm job is missing "
                                      "(a new array and collect job)");
  cmd->add_option("dir", a->dir, "The --out folder of `pyro farm submit`")->required();
  cmd->add_flag("--dry-run", a->dry_run,
                "Print the batch scripts and sbatch commands; submit nothing");
  cmd->add_flag("--overwrite", a->overwrite,
                "The scene or an asset changed since the submit: render the job's frames again "
                "as they are now (refused without it)");
  cmd->callback([a] { write_stdout(resubmit_farm(*a, print_note)); });
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
