#include "systems/runtime/quality/quality_cache.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/core/cache_folder.h"
#include "engine/core/file_kind.h"
#include "engine/io/output_gate.h"
#include "engine/io/text_file.h"

namespace pyro {

uint64_t fnv1a64(const std::string& bytes, uint64_t hash) {
  for (unsigned char c : bytes) {
    hash ^= c;
    hash *= 0x100000001b3ull;
  }
  return hash;
}

std::string quality_cache_path() {
  const std::string folder = cache_folder();
  return folder.empty() ? std::string() : (std::filesystem::path(folder) / "quality.json").string();
}

std::string engine_build_identity() {
  // The running executable's size and modification time: a rebuilt engine measures again.
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return "unknown build";
  const auto size = std::filesystem::file_size(exe, ec);
  if (ec) return "unknown build";
  const auto time = std::filesystem::last_write_time(exe, ec);
  if (ec) return "unknown build";
  return exe.string() + "|" + std::to_string(size) + "|" +
         std::to_string(time.time_since_epoch().count());
}

std::string quality_cache_key(const std::string& scene_bytes, int width, int height,
                              double max_rmse, const std::string& renderer) {
  char target[64];
  std::snprintf(target, sizeof target, "%dx%d|%.9g|", width, height, max_rmse);
  uint64_t h = fnv1a64(scene_bytes);
  h = fnv1a64(target, h);
  h = fnv1a64(renderer, h);
  h = fnv1a64(engine_build_identity(), h);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

namespace {

// The cache's entries; an empty object for a missing file. `damage` says why a file that exists
// was not read (not a regular file, not a JSON object).
nlohmann::json read_all(const std::string& path, std::string& damage) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec) && !std::filesystem::is_symlink(path, ec))
    return nlohmann::json::object();
  if (const std::string kind = non_regular_file_kind(path); !kind.empty()) {
    damage = "expected a regular file, found " + kind;
    return nlohmann::json::object();
  }
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
  if (j.is_object()) return j;
  damage = "not a JSON object";
  return nlohmann::json::object();
}

}  // namespace

std::optional<nlohmann::json> read_quality_cache(const std::string& path, const std::string& key,
                                                 const std::function<void(const std::string&)>& on_note) {
  if (path.empty()) return std::nullopt;
  std::string damage;
  const nlohmann::json all = read_all(path, damage);
  if (!damage.empty() && on_note)
    on_note("quality: ignored the cache \"" + path + "\" (" + damage + ")");
  const auto it = all.find(key);
  if (it == all.end() || !it->is_object()) return std::nullopt;
  return *it;
}

bool write_quality_cache(const std::string& path, const std::string& key, const nlohmann::json& entry) {
  if (path.empty()) return false;
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  std::string damage;
  nlohmann::json all = read_all(path, damage);
  all[key] = entry;
  try {
    OutputGate().writes_file(path, "the quality cache").check();  // never a device node or FIFO
    write_text_file(path, all.dump(1) + "\n");
  } catch (const std::exception&) {
    return false;  // a cache that cannot be written never fails the command
  }
  return true;
}

}  // namespace pyro
