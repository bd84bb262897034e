#pragma once
// The quality picker's results, cached in one JSON file so a scene is measured once per machine:
// quality.json in the cache folder (engine/core/cache_folder.h). Entries are keyed by a hash of
// everything that changes the answer: the scene as parsed, the output size, the error target, the OpenGL renderer
// (vendor, renderer, version strings) and the engine build, so editing the scene, rebuilding
// the engine or moving to another machine measures again. The file is rewritten atomically (temporary name + rename).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace pyro {

// FNV-1a, 64 bits (Fowler, Noll, Vo; IETF draft-eastlake-fnv): a stable content hash.
uint64_t fnv1a64(const std::string& bytes, uint64_t hash = 0xcbf29ce484222325ull);

// The cache file's path; empty when no folder can be named (no variable set).
std::string quality_cache_path();

// The running engine build (the executable's path, size and modification time).
std::string engine_build_identity();

// The key of one pick: hex of the hash of the parts above and the engine build.
std::string quality_cache_key(const std::string& scene_bytes, int width, int height,
                              double max_rmse, const std::string& renderer);

// The entry under `key`, if the file exists, parses and holds it. A cache that is not a regular
// file or does not parse is ignored, with a note to `on_note`.
std::optional<nlohmann::json> read_quality_cache(const std::string& path, const std::string& key,
                                                 const std::function<void(const std::string&)>& on_note = {});
// Adds or replaces the entry; creates the folder. Returns false (and writes nothing) on any
// failure (a full disk, a read-only folder, a cache that is not a regular file).
bool write_quality_cache(const std::string& path, const std::string& key, const nlohmann::json& entry);

}  // namespace pyro
