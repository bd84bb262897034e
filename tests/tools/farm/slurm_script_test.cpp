// The farm's batch scripts run by bash: each array task's pyro gets exactly the words it should,
// whatever the paths hold (spaces, quotes, $, ;), and the sbatch lines keep Slurm's patterns.
#include "tools/farm/slurm_script.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "tests/support/file_bytes.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// A record whose "pyro" is a script writing its arguments, one per line, into `args_file`.
FarmRecord slurm_script_record(const fs::path& dir, const fs::path& args_file) {
  const fs::path fake = dir / "fake pyro 'x' $HOME";
  std::ofstream(fake) << "#!/bin/sh\nprintf '%s\\n' \"$@\" > " << shell_quote(args_file.string())
                      << "\n";
  ::chmod(fake.c_str(), 0755);
  FarmRecord r;
  r.scene = (dir / "my scene; rm -rf $HOME.json").string();
  r.frames = {0, 9};
  r.chunk = 4;
  r.pyro = fake.string();
  r.render_options = {"--width", "32", "--stereo", "a b'c"};
  return r;
}

std::vector<std::string> slurm_script_lines(const fs::path& file) {
  std::vector<std::string> lines;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(SlurmScript, EachArrayTaskRendersItsChunkWithTheWordsQuoted) {
  const fs::path tmp = test::scratch_dir("script");
  const fs::path args = tmp / "args.txt";
  const FarmRecord r = slurm_script_record(tmp, args);
  const std::string dir = (tmp / "out `x` \"y\"").string();
  const std::vector<FrameRange> chunks = {{0, 3}, {4, 7}, {8, 9}};
  std::ofstream(tmp / "render.sh") << render_array_script(r, dir, chunks);
  const std::string run = "SLURM_ARRAY_TASK_ID=1 bash " + shell_quote((tmp / "render.sh").string());
  ASSERT_EQ(std::system(run.c_str()), 0);
  EXPECT_EQ(slurm_script_lines(args),
            (std::vector<std::string>{
                "render", r.scene, "--out", (fs::path(dir) / ".farm/chunks/4-7").string(),
                "--frames", "4:7", "--wait", "--resume", "--width", "32", "--stereo", "a b'c"}));
  // Outside an array task the script refuses rather than render something else.
  EXPECT_NE(std::system(("env -u SLURM_ARRAY_TASK_ID bash " +
                         shell_quote((tmp / "render.sh").string()) + " 2>/dev/null")
                            .c_str()),
            0);
}

TEST(SlurmScript, TheCollectJobCollectsTheFolder) {
  const fs::path tmp = test::scratch_dir("collect");
  const fs::path args = tmp / "args.txt";
  const FarmRecord r = slurm_script_record(tmp, args);
  const std::string dir = (tmp / "it's here").string();
  std::ofstream(tmp / "collect.sh") << collect_job_script(r, dir);
  ASSERT_EQ(std::system(("bash " + shell_quote((tmp / "collect.sh").string())).c_str()), 0);
  EXPECT_EQ(slurm_script_lines(args), (std::vector<std::string>{"farm", "collect", dir}));
}

TEST(SlurmScript, SbatchArgumentsNameTheArrayTheDependencyAndTheLogs) {
  FarmRecord r;
  r.partition = "gpu";
  const std::vector<std::string> render =
      render_array_sbatch_args(r, "/f/50%", "/f/50%/.farm/render-0.sh", 6);
  EXPECT_EQ(render, (std::vector<std::string>{"--parsable", "--job-name=pyro-render",
                                              "--output=/f/50%%/.farm/logs/render-%A_%a.log",
                                              "--partition=gpu", "--array=0-5", "--requeue",
                                              "/f/50%/.farm/render-0.sh"}));
  r.partition.clear();
  const std::vector<std::string> collect =
      collect_sbatch_args(r, "/f", "/f/.farm/collect-0.sh", "77");
  EXPECT_EQ(collect,
            (std::vector<std::string>{"--parsable", "--job-name=pyro-collect",
                                      "--output=/f/.farm/logs/collect-%j.log",
                                      "--dependency=afterany:77", "/f/.farm/collect-0.sh"}));
}

TEST(SlurmScript, SchedulerOptionsGoToTheRenderArrayAndWhereSensibleToCollect) {
  FarmRecord r;
  r.scheduler = {"2:00:00", "4G", 8, "proj", {"--qos=high", "--constraint=avx2"}};
  const std::vector<std::string> render = render_array_sbatch_args(r, "/f", "/f/.farm/render-0.sh", 2);
  EXPECT_EQ(render, (std::vector<std::string>{
                        "--parsable", "--job-name=pyro-render",
                        "--output=/f/.farm/logs/render-%A_%a.log", "--account=proj",
                        "--time=2:00:00", "--mem=4G", "--cpus-per-task=8", "--qos=high",
                        "--constraint=avx2", "--array=0-1", "--requeue", "/f/.farm/render-0.sh"}));
  const std::vector<std::string> collect = collect_sbatch_args(r, "/f", "/f/.farm/collect-0.sh", "9");
  EXPECT_EQ(collect, (std::vector<std::string>{"--parsable", "--job-name=pyro-collect",
                                               "--output=/f/.farm/logs/collect-%j.log",
                                               "--account=proj", "--qos=high", "--constraint=avx2",
                                               "--dependency=afterany:9", "/f/.farm/collect-0.sh"}));
}

TEST(SlurmScript, CpusPerTaskSetTheTasksThreads) {
  const fs::path tmp = test::scratch_dir("threads");
  const fs::path args = tmp / "args.txt";
  FarmRecord r = slurm_script_record(tmp, args);
  r.scheduler.cpus_per_task = 6;
  // The fake pyro also writes the llvmpipe thread count it was started with.
  std::ofstream(r.pyro) << "#!/bin/sh\nprintf '%s\\n' \"$@\" \"LP=$LP_NUM_THREADS\" > "
                        << shell_quote(args.string()) << "\n";
  std::ofstream(tmp / "render.sh") << render_array_script(r, (tmp / "out").string(), {{0, 9}});
  ASSERT_EQ(std::system(("SLURM_ARRAY_TASK_ID=0 bash " + shell_quote((tmp / "render.sh").string())).c_str()), 0);
  const std::vector<std::string> lines = slurm_script_lines(args);
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(std::vector<std::string>(lines.end() - 3, lines.end()),
            (std::vector<std::string>{"--threads", "6", "LP=6"}));
  // Threads given as a render option are the task's own.
  r.render_options = {"--threads", "2"};
  std::ofstream(tmp / "render.sh") << render_array_script(r, (tmp / "out").string(), {{0, 9}});
  ASSERT_EQ(std::system(("SLURM_ARRAY_TASK_ID=0 bash " + shell_quote((tmp / "render.sh").string())).c_str()), 0);
  const std::vector<std::string> own = slurm_script_lines(args);
  ASSERT_GE(own.size(), 3u);
  EXPECT_EQ(std::vector<std::string>(own.end() - 3, own.end()),
            (std::vector<std::string>{"--threads", "2", "LP=6"}));
}

TEST(SlurmScript, ShellQuotingSurvivesTheShell) {
  for (const std::string word :
       {"plain", "a b", "it's", "$(echo no)", "`x`", "a\\b", "\"q\"", ""}) {
    const std::string out = test::scratch_dir("quote").string() + "/w";
    ASSERT_EQ(std::system(("printf %s " + shell_quote(word) + " > " + shell_quote(out)).c_str()),
              0);
    EXPECT_EQ(test::read_bytes(out), word);
  }
}

}  // namespace
}  // namespace pyro
