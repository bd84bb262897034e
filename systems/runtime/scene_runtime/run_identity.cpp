#include "systems/runtime/scene_runtime/run_identity.h"

#include <sys/stat.h>

#include <filesystem>
#include <vector>

#include "engine/core/build_id.h"
#include "engine/core/content_path.h"
#include "engine/core/sha256.h"
#include "systems/runtime/scene_runtime/default_flipbook.h"

namespace pyro {

namespace {

nlohmann::json asset_digests(const SceneDescription& scene, DigestCache& digests) {
  nlohmann::json assets = nlohmann::json::object();
  for (const VolumeDescription& v : scene.volumes)  // a particle sequence is a folder
    assets[v.pointer] = v.kind == VolumeFileKind::sequence ? digests.folder(v.path) : digests.file(v.path);
  for (size_t i = 0; i < scene.fires.size(); ++i) {
    const std::string& folder = scene.fires[i].flipbook;
    assets["/fires/" + std::to_string(i) + "/flipbook"] =
        digests.folder(folder.empty() ? default_flipbook_folder() : folder);
  }
  return assets;
}

nlohmann::json engine_identity(const std::string& version, DigestCache& digests) {
  return {{"version", version},
          {"build", program_build_id()},
          {"shaders", digests.folder(content_path("shaders"))}};
}

// "key a -> b" for each key whose value differs between two objects.
std::string changed_keys(const nlohmann::json& before, const nlohmann::json& now) {
  std::string out;
  auto add = [&](const std::string& key, const nlohmann::json& a, const nlohmann::json& b) {
    out += (out.empty() ? "" : ", ") + key + " " + (a.is_null() ? "unset" : a.dump()) + " -> " +
           (b.is_null() ? "unset" : b.dump());
  };
  for (const auto& [key, value] : now.items())
    if (!before.contains(key) || before.at(key) != value) add(key, before.value(key, nlohmann::json()), value);
  for (const auto& [key, value] : before.items())
    if (!now.contains(key)) add(key, value, nlohmann::json());
  return out;
}

}  // namespace

RunIdentity run_identity(const SceneDescription& scene, const nlohmann::json& settings,
                         const std::string& engine_version, DigestCache& digests) {
  RunIdentity id;
  id.parts = {{"scene", scene.content_digest},
              {"assets", asset_digests(scene, digests)},
              {"settings", settings},
              {"engine", engine_identity(engine_version, digests)}};
  id.digest = sha256_hex(id.parts.dump());
  return id;
}

nlohmann::json scene_source(const std::string& scene_path) {
  struct stat st {};
  if (scene_path == "-" || ::stat(scene_path.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
    return nullptr;
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::canonical(scene_path, ec);
  return {{"path", ec ? std::filesystem::absolute(scene_path).lexically_normal().string()
                      : canonical.string()},
          {"file", std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino)}};
}

std::string identity_difference(const nlohmann::json& before, const nlohmann::json& now) {
  const char* keys[] = {"scene", "assets", "settings", "engine"};
  for (const char* key : keys)
    if (!before.is_object() || !before.contains(key)) return "an identity this pyro does not read";
  std::vector<std::string> what;
  if (before["scene"] != now["scene"]) what.push_back("the scene");
  const nlohmann::json& a = before["assets"];
  const nlohmann::json& b = now["assets"];
  if (a.is_object() && b.is_object()) {
    for (const auto& [pointer, digest] : b.items())
      if (!a.contains(pointer) || a.at(pointer) != digest) what.push_back("the asset at " + pointer);
    for (const auto& [pointer, digest] : a.items())
      if (!b.contains(pointer)) what.push_back("the asset at " + pointer + " (gone)");
  }
  if (before["settings"] != now["settings"]) {
    const std::string keys_changed = before["settings"].is_object() && now["settings"].is_object()
                                         ? " (" + changed_keys(before["settings"], now["settings"]) + ")"
                                         : "";
    what.push_back("the settings" + keys_changed);
  }
  if (before["engine"] != now["engine"]) what.push_back("the engine (version, build or shaders)");
  if (what.empty()) return "nothing";
  std::string out;
  for (size_t i = 0; i < what.size(); ++i)
    out += (i == 0 ? "" : i + 1 == what.size() ? " and " : ", ") + what[i];
  return out;
}

}  // namespace pyro
