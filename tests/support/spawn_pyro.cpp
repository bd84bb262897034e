#include "tests/support/spawn_pyro.h"

#include <fcntl.h>
#include <unistd.h>

#include "tests/support/test_paths.h"

namespace pyro::test {

pid_t spawn_pyro(const std::vector<std::string>& args, int err_fd,
                 const std::function<void()>& in_child) {
  std::vector<std::string> argv_text = {pyro_binary()};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    if (in_child) in_child();
    const int null = ::open("/dev/null", O_RDWR);
    ::dup2(null, 0);
    ::dup2(null, 1);
    ::dup2(err_fd >= 0 ? err_fd : null, 2);
    ::execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

}  // namespace pyro::test
