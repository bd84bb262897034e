#include "systems/runtime/scene_runtime/scene_asset_cache.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string_view>
#include <system_error>
#include <utility>

#include "engine/io/content_digest.h"

namespace pyro {
namespace {

// A cache key: every field written with its length or as its bits, so that no two different
// inputs spell the same key.
class KeyText {
 public:
  KeyText& add(std::string_view s) {
    text_ += std::to_string(s.size());
    text_ += ':';
    text_ += s;
    return *this;
  }
  KeyText& add(const char* s) { return add(std::string_view(s)); }
  KeyText& add(float v) {
    uint32_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return add(std::to_string(bits));
  }
  KeyText& add(const glm::vec3& v) { return add(v.x).add(v.y).add(v.z); }
  KeyText& add(const glm::vec4& v) { return add(v.x).add(v.y).add(v.z).add(v.w); }
  KeyText& add(long long v) { return add(std::to_string(v)); }
  KeyText& add(bool v) { return add(v ? "1" : "0"); }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

// The folder's own stamp and every file's in it, by name.
std::string folder_stamp(const std::string& folder) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  KeyText key;
  key.add(file_version_key(folder));
  for (const std::string& name : names) key.add(name).add(file_version_key(folder + "/" + name));
  return key.text();
}

void add_emission(KeyText& key, const VolumeEmissionDescription& e) {
  key.add(e.automatic).add(e.scale).add(e.offset).add(e.intensity);
  key.add(static_cast<long long>(e.table.size()));
  for (const auto& [value, kelvin] : e.table) key.add(value).add(kelvin);
}

// What the import of any volume reads from the scene besides its entry: the lights it is lit
// with, the background, and whether the media are lit every frame instead (scene_volume.h).
void add_scene_lighting(KeyText& key, const SceneDescription& scene) {
  key.add(scene.shadows.has_value()).add(scene.background);
  key.add(static_cast<long long>(scene.directional_lights.size()));
  for (const DirectionalLight& l : scene.directional_lights)
    key.add(l.direction).add(l.color).add(l.intensity);
  key.add(static_cast<long long>(scene.ambient_lights.size()));
  for (const AmbientLight& l : scene.ambient_lights) key.add(l.color);
}

std::string volume_key(const SceneDescription& scene, const VolumeDescription& v) {
  KeyText key;
  key.add(v.file).add(v.fallback).add(v.path).add(static_cast<long long>(v.kind)).add(v.used_fallback);
  key.add(v.grid).add(static_cast<long long>(v.grid_index)).add(v.error).add(v.extinction);
  key.add(v.temperature_grid);
  add_emission(key, v.emission);
  key.add(v.anchor_center).add(v.position).add(v.scale).add(v.size);
  add_scene_lighting(key, scene);
  key.add(file_version_key(v.path));
  return key.text();
}

std::string flipbook_key(const FlipbookFire& fire) {
  const FlipbookPreparation& p = fire.preparation;
  KeyText key;
  key.add(fire.flipbook).add(p.crop).add(p.base_line).add(p.soften).add(folder_stamp(fire.flipbook));
  return key.text();
}

// The entry `key` of this load: already taken by it, else moved over from the last load's.
template <class Value>
Value* take_held(std::map<std::string, Value>& last, std::map<std::string, Value>& next,
                 const std::string& key) {
  if (auto it = next.find(key); it != next.end()) return &it->second;
  auto node = last.extract(key);
  if (node.empty()) return nullptr;
  return &next.insert(std::move(node)).position->second;
}

}  // namespace

void SceneAssetCache::begin_load() {
  volumes_.merge(next_volumes_);
  flipbooks_.merge(next_flipbooks_);
  next_volumes_.clear();
  next_flipbooks_.clear();
}

void SceneAssetCache::end_load() {
  volumes_ = std::move(next_volumes_);
  flipbooks_ = std::move(next_flipbooks_);
  next_volumes_.clear();
  next_flipbooks_.clear();
}

VolumeAsset SceneAssetCache::volume(const SceneDescription& scene, const VolumeDescription& v,
                                    const std::function<LoadedVolume()>& read,
                                    const NoteSink& note) {
  const std::string key = volume_key(scene, v);
  LoadedVolume* held = take_held(volumes_, next_volumes_, key);
  if (held) {
    ++counters_.volumes_reused;
  } else {
    held = &next_volumes_.emplace(key, read()).first->second;
    ++counters_.volumes_loaded;
  }
  if (note) {
    for (const std::string& n : held->notes) note(n);
  }
  return held->asset;
}

FlipbookAssets SceneAssetCache::flipbooks(const std::vector<FlipbookFire>& fires) {
  return load_flipbooks(fires, [this](const FlipbookFire& fire) {
    const std::string key = flipbook_key(fire);
    FlipbookFrames* held = take_held(flipbooks_, next_flipbooks_, key);
    if (held) {
      ++counters_.flipbooks_reused;
    } else {
      held = &next_flipbooks_.emplace(key, read_prepared_flipbook(fire)).first->second;
      ++counters_.flipbooks_prepared;
    }
    return *held;
  });
}

}  // namespace pyro
