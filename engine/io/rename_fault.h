#pragma once
// A fault-injection point for the tests of atomic output: every rename that moves finished
// output into place (durable files, staging folders, folder replacements) calls
// before_output_rename() first. When the environment variable PYRO_TEST_KILL_BEFORE_RENAME is
// N > 0, the process kills itself with SIGKILL just before its N-th such rename, so that a test
// can stop a command between any two renames and check that what is left is the old output or
// the new one, never a mix. Unset (always, outside those tests), it only counts.
namespace pyro {

void before_output_rename();

}  // namespace pyro
