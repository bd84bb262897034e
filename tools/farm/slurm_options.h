#pragma once
// The scheduler options of `pyro farm submit` checked before anything is written or submitted,
// each refusal naming the option, the value and the form Slurm takes (sbatch(1)): a bad value
// would otherwise be found by sbatch only after the farm's folder was made, or by Slurm when the
// job runs.
#include <string>

#include "tools/farm/farm_record.h"

namespace pyro {

// A time limit in one of Slurm's forms: MINUTES, MINUTES:SECONDS, HOURS:MINUTES:SECONDS,
// DAYS-HOURS, DAYS-HOURS:MINUTES, DAYS-HOURS:MINUTES:SECONDS (minutes and seconds below 60 after
// a larger unit, hours below 24 after days), or UNLIMITED / INFINITE (in any case).
bool is_slurm_time(const std::string& time);
// A memory size: a whole number with an optional unit K, M, G or T (Slurm's default: M).
bool is_slurm_memory(const std::string& mem);

// Throws UserError naming the option (--time, --mem, --cpus-per-task, --account, --sbatch-arg)
// for a value Slurm would not take, or an --sbatch-arg that would change what pyro itself asks
// of sbatch (the array, the dependency, the logs, the job's name) or repeats one of the farm's
// own options.
void check_farm_scheduler(const FarmScheduler& scheduler);

}  // namespace pyro
