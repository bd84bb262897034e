#include "engine/io/durable_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>

#include "engine/io/io_error.h"

namespace pyro {

namespace {

bool process_gone(const std::string& digits) {
  if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
    return false;
  std::error_code ec;
  return !std::filesystem::exists("/proc/" + digits, ec);
}

std::string fresh_temporary(const std::string& path) {
  remove_stale_temporaries(path);
  return path + ".partial-" + std::to_string(::getpid());
}

}  // namespace

int remove_stale_temporaries(const std::string& path) {
  namespace fs = std::filesystem;
  const std::string prefix = fs::path(path).filename().string() + ".partial-";
  int removed = 0;
  std::error_code ec;
  for (fs::directory_iterator it(folder_of(path), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) != 0 || !process_gone(name.substr(prefix.size()))) continue;
    std::error_code rm;
    if (it->is_regular_file(rm) && fs::remove(it->path(), rm)) ++removed;
  }
  return removed;
}

DurableFile::DurableFile(const std::string& path) : file_(path, fresh_temporary(path), O_WRONLY) {}

void DurableFile::write(const void* data, size_t size) {
  if (const int error = write_all(file_.fd(), data, size)) file_.fail("write", error);
}

void write_file_durably(const std::string& path, std::string_view bytes) {
  DurableFile file(path);
  file.write(bytes);
  file.commit();
}

void sync_folder(const std::string& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw IoError(folder, "open the folder to flush it (fsync)", errno);
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0 && err != EINVAL) throw IoError(folder, "flush the folder to disk (fsync)", err);
}

}  // namespace pyro
