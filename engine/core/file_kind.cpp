#include "engine/core/file_kind.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

namespace pyro {

std::string non_regular_file_kind(const std::string& path) {
  struct stat s {};
  if (::stat(path.c_str(), &s) != 0) {
    if (errno == ELOOP) return "a symbolic link loop";
    if (errno == ENOENT || errno == ENOTDIR) return "no file";
    return std::string("an unreadable path (") + std::strerror(errno) + ")";
  }
  if (S_ISREG(s.st_mode)) return "";
  if (S_ISDIR(s.st_mode)) return "a folder";
  if (S_ISFIFO(s.st_mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(s.st_mode)) return "a socket";
  if (S_ISCHR(s.st_mode)) return "a character device";
  if (S_ISBLK(s.st_mode)) return "a block device";
  return "not a regular file";
}

bool is_fifo(const std::string& path) {
  struct stat s {};
  return ::stat(path.c_str(), &s) == 0 && S_ISFIFO(s.st_mode);
}

}  // namespace pyro
