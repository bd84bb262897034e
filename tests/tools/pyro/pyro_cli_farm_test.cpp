// `pyro farm` end to end without a cluster: sbatch is a stand-in script that records its
// arguments and prints a job id, and the array tasks are the batch script submit wrote, run by
// bash once per task as Slurm would. The frames collect gathers are compared byte for byte with
// one `pyro render` of the whole range; a deleted frame is reported as a range with a non-zero
// exit, a damaged or swapped one by name and never certified; resubmit refuses a job whose scene
// was edited since submit unless told to render it again; the scheduler options reach sbatch.
// (tests/farm/slurm_farm_test.sh does the same on a real single-node Slurm.)
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "engine/core/sha256.h"
#include "engine/io/video_reader.h"
#include "tests/support/cli_render.h"
#include "tests/support/file_bytes.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// A folder holding an `sbatch` that appends its arguments to calls.txt and prints 101, 102, ...
fs::path fake_sbatch_folder(const fs::path& dir) {
  const fs::path bin = dir / "bin";
  fs::create_directories(bin);
  std::ofstream(bin / "sbatch") << "#!/bin/sh\n"
                                   "here=$(dirname \"$0\")\n"
                                   "printf '%s\\n' \"$@\" '--' >> \"$here/calls.txt\"\n"
                                   "n=$(cat \"$here/counter\" 2>/dev/null || echo 100)\n"
                                   "n=$((n + 1)); echo $n > \"$here/counter\"; echo $n\n";
  ::chmod((bin / "sbatch").c_str(), 0755);
  return bin;
}

test::CommandResult farm_with_path(const fs::path& bin, const std::vector<std::string>& args) {
  return test::run_pyro_with("env PATH=" + test::shell_quote(bin.string()) + ":\"$PATH\"", args);
}

std::vector<std::string> farm_submit_args(const fs::path& out,
                                          const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"farm",    "submit",     test::scene_path("fog.json"),
                                   "--out",   out.string(), "--frames",
                                   "0:5",     "--chunk",    "4",
                                   "--width", "32",         "--height",
                                   "24"};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

// Runs array task `task` of submission `submission`'s batch script as Slurm would.
int run_farm_task(const fs::path& out, int task, int submission = 0) {
  const std::string script = "render-" + std::to_string(submission) + ".sh";
  const std::string cmd = "SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " bash " +
                          test::shell_quote((out / ".farm" / script).string()) +
                          " >/dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::map<std::string, std::string> farm_frames(const fs::path& dir) {
  std::map<std::string, std::string> frames;
  for (const auto& [name, bytes] : test::contents(dir))
    if (name.rfind("frame_", 0) == 0) frames[name] = bytes;
  return frames;
}

TEST(PyroCliFarm, CollectedChunksAreTheBytesOfOneRenderAndADeletedFrameIsNamed) {
  const fs::path dir = test::scratch_dir("farm");
  const fs::path bin = fake_sbatch_folder(dir), out = dir / "farm out";
  const auto submitted = farm_with_path(bin, farm_submit_args(out));
  ASSERT_EQ(submitted.exit_code, 0) << submitted.err;
  EXPECT_NE(submitted.out.find(
                "submitted render job array 101 (2 task(s): frames 0:3, 4:5) and collect job 102"),
            std::string::npos)
      << submitted.out;
  const std::string calls = test::read_bytes(bin / "calls.txt");
  EXPECT_NE(calls.find("--array=0-1\n"), std::string::npos) << calls;
  EXPECT_NE(calls.find("--dependency=afterany:101\n"), std::string::npos) << calls;
  ASSERT_EQ(run_farm_task(out, 1), 0);
  ASSERT_EQ(run_farm_task(out, 0), 0);

  const auto collected = test::run_pyro({"farm", "collect", out.string()});
  ASSERT_EQ(collected.exit_code, 0) << collected.err;
  ASSERT_EQ(
      test::run_pyro({"render", test::scene_path("fog.json"), "--out", (dir / "single").string(),
                      "--frames", "0:5", "--width", "32", "--height", "24"})
          .exit_code,
      0);
  const auto frames = farm_frames(out);
  ASSERT_EQ(frames.size(), 6u);
  EXPECT_EQ(frames, farm_frames(dir / "single"));
  std::string sums;
  for (const auto& [name, bytes] : frames) sums += sha256_hex(bytes) + "  " + name + "\n";
  EXPECT_EQ(test::read_bytes(out / "SHA256SUMS"), sums);
  EXPECT_FALSE(fs::exists(out / ".farm" / "chunks" / "0-3")) << "a collected chunk's folder goes";
  const auto video =
      test::run_pyro({"farm", "collect", out.string(), "--video", (dir / "farm.gif").string()});
  ASSERT_EQ(video.exit_code, 0) << video.err;
  const VideoClip clip = read_video((dir / "farm.gif").string());
  EXPECT_EQ(clip.frame_count(), 6);
  EXPECT_EQ(clip.width, 32);
  EXPECT_EQ(clip.height, 24);

  fs::remove(out / "frame_0004.png");
  const auto incomplete = test::run_pyro({"farm", "collect", out.string()});
  EXPECT_EQ(incomplete.exit_code, 2);
  EXPECT_NE(incomplete.err.find("missing frames 4:4"), std::string::npos) << incomplete.err;
  EXPECT_FALSE(fs::exists(out / "SHA256SUMS")) << "checksums stand for a complete job only";
  const auto resubmit = test::run_pyro({"farm", "resubmit", out.string(), "--dry-run"});
  ASSERT_EQ(resubmit.exit_code, 0) << resubmit.err;
  EXPECT_NE(resubmit.out.find("ranges=('4:4')"), std::string::npos) << resubmit.out;
}

TEST(PyroCliFarm, AKilledChunkIsMissingUntilResubmittedAndThenResumes) {
  const fs::path dir = test::scratch_dir("resubmit");
  const fs::path bin = fake_sbatch_folder(dir), out = dir / "out";
  ASSERT_EQ(farm_with_path(bin, farm_submit_args(out)).exit_code, 0);
  ASSERT_EQ(run_farm_task(out, 0), 0);  // task 1 (frames 4:5) never ran: its node died
  const auto incomplete = test::run_pyro({"farm", "collect", out.string()});
  EXPECT_EQ(incomplete.exit_code, 2);
  EXPECT_NE(incomplete.err.find("missing frames 4:5"), std::string::npos) << incomplete.err;
  const auto resubmitted = farm_with_path(bin, {"farm", "resubmit", out.string()});
  ASSERT_EQ(resubmitted.exit_code, 0) << resubmitted.err;
  EXPECT_NE(resubmitted.out.find("submitted render job array 103 (1 task(s): frames 4:5)"),
            std::string::npos)
      << resubmitted.out;
  const std::string task = "SLURM_ARRAY_TASK_ID=0 bash " +
                           test::shell_quote((out / ".farm/render-1.sh").string()) +
                           " >/dev/null 2>&1";
  ASSERT_EQ(std::system(task.c_str()), 0);
  const auto collected = test::run_pyro({"farm", "collect", out.string()});
  ASSERT_EQ(collected.exit_code, 0) << collected.err;
  EXPECT_EQ(farm_frames(out).size(), 6u);
}

// The render of frames 0:5 at 32x24 of `scene` into `to`, by one `pyro render`.
std::map<std::string, std::string> single_render(const fs::path& scene, const fs::path& to) {
  const auto r = test::run_pyro({"render", scene.string(), "--out", to.string(), "--frames", "0:5",
                                 "--width", "32", "--height", "24"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return farm_frames(to);
}

TEST(PyroCliFarm, DamagedOrSwappedFramesAreNamedAndNeverCertified) {
  const fs::path dir = test::scratch_dir("farm_damaged");
  const fs::path bin = fake_sbatch_folder(dir), out = dir / "out";
  ASSERT_EQ(farm_with_path(bin, farm_submit_args(out)).exit_code, 0);
  ASSERT_EQ(run_farm_task(out, 0), 0);
  ASSERT_EQ(run_farm_task(out, 1), 0);
  const fs::path chunk = out / ".farm" / "chunks" / "0-3";
  fs::resize_file(chunk / "frame_0001.png", fs::file_size(chunk / "frame_0001.png") / 2);
  fs::copy_file(chunk / "frame_0000.png", chunk / "frame_0002.png",
                fs::copy_options::overwrite_existing);
  const auto damaged = test::run_pyro({"farm", "collect", out.string()});
  EXPECT_EQ(damaged.exit_code, 2);
  for (const char* name : {"chunks/0-3/frame_0001.png", "chunks/0-3/frame_0002.png", "missing frames 1:2"})
    EXPECT_NE(damaged.err.find(name), std::string::npos) << name << "\n" << damaged.err;
  EXPECT_FALSE(fs::exists(out / "SHA256SUMS"));
  EXPECT_FALSE(fs::exists(out / "frame_0001.png"));
  EXPECT_FALSE(fs::exists(out / "frame_0002.png"));

  const auto resubmitted = farm_with_path(bin, {"farm", "resubmit", out.string()});
  ASSERT_EQ(resubmitted.exit_code, 0) << resubmitted.err;
  EXPECT_NE(resubmitted.out.find("(1 task(s): frames 1:2)"), std::string::npos) << resubmitted.out;
  ASSERT_EQ(run_farm_task(out, 0, 1), 0);
  const auto collected = test::run_pyro({"farm", "collect", out.string()});
  ASSERT_EQ(collected.exit_code, 0) << collected.err;
  const auto frames = farm_frames(out);
  EXPECT_EQ(frames, single_render(test::scene_path("fog.json"), dir / "single"));

  // A frame copied over another after the collect: named, and the checksums withdrawn.
  fs::copy_file(out / "frame_0000.png", out / "frame_0005.png", fs::copy_options::overwrite_existing);
  const auto swapped = test::run_pyro({"farm", "collect", out.string()});
  EXPECT_EQ(swapped.exit_code, 2);
  EXPECT_NE(swapped.err.find("frame_0005.png"), std::string::npos) << swapped.err;
  EXPECT_FALSE(fs::exists(out / "SHA256SUMS"));
}

TEST(PyroCliFarm, ResubmitRefusesAnEditedSceneUnlessToldToRenderItAgain) {
  const fs::path dir = test::scratch_dir("farm_edited");
  const fs::path bin = fake_sbatch_folder(dir), out = dir / "out", scene = dir / "fog.json";
  fs::copy_file(test::scene_path("fog.json"), scene);
  std::vector<std::string> submit = farm_submit_args(out);
  submit[2] = scene.string();
  ASSERT_EQ(farm_with_path(bin, submit).exit_code, 0);
  ASSERT_EQ(run_farm_task(out, 0), 0);
  std::string text = test::read_bytes(scene);
  const std::string background = "\"background\": [0.56, 0.6, 0.66]";
  ASSERT_NE(text.find(background), std::string::npos);
  text.replace(text.find(background), background.size(), "\"background\": [0.1, 0.2, 0.3]");
  std::ofstream(scene, std::ios::binary) << text;
  ASSERT_EQ(run_farm_task(out, 1), 0);  // renders the edited scene
  EXPECT_EQ(test::run_pyro({"farm", "collect", out.string()}).exit_code, 2);

  const std::string calls = test::read_bytes(bin / "calls.txt");
  const auto refused = farm_with_path(bin, {"farm", "resubmit", out.string()});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("the scene"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--overwrite"), std::string::npos) << refused.err;
  EXPECT_EQ(test::read_bytes(bin / "calls.txt"), calls) << "a refused resubmit submits nothing";

  const auto again = farm_with_path(bin, {"farm", "resubmit", out.string(), "--overwrite"});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("(1 task(s): frames 0:3)"), std::string::npos)
      << "frames 4:5 are the edited scene's already\n" << again.out;
  ASSERT_EQ(run_farm_task(out, 0, 1), 0);
  const auto collected = test::run_pyro({"farm", "collect", out.string()});
  ASSERT_EQ(collected.exit_code, 0) << collected.err;
  EXPECT_EQ(farm_frames(out), single_render(scene, dir / "single"));
  const auto nothing = farm_with_path(bin, {"farm", "resubmit", out.string()});
  ASSERT_EQ(nothing.exit_code, 0) << nothing.err;
  EXPECT_NE(nothing.out.find("nothing to resubmit"), std::string::npos) << nothing.out;
}

TEST(PyroCliFarm, SchedulerOptionsReachSbatchAndTheTasks) {
  const fs::path dir = test::scratch_dir("farm_scheduler");
  const fs::path bin = fake_sbatch_folder(dir), out = dir / "out";
  const auto submitted = farm_with_path(
      bin, farm_submit_args(out, {"--time", "1-02:30:00", "--mem", "4G", "--cpus-per-task", "3",
                                  "--account", "proj_a", "--sbatch-arg=--qos=high",
                                  "--sbatch-arg=--constraint=avx2"}));
  ASSERT_EQ(submitted.exit_code, 0) << submitted.err;
  const std::string calls = test::read_bytes(bin / "calls.txt");
  const size_t split = calls.find("--\n");
  ASSERT_NE(split, std::string::npos) << calls;
  const std::string render = calls.substr(0, split), collect = calls.substr(split);
  for (const char* arg : {"--time=1-02:30:00\n", "--mem=4G\n", "--cpus-per-task=3\n",
                          "--account=proj_a\n", "--qos=high\n", "--constraint=avx2\n"})
    EXPECT_NE(render.find(arg), std::string::npos) << arg << "\n" << render;
  for (const char* arg : {"--account=proj_a\n", "--qos=high\n", "--constraint=avx2\n"})
    EXPECT_NE(collect.find(arg), std::string::npos) << arg << "\n" << collect;
  EXPECT_EQ(collect.find("--time="), std::string::npos) << collect;
  const std::string script = test::read_bytes(out / ".farm" / "render-0.sh");
  EXPECT_NE(script.find("export LP_NUM_THREADS=3"), std::string::npos) << script;
  EXPECT_NE(script.find("'--threads' '3'"), std::string::npos) << script;
  ASSERT_EQ(run_farm_task(out, 0), 0) << "the render takes --threads";
  ASSERT_EQ(run_farm_task(out, 1), 0);
  ASSERT_EQ(test::run_pyro({"farm", "collect", out.string()}).exit_code, 0);
  EXPECT_EQ(farm_frames(out), single_render(test::scene_path("fog.json"), dir / "single"));
}

TEST(PyroCliFarm, BadSchedulerOptionsAreRefusedUpFront) {
  const fs::path dir = test::scratch_dir("farm_scheduler_bad");
  const fs::path bin = fake_sbatch_folder(dir), out = dir / "out";
  const std::vector<std::vector<std::string>> bad = {
      {"--time", "1h"},         {"--time", "1:75:00"},       {"--time", "2-"},
      {"--mem", "4GB"},         {"--mem", "-4G"},            {"--cpus-per-task", "0"},
      {"--account", "a b"},     {"--sbatch-arg=--array=0-9"}, {"--sbatch-arg=qos=high"}};
  for (const auto& args : bad) {
    const auto refused = farm_with_path(bin, farm_submit_args(out, args));
    EXPECT_EQ(refused.exit_code, 2) << args[0] << " " << args.back() << "\n" << refused.err;
    const std::string option = args[0].substr(0, args[0].find('='));
    EXPECT_NE(refused.err.find(option), std::string::npos) << option << "\n" << refused.err;
  }
  EXPECT_FALSE(fs::exists(out)) << "a refused submit writes nothing";
  EXPECT_FALSE(fs::exists(bin / "calls.txt")) << "and submits nothing";
  const std::vector<std::vector<std::string>> good_values = {
      {"--time", "90"},        {"--time", "2-12"},  {"--time", "30:00"},
      {"--time", "UNLIMITED"}, {"--mem", "2048"},   {"--mem", "512M"}};
  for (const auto& good : good_values) {
    const auto ok = farm_with_path(bin, farm_submit_args(out, {good[0], good[1], "--dry-run"}));
    EXPECT_EQ(ok.exit_code, 0) << good[0] << " " << good[1] << "\n" << ok.err;
    EXPECT_NE(ok.out.find(good[0] + "=" + good[1]), std::string::npos) << ok.out;
  }
}

TEST(PyroCliFarm, BadInputIsRefusedAndLeavesNothing) {
  const fs::path dir = test::scratch_dir("bad");
  const auto no_dir = test::run_pyro({"farm", "collect", (dir / "nowhere").string()});
  EXPECT_EQ(no_dir.exit_code, 2);
  EXPECT_NE(
      no_dir.err.find((dir / "nowhere").string() + ": an output folder of `pyro farm submit`"),
      std::string::npos)
      << no_dir.err;
  fs::create_directories(dir / "empty");
  const auto no_record = test::run_pyro({"farm", "resubmit", (dir / "empty").string()});
  EXPECT_EQ(no_record.exit_code, 2);
  EXPECT_NE(no_record.err.find("farm.json"), std::string::npos) << no_record.err;

  const fs::path out = dir / "out";
  const auto no_sbatch = test::run_pyro_with(
      "env PATH=" + test::shell_quote((dir / "empty").string()), farm_submit_args(out));
  EXPECT_EQ(no_sbatch.exit_code, 2);
  EXPECT_NE(no_sbatch.err.find("sbatch"), std::string::npos) << no_sbatch.err;
  const fs::path bin = fake_sbatch_folder(dir);
  const auto bad_chunk =
      farm_with_path(bin, {"farm", "submit", test::scene_path("fog.json"), "--out", out.string(),
                           "--frames", "0:5", "--chunk", "0"});
  EXPECT_EQ(bad_chunk.exit_code, 2);
  EXPECT_NE(bad_chunk.err.find("--chunk"), std::string::npos) << bad_chunk.err;
  const auto bad_range =
      farm_with_path(bin, {"farm", "submit", test::scene_path("fog.json"), "--out", out.string(),
                           "--frames", "9:2", "--chunk", "2"});
  EXPECT_EQ(bad_range.exit_code, 2);
  EXPECT_NE(bad_range.err.find("--frames"), std::string::npos) << bad_range.err;
  EXPECT_FALSE(fs::exists(out)) << "a refused submit writes nothing";
  EXPECT_FALSE(fs::exists(bin / "calls.txt")) << "and submits nothing";

  const auto dry = test::run_pyro(farm_submit_args(out, {"--dry-run"}));
  ASSERT_EQ(dry.exit_code, 0) << dry.err;
  EXPECT_NE(dry.out.find("--dependency=afterany:RENDER_JOB"), std::string::npos) << dry.out;
  EXPECT_FALSE(fs::exists(out)) << "--dry-run writes nothing";
  const auto twice = farm_with_path(bin, farm_submit_args(out));
  ASSERT_EQ(twice.exit_code, 0) << twice.err;
  const auto again = farm_with_path(bin, farm_submit_args(out));
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("pyro farm resubmit"), std::string::npos) << again.err;
}

}  // namespace
}  // namespace pyro
