#pragma once
// Slurm's sbatch, run as a child process with an argument vector (no shell between: nothing in a
// path is ever interpreted).
#include <string>
#include <vector>

namespace pyro {

// The executable `name` found on $PATH (as execvp would), or empty.
std::string find_on_path(const std::string& name);

// Throws UserError when sbatch is not on $PATH, naming it and what to do: for a command to call
// before it writes anything.
void require_sbatch();

// Runs `sbatch ARGS` (ARGS starting with --parsable) and returns the job id it prints. sbatch's
// own messages go to this process's standard error. Throws UserError when sbatch is missing or
// refuses the job (a partition that does not exist, say), naming its exit status.
std::string run_sbatch(const std::vector<std::string>& args);

}  // namespace pyro
