#pragma once
// The Slurm side of a farm job as text: the batch scripts (a job array with one task per chunk
// of frames, and the collect job) and the sbatch command lines that submit them. Every path and
// option is quoted for the shell, so a folder named "a b; rm -rf ~" stays a folder name.
//
// Each task renders into its own output folder (DIR/.farm/chunks/A-B, farm_record.h): an output
// folder has one writer at a time, held by a lock for the whole render (engine/io/output_folder.h),
// so tasks writing into DIR itself would run one after the other on a node. `pyro farm collect`
// moves the chunks' frames into DIR under DIR's lock.
#include <string>
#include <vector>

#include "tools/farm/farm_record.h"

namespace pyro {

// `word` as one shell word: single-quoted, a ' inside written '\''.
std::string shell_quote(const std::string& word);
// `argv` as a shell command line, each word quoted.
std::string shell_command_text(const std::vector<std::string>& argv);

// The job array's script: task i runs `pyro render` of the record's scene for chunks[i] into
// chunk_folder(dir, chunks[i]), with --wait (a requeued task waits for a straggler of its own
// chunk) and --resume (it keeps the frames a killed or requeued task finished, and draws again
// those of another identity). With --cpus-per-task N, the task renders with N threads (--threads
// N, LP_NUM_THREADS=N) rather than one per core of the node.
std::string render_array_script(const FarmRecord& record, const std::string& dir,
                                const std::vector<FrameRange>& chunks);
// The collect job's script: `pyro farm collect DIR`.
std::string collect_job_script(const FarmRecord& record, const std::string& dir);

// The arguments after `sbatch` submitting `script` as an array of `tasks` tasks, and the collect
// job that runs after every one of them has ended (afterany: also when one failed or was
// cancelled, so that collect always runs and reports the missing frames; afterok would leave it
// pending for ever). Logs go to DIR/.farm/logs. Both carry the partition, the account and the
// --sbatch-arg words; the render array also the time, memory and CPUs of each task (the collect
// job, which only moves and checks files, keeps the cluster's defaults).
std::vector<std::string> render_array_sbatch_args(const FarmRecord& record, const std::string& dir,
                                                  const std::string& script, int tasks);
std::vector<std::string> collect_sbatch_args(const FarmRecord& record, const std::string& dir,
                                             const std::string& script,
                                             const std::string& array_job);

}  // namespace pyro
