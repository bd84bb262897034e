#include "engine/io/content_digest.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/sha256.h"
#include "engine/io/durable_file.h"
#include "engine/io/io_error.h"

namespace pyro {

namespace fs = std::filesystem;

namespace {

bool is_hex_digest(const std::string& s) {
  return s.size() == 64 &&
         std::all_of(s.begin(), s.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

// What identifies one version of a file without reading it.
std::string stat_key(const struct stat& s) {
  return std::to_string(s.st_dev) + ":" + std::to_string(s.st_ino) + ":" + std::to_string(s.st_size) +
         ":" + std::to_string(s.st_mtim.tv_sec) + "." + std::to_string(s.st_mtim.tv_nsec);
}

void read_entries(const std::string& file, std::map<std::string, std::string>& out) {
  if (file.empty()) return;
  std::ifstream in(file, std::ios::binary);
  if (!in) return;
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object()) return;
  for (const auto& [key, value] : j.items())
    if (value.is_string() && is_hex_digest(value.get<std::string>())) out[key] = value.get<std::string>();
}

}  // namespace

std::string file_version_key(const std::string& path) {
  struct stat s {};
  if (::stat(path.c_str(), &s) != 0) return "missing";
  return stat_key(s);
}

std::string file_sha256(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw IoError(path, "open to compute its content digest", errno);
  Sha256 h;
  std::vector<char> block(1 << 20);
  for (;;) {
    const ssize_t n = ::read(fd, block.data(), block.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int error = errno;
      ::close(fd);
      throw IoError(path, "read to compute its content digest", error);
    }
    if (n == 0) break;
    h.update(block.data(), size_t(n));
  }
  ::close(fd);
  return h.hex_digest();
}

DigestCache::DigestCache(std::string folder) {
  if (!folder.empty()) file_ = (fs::path(folder) / "digests.json").string();
  read_entries(file_, entries_);
}

DigestCache::~DigestCache() {
  if (dirty_ && !file_.empty()) {
    try {
      std::error_code ec;
      fs::create_directories(fs::path(file_).parent_path(), ec);
      std::map<std::string, std::string> merged;
      read_entries(file_, merged);  // another process's entries since we read
      for (const auto& [k, v] : entries_) merged[k] = v;
      write_file_durably(file_, nlohmann::json(merged).dump(1) + "\n");
    } catch (const std::exception&) {
      // A cache that cannot be written costs the next run the time to hash again; nothing else.
    }
  }
}

std::string DigestCache::file(const std::string& path) {
  struct stat s {};
  if (::stat(path.c_str(), &s) != 0) throw IoError(path, "look up to compute its content digest", errno);
  const std::string key = stat_key(s);
  if (auto it = entries_.find(key); it != entries_.end()) return it->second;
  const std::string digest = file_sha256(path);
  ++computed_;
  // Only a file unchanged while it was read is cached under its key.
  struct stat after {};
  if (::stat(path.c_str(), &after) == 0 && stat_key(after) == key) {
    entries_[key] = digest;
    dirty_ = true;
  }
  return digest;
}

std::string DigestCache::folder(const std::string& path) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().filename().string().rfind('.', 0) == 0) {
      if (it->is_directory(ec)) it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file(ec)) files.push_back(it->path());
  }
  if (ec) throw IoError(path, "list to compute its content digest", ec.value());
  std::sort(files.begin(), files.end());
  Sha256 h;
  for (const fs::path& f : files) {
    const std::string name = fs::relative(f, path, ec).generic_string();
    h.update(name + '\0' + file(f.string()) + '\n');
  }
  return h.hex_digest();
}

}  // namespace pyro
