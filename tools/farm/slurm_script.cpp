#include "tools/farm/slurm_script.h"

#include <algorithm>

#include "tools/farm/frame_chunks.h"

namespace pyro {

std::string shell_quote(const std::string& word) {
  std::string q = "'";
  for (char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string shell_command_text(const std::vector<std::string>& argv) {
  std::string text;
  for (const std::string& a : argv) text += (text.empty() ? "" : " ") + shell_quote(a);
  return text;
}

namespace {

std::string bash_array(const std::string& name, const std::vector<std::string>& items) {
  std::string text = name + "=(";
  for (size_t i = 0; i < items.size(); ++i) text += (i ? " " : "") + shell_quote(items[i]);
  return text + ")\n";
}

// `path` inside an sbatch --output pattern, where % starts a replacement (%A: the array's job id)
// and %% is a literal %.
std::string slurm_pattern_path(const std::string& path) {
  std::string out;
  for (char c : path) out += c == '%' ? std::string("%%") : std::string(1, c);
  return out;
}

// --parsable: sbatch prints the job id alone. `log_pattern` names the log inside DIR/.farm/logs
// (Slurm's replacements in it are kept).
std::vector<std::string> common_sbatch_args(const FarmRecord& record, const std::string& dir,
                                            const std::string& name,
                                            const std::string& log_pattern) {
  const std::string logs = slurm_pattern_path((farm_folder(dir) / "logs").string());
  std::vector<std::string> args = {"--parsable", "--job-name=" + name,
                                   "--output=" + logs + "/" + log_pattern};
  if (!record.partition.empty()) args.push_back("--partition=" + record.partition);
  if (!record.scheduler.account.empty()) args.push_back("--account=" + record.scheduler.account);
  return args;
}

// What each render task asks for: its time, memory and CPUs.
void add_task_resources(const FarmScheduler& s, std::vector<std::string>& args) {
  if (!s.time.empty()) args.push_back("--time=" + s.time);
  if (!s.mem.empty()) args.push_back("--mem=" + s.mem);
  if (s.cpus_per_task > 0) args.push_back("--cpus-per-task=" + std::to_string(s.cpus_per_task));
}

// The threads of a task with --cpus-per-task N: N for llvmpipe's rasterizer (LP_NUM_THREADS,
// read when the context is made) and N for the frame schedule (render --threads, unless the
// render options give their own), rather than one per core of the whole node.
std::string task_threads(const FarmRecord& record, std::string& options) {
  const int n = record.scheduler.cpus_per_task;
  if (n <= 0) return {};
  const auto& o = record.render_options;
  if (std::find(o.begin(), o.end(), "--threads") == o.end())
    options += " " + shell_quote("--threads") + " " + shell_quote(std::to_string(n));
  return "export LP_NUM_THREADS=" + std::to_string(n) + "\n";
}

}  // namespace

std::string render_array_script(const FarmRecord& record, const std::string& dir,
                                const std::vector<FrameRange>& chunks) {
  std::vector<std::string> ranges, folders;
  for (const FrameRange& c : chunks) {
    ranges.push_back(range_text(c));
    folders.push_back(chunk_folder(dir, c).string());
  }
  std::string options;
  for (const std::string& o : record.render_options) options += " " + shell_quote(o);
  const std::string threads = task_threads(record, options);
  return "#!/bin/bash\n"
         "# pyro farm: array task i renders the frames ranges[i] of the scene into its own output\n"
         "# folder, folders[i]; `pyro farm collect` moves them into the farm's folder. --resume "
         "keeps\n"
         "# what a killed or requeued run of the task had finished.\n"
         "set -eu\n" +
         threads + bash_array("ranges", ranges) + bash_array("folders", folders) +
         "i=${SLURM_ARRAY_TASK_ID:?this script runs as a task of a Slurm job array}\n"
         "exec " +
         shell_quote(record.pyro) + " render " + shell_quote(record.scene) +
         " --out \"${folders[$i]}\" --frames \"${ranges[$i]}\" --wait --resume" + options + "\n";
}

std::string collect_job_script(const FarmRecord& record, const std::string& dir) {
  return "#!/bin/bash\n"
         "# pyro farm: after every task of the render array, the frames moved into the farm's\n"
         "# folder and checked; a missing range fails this job (pyro farm resubmit renders it).\n"
         "set -eu\n"
         "exec " +
         shell_quote(record.pyro) + " farm collect " + shell_quote(dir) + "\n";
}

std::vector<std::string> render_array_sbatch_args(const FarmRecord& record, const std::string& dir,
                                                  const std::string& script, int tasks) {
  std::vector<std::string> args =
      common_sbatch_args(record, dir, "pyro-render", "render-%A_%a.log");
  add_task_resources(record.scheduler, args);
  args.insert(args.end(), record.scheduler.sbatch_args.begin(), record.scheduler.sbatch_args.end());
  args.push_back("--array=0-" + std::to_string(tasks - 1));
  // A task whose node fails is queued again (and resumes its chunk) rather than lost.
  args.push_back("--requeue");
  args.push_back(script);
  return args;
}

std::vector<std::string> collect_sbatch_args(const FarmRecord& record, const std::string& dir,
                                             const std::string& script,
                                             const std::string& array_job) {
  std::vector<std::string> args = common_sbatch_args(record, dir, "pyro-collect", "collect-%j.log");
  args.insert(args.end(), record.scheduler.sbatch_args.begin(), record.scheduler.sbatch_args.end());
  args.push_back("--dependency=afterany:" + array_job);
  args.push_back(script);
  return args;
}

}  // namespace pyro
