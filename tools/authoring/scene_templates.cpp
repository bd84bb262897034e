#include "tools/authoring/scene_templates.h"

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string_view>

#include <nlohmann/json.hpp>

#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "engine/io/parameter_text.h"

namespace pyro::cli {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// The keys whose values are paths relative to the scene file's folder (the loader resolves them
// against it), by the array of objects that holds them.
struct AssetPathKey {
  const char* array;
  const char* key;
};
constexpr AssetPathKey kAssetPathKeys[] = {{"volumes", "file"}, {"volumes", "fallback"}, {"fires", "flipbook"}, {"meshes", "file"}};

json parse_template(const std::string& path, const std::string& text) {
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    throw UserError(path, "", std::string("expected a JSON scene template: ") + e.what());
  }
}

// `value`, a path relative to `from_folder` (or absolute), as a path relative to `to_folder`.
std::string rebased_path(const std::string& value, const fs::path& from_folder, const fs::path& to_folder) {
  if (fs::path(value).is_absolute()) return value;
  const fs::path target = fs::weakly_canonical(from_folder / value);
  const fs::path relative = fs::relative(target, to_folder);
  return relative.empty() ? target.generic_string() : relative.generic_string();
}

// Replaces the string value of each member `"key": "from"` of `text` by `to`; returns how many.
int replace_member_value(std::string& text, const std::string& key, const std::string& from, const std::string& to) {
  const std::string key_token = json(key).dump(), from_token = json(from).dump(), to_token = json(to).dump();
  int count = 0;
  for (std::size_t at = text.find(key_token); at != std::string::npos; at = text.find(key_token, at + 1)) {
    std::size_t v = text.find_first_not_of(" \t\r\n", at + key_token.size());
    if (v == std::string::npos || text[v] != ':') continue;
    v = text.find_first_not_of(" \t\r\n", v + 1);
    if (v == std::string::npos || text.compare(v, from_token.size(), from_token) != 0) continue;
    text.replace(v, from_token.size(), to_token);
    ++count;
  }
  return count;
}

struct PathRewrite {
  json::json_pointer at;
  std::string key, from, to;
};

// "$schema" and every asset path of `doc`, with the value each takes at `to_folder`.
std::vector<PathRewrite> path_rewrites(const json& doc, const fs::path& from_folder, const fs::path& to_folder) {
  std::vector<PathRewrite> rewrites;
  const auto add = [&](const json::json_pointer& at, const std::string& key) {
    if (doc.contains(at) && doc[at].is_string()) {
      const std::string from = doc[at].get<std::string>();
      rewrites.push_back({at, key, from, rebased_path(from, from_folder, to_folder)});
    }
  };
  add(json::json_pointer("/$schema"), "$schema");
  for (const AssetPathKey& k : kAssetPathKeys) {
    if (!doc.contains(k.array) || !doc[k.array].is_array()) continue;
    for (std::size_t i = 0; i < doc[k.array].size(); ++i)
      add(json::json_pointer("/" + std::string(k.array) + "/" + std::to_string(i) + "/" + k.key), k.key);
  }
  return rewrites;
}

}  // namespace

std::vector<SceneTemplate> scene_templates() {
  std::vector<SceneTemplate> templates;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(content_path("templates"), ec)) {
    if (entry.path().extension() != ".json") continue;
    const std::string path = entry.path().string();
    const json doc = parse_template(path, read_text_file(path));
    templates.push_back({entry.path().stem().string(), path, doc.value("name", "")});
  }
  std::sort(templates.begin(), templates.end(),
            [](const SceneTemplate& a, const SceneTemplate& b) { return a.name < b.name; });
  return templates;
}

SceneTemplate find_scene_template(const std::string& name) {
  const std::vector<SceneTemplate> templates = scene_templates();
  std::vector<std::string_view> names;
  for (const SceneTemplate& t : templates) {
    if (t.name == name) return t;
    names.push_back(t.name);
  }
  throw UserError("", "--template", "unknown template " + in_quotes(name) + "; expected one of " +
                                        quoted_list(names) + " (pyro new --list)");
}

std::string scene_template_text(const SceneTemplate& t, const std::string& destination) {
  std::string text = read_text_file(t.path);
  json expected = parse_template(t.path, text);
  const fs::path to_folder = fs::absolute(destination).parent_path();
  for (const PathRewrite& r : path_rewrites(expected, fs::absolute(t.path).parent_path(), to_folder)) {
    if (r.from == r.to) continue;
    replace_member_value(text, r.key, r.from, r.to);
    expected[r.at] = r.to;
  }
  // The text edit must have changed those values and nothing else.
  if (json::parse(text) != expected)
    throw std::logic_error(t.path + ": its paths could not be rewritten in place (a path key written unusually?)");
  return text;
}

}  // namespace pyro::cli
