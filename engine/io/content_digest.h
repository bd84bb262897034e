#pragma once
// Content digests of the files and folders a run reads (VDB and particle files, flipbook
// folders, the engine's executable and shaders): SHA-256 of the bytes (engine/core/sha256.h),
// so that a renamed copy has the same identity and an edited file in place has another.
//
// Reading gigabytes on every run would make a resume slow, so digests are cached in
// `digests.json` in the cache folder (engine/core/cache_folder.h), keyed by the file's device,
// inode, size and modification time in nanoseconds: a file rewritten in place changes its
// modification time, so its cached digest is no longer found. The cache is checked like any
// input: entries that are not 64 hex digits are dropped; a cache that cannot be read or written
// costs only the time to hash again.
#include <map>
#include <string>

namespace pyro {

class DigestCache {
 public:
  // Reads the cache file in `folder` (empty: no cache; every digest is computed).
  explicit DigestCache(std::string folder);
  ~DigestCache();  // writes the cache back when it gained entries (failures ignored)
  DigestCache(const DigestCache&) = delete;
  DigestCache& operator=(const DigestCache&) = delete;

  // The digest of a regular file's bytes. Throws IoError when it cannot be read.
  std::string file(const std::string& path);
  // The digest of a folder: of each regular file's name and digest, in name order, descending
  // into sub-folders; entries whose names start with '.' (a staging folder's records, temporary
  // files) are not content and are skipped.
  std::string folder(const std::string& path);

  int computed() const { return computed_; }  // digests computed (not found in the cache)

 private:
  std::string file_;
  std::map<std::string, std::string> entries_;  // stat key -> digest
  bool dirty_ = false;
  int computed_ = 0;
};

// What identifies one version of a file without reading it: its device, inode, size and
// modification time in nanoseconds (a file replaced or rewritten gets another); "missing" when
// it cannot be stat'ed.
std::string file_version_key(const std::string& path);

// SHA-256 of a file's bytes, read in blocks (no cache). Throws IoError.
std::string file_sha256(const std::string& path);

}  // namespace pyro
