#pragma once
// pyro view's hot reload, as a state machine that needs no window: the viewer stamps the scene
// file (modification time, size, inode) every frame; a stamp unlike the last one it tried means
// an edit, and the viewer loads the file with the normal scene loader. A good load replaces the
// running scene; a broken one keeps the last good scene running and its message (file, place,
// what was expected) is shown until the next good load. Each distinct stamp is tried once, so a
// broken file is not reloaded every frame; a manual reload (R) tries again whatever the stamp.
#include <cstdint>
#include <string>
#include <vector>

namespace pyro {

struct FileStamp {
  bool exists = false;
  int64_t mtime_ns = 0;
  uint64_t size = 0;
  uint64_t inode = 0;  // an editor that saves by renaming a new file over the old one
  bool operator==(const FileStamp&) const = default;
};

FileStamp stamp_file(const std::string& path);

struct ReloadEvent {
  uint64_t frame = 0;  // the viewer's frame count when the load was tried
  bool ok = false;
  std::string error;  // the loader's message when !ok
};

class SceneReloader {
 public:
  explicit SceneReloader(const FileStamp& loaded) : tried_(loaded) {}

  // True when `now` differs from the stamp of the last load tried (good or broken).
  bool changed(const FileStamp& now) const { return !(now == tried_); }

  void succeeded(const FileStamp& stamp, uint64_t frame);
  void failed(const FileStamp& stamp, uint64_t frame, std::string message);
  // The viewer wrote the file itself (a save): this stamp is not an edit to load.
  void accept(const FileStamp& stamp) { tried_ = stamp; }

  // The last load failed: the running scene is an older one and error() says why.
  bool showing_error() const { return !error_.empty(); }
  const std::string& error() const { return error_; }
  const std::vector<ReloadEvent>& history() const { return history_; }

 private:
  FileStamp tried_;
  std::string error_;
  std::vector<ReloadEvent> history_;
};

}  // namespace pyro
