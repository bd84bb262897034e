#pragma once
// A write the operating system refused: a full disk, a read-only file system, an I/O error. It
// names the file, what was being done and the OS error (strerror). Not the user's mistake in a
// file: the command line prints what() and exits with status 1.
#include <stdexcept>
#include <string>

namespace pyro {

class IoError : public std::runtime_error {
 public:
  IoError(const std::string& file, const std::string& action, int os_error);
  const std::string& file() const { return file_; }
  const std::string& action() const { return action_; }
  int os_error() const { return os_error_; }

 private:
  std::string file_, action_;
  int os_error_ = 0;
};

}  // namespace pyro
