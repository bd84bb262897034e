#pragma once
// `pyro ARGS` started as a child process (fork and exec, no shell), for tests that must kill it,
// run two at once or limit its resources. Its standard input and output are /dev/null, its
// standard error `err_fd` (or /dev/null when negative); `in_child` runs in the child just before
// the exec (setrlimit, say).
#include <sys/types.h>

#include <functional>
#include <string>
#include <vector>

namespace pyro::test {

pid_t spawn_pyro(const std::vector<std::string>& args, int err_fd = -1,
                 const std::function<void()>& in_child = {});

}  // namespace pyro::test
