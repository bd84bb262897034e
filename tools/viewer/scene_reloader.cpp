#include "tools/viewer/scene_reloader.h"

#include <sys/stat.h>

namespace pyro {

FileStamp stamp_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return {};
  FileStamp s;
  s.exists = true;
  s.mtime_ns = int64_t(st.st_mtim.tv_sec) * 1000000000 + int64_t(st.st_mtim.tv_nsec);
  s.size = uint64_t(st.st_size);
  s.inode = uint64_t(st.st_ino);
  return s;
}

void SceneReloader::succeeded(const FileStamp& stamp, uint64_t frame) {
  tried_ = stamp;
  error_.clear();
  history_.push_back({frame, true, {}});
}

void SceneReloader::failed(const FileStamp& stamp, uint64_t frame, std::string message) {
  tried_ = stamp;
  if (message.empty()) message = "the scene could not be loaded";
  error_ = message;
  history_.push_back({frame, false, std::move(message)});
}

}  // namespace pyro
