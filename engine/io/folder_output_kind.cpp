#include "engine/io/folder_output_kind.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <set>

#include <nlohmann/json.hpp>

#include "engine/io/text_file.h"

namespace pyro {

namespace fs = std::filesystem;

namespace {

bool matches_any(const std::string& name, const std::vector<std::string>& patterns) {
  return std::any_of(patterns.begin(), patterns.end(),
                     [&](const std::string& p) { return matches_output_name(name, p); });
}

// Every file under `folder`, as paths relative to it, sorted.
std::vector<std::string> files_under(const fs::path& folder) {
  std::vector<std::string> files;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code kind;
    if (!it->is_directory(kind)) files.push_back(fs::relative(it->path(), folder, kind).string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The manifest's kind and files; an empty kind when there is none or it cannot be read.
std::string read_output_manifest(const fs::path& folder, std::set<std::string>& listed) {
  std::ifstream in(folder / kFolderOutputManifest, std::ios::binary);
  if (!in) return "";
  const nlohmann::json m = nlohmann::json::parse(std::istreambuf_iterator<char>(in), {}, nullptr, false);
  if (m.is_discarded() || !m.is_object() || !m.contains("files") || !m["files"].is_array()) return "";
  for (const nlohmann::json& f : m["files"])
    if (f.is_string()) listed.insert(f.get<std::string>());
  if (m.contains("kind") && m["kind"].is_string()) return m["kind"].get<std::string>();
  return m.contains("identity") ? "render" : "";
}

std::string first_component(const std::string& relative) {
  return relative.substr(0, relative.find('/'));
}

}  // namespace

bool matches_output_name(const std::string& name, const std::string& pattern) {
  const size_t star = pattern.find('*');
  if (star == std::string::npos) return name == pattern;
  const size_t tail = pattern.size() - star - 1;
  return name.size() >= star + tail && name.compare(0, star, pattern, 0, star) == 0 &&
         name.compare(name.size() - tail, tail, pattern, star + 1, tail) == 0;
}

FolderOutputContents read_folder_output(const fs::path& folder, const FolderOutputKind& kind) {
  FolderOutputContents c;
  std::error_code ec;
  c.exists = fs::is_directory(folder, ec);
  if (!c.exists) return c;
  std::set<std::string> listed;
  c.held_kind = read_output_manifest(folder, listed);
  const std::vector<std::string> files = files_under(folder);
  const bool unrecorded = c.held_kind.empty() && !files.empty() && !kind.unrecorded_names.empty() &&
                          std::all_of(files.begin(), files.end(), [&](const std::string& f) {
                            return matches_any(f, kind.unrecorded_names);
                          });
  if (unrecorded) c.held_kind = kind.name;
  for (const std::string& f : files) {
    const bool own = f == kFolderOutputManifest || listed.count(f) > 0 || unrecorded ||
                     matches_any(first_component(f), kind.own_names);
    (own ? c.outputs : c.foreign).push_back(f);
  }
  return c;
}

std::string name_some_files(const std::vector<std::string>& files) {
  constexpr size_t kNamed = 3;
  std::string text;
  for (size_t i = 0; i < files.size() && i < kNamed; ++i)
    text += (i == 0 ? "" : ", ") + std::string("\"") + files[i] + "\"";
  if (files.size() > kNamed) text += " and " + std::to_string(files.size() - kNamed) + " more file(s)";
  return text;
}

void write_folder_output_manifest(const fs::path& folder, const FolderOutputKind& kind) {
  nlohmann::json names = nlohmann::json::array();
  for (const std::string& f : files_under(folder))
    if (f != kFolderOutputManifest) names.push_back(f);
  const nlohmann::json manifest = {{"kind", kind.name}, {"files", names}};
  write_text_file((folder / kFolderOutputManifest).string(), manifest.dump(1) + "\n");
}

}  // namespace pyro
