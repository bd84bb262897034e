#include "tools/farm/sbatch.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <string_view>

#include "engine/core/user_error.h"
#include "engine/io/io_error.h"

extern char** environ;

namespace pyro {

std::string find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string_view rest = path ? path : "";
  while (true) {
    const size_t colon = rest.find(':');
    std::string folder(rest.substr(0, colon));
    if (folder.empty()) folder = ".";  // an empty entry is the current folder
    const std::string candidate = folder + "/" + name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    if (colon == std::string_view::npos) return {};
    rest.remove_prefix(colon + 1);
  }
}

void require_sbatch() {
  if (find_on_path("sbatch").empty())
    throw UserError("sbatch", "",
                    "Slurm's sbatch on $PATH to submit the jobs; it is not there (run "
                    "on a Slurm login node, or pass --dry-run to print the scripts)");
}

namespace {

// What the child printed on `fd` until it closed it.
std::string read_all(int fd) {
  std::string text;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0)
      text.append(buffer, static_cast<size_t>(n));
    else if (n == 0 || errno != EINTR)
      return text;
  }
}

int wait_for(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

std::string run_sbatch(const std::vector<std::string>& args) {
  const std::string sbatch = find_on_path("sbatch");
  require_sbatch();
  int out[2];
  if (::pipe(out) != 0) throw IoError("sbatch", "create a pipe for its output", errno);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, out[0]);
  std::vector<char*> argv = {const_cast<char*>(sbatch.c_str())};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, sbatch.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(out[1]);
  if (spawned != 0) {
    ::close(out[0]);
    throw IoError(sbatch, "start sbatch", spawned);
  }
  const std::string printed = read_all(out[0]);
  ::close(out[0]);
  const int status = wait_for(pid);
  // --parsable prints "JOBID" or "JOBID;CLUSTER".
  const std::string id = printed.substr(0, printed.find_first_of(";\n"));
  if (status != 0 || id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
    throw UserError("sbatch", "",
                    "a job id from sbatch; it exited with status " + std::to_string(status) +
                        " and printed \"" + printed + "\" (its message is above)");
  return id;
}

}  // namespace pyro
