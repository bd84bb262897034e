#include "tools/farm/farm_collect.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/io/content_digest.h"
#include "engine/io/io_error.h"
#include "engine/io/output_folder.h"
#include "engine/io/staging_folder.h"
#include "engine/io/text_file.h"
#include "tools/farm/frame_chunks.h"
#include "systems/runtime/scene_runtime/run_identity.h"

namespace pyro {

namespace fs = std::filesystem;

int frame_of_file(const std::string& name) {
  constexpr std::string_view prefix = "frame_";
  if (name.rfind(prefix, 0) != 0) return -1;
  size_t end = prefix.size();
  while (end < name.size() && end - prefix.size() < 9 && name[end] >= '0' && name[end] <= '9')
    ++end;
  if (end == prefix.size() || end == name.size() || (name[end] != '.' && name[end] != '_'))
    return -1;
  return std::stoi(name.substr(prefix.size(), end - prefix.size()));
}

namespace {

std::string describe_difference(const std::string& before, const std::string& now) {
  return identity_difference(nlohmann::json::parse(before), nlohmann::json::parse(now));
}

// An output folder's manifest; a discarded value when there is none or it cannot be read.
nlohmann::json read_manifest(const fs::path& folder) {
  std::ifstream in(folder / kOutputManifestName, std::ios::binary);
  if (!in) return nlohmann::json(nlohmann::json::value_t::discarded);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return nlohmann::json::parse(text, nullptr, false);
}

std::string manifest_digest(const nlohmann::json& m) {
  const nlohmann::json::json_pointer p("/identity/digest");
  return m.is_object() && m.contains(p) && m.at(p).is_string() ? m.at(p).get<std::string>()
                                                               : std::string();
}

// Whether `file` has the SHA-256 `m` records for its name.
bool has_recorded_digest(const nlohmann::json& m, const fs::path& file) {
  const nlohmann::json::json_pointer p("/sha256");
  if (!m.contains(p) || !m.at(p).is_object()) return false;
  const auto it = m.at(p).find(file.filename().string());
  std::error_code ec;
  if (it == m.at(p).end() || !it->is_string() || !fs::is_regular_file(file, ec)) return false;
  try {
    return *it == file_sha256(file.string());
  } catch (const IoError&) {
    return false;
  }
}

// The frames of `record` whose files `folder`'s manifest names for the record's identity and
// the folder holds with the bytes the manifest records.
std::set<int> frames_in_manifest(const fs::path& folder, const FarmRecord& record) {
  std::set<int> frames;
  const nlohmann::json m = read_manifest(folder);
  if (manifest_digest(m) != record.digest() || !m.contains("files") || !m.at("files").is_array())
    return frames;
  for (const auto& f : m.at("files")) {
    const int frame = f.is_string() ? frame_of_file(f.get<std::string>()) : -1;
    if (frame >= record.frames.first && frame <= record.frames.last &&
        has_recorded_digest(m, folder / f.get<std::string>()))
      frames.insert(frame);
  }
  return frames;
}

std::vector<fs::path> chunk_folders(const std::string& dir) {
  std::vector<fs::path> folders;
  std::error_code ec;
  for (fs::directory_iterator it(farm_folder(dir) / "chunks", ec), end; !ec && it != end;
       it.increment(ec))
    if (it->is_directory(ec)) folders.push_back(it->path());
  std::sort(folders.begin(), folders.end());
  return folders;
}

// A chunk folder locked, its manifest checked against the job's identity; null (with a note when
// it holds something) when its frames cannot be moved in now.
std::unique_ptr<OutputFolder> open_chunk(const fs::path& path, const FarmRecord& record,
                                         const NoteSink& note) {
  try {
    auto folder = std::make_unique<OutputFolder>(path.string(), record.identity.dump(),
                                                 describe_difference, OutputFolderOptions{});
    if (!folder->held_files().empty() || !folder->damaged_files().empty()) return folder;
  } catch (const UserError& e) {
    if (note) note("left " + path.string() + " as it is: " + e.what());
  }
  return nullptr;
}

// The quality pick the collected run records: DIR's, else the first chunk's; chunks drawn with
// another pick (a cache that changed between tasks) are left out and named, since a folder's
// frames share one pick.
std::string run_quality(const OutputFolder& out, std::vector<std::unique_ptr<OutputFolder>>& chunks,
                        const std::vector<fs::path>& paths, const NoteSink& note) {
  std::string quality = out.recorded("quality");
  for (size_t i = 0; i < chunks.size(); ++i) {
    if (!chunks[i]) continue;
    const std::string q = chunks[i]->recorded("quality");
    if (quality.empty()) quality = q;
    if (q == quality) continue;
    if (note) note("left " + paths[i].string() + " as it is: drawn with another quality pick");
    chunks[i].reset();
  }
  return quality;
}

// Removes what is left of the collected chunks: their manifests (DIR's names their frames now),
// their damaged frames, staging folders of killed tasks, and the folders once empty.
void remove_collected(std::vector<std::unique_ptr<OutputFolder>>& chunks,
                      const std::vector<fs::path>& paths) {
  std::error_code ec;
  for (size_t i = 0; i < chunks.size(); ++i) {
    if (!chunks[i]) continue;
    fs::remove(paths[i] / kOutputManifestName, ec);
    for (const std::string& name : chunks[i]->damaged_files()) fs::remove(paths[i] / name, ec);
    remove_stale_staging(paths[i]);
    chunks[i].reset();         // unlocks
    fs::remove(paths[i], ec);  // (only when empty)
  }
}

int move_chunks_in(OutputFolder& out, const std::vector<std::unique_ptr<OutputFolder>>& chunks,
                   const std::vector<fs::path>& paths, const FrameRange& frames) {
  int moved = 0;
  for (size_t i = 0; i < chunks.size(); ++i) {
    if (!chunks[i]) continue;
    for (const std::string& name : chunks[i]->held_files()) {
      const int frame = frame_of_file(name);
      if (frame < frames.first || frame > frames.last) continue;
      out.staging().adopt(paths[i] / name);
      ++moved;
    }
  }
  return moved;
}

// The frames of the job found damaged in a chunk folder opened for collection, or in DIR and not
// replaced by this collect (called after out.commit()), each named by its path inside DIR.
std::vector<std::string> damaged_frames(const std::string& dir, const OutputFolder& out,
                                        const std::vector<std::unique_ptr<OutputFolder>>& chunks,
                                        const std::vector<fs::path>& paths) {
  std::vector<std::string> damaged;
  const std::vector<std::string>& held = out.held_files();
  for (const std::string& name : out.damaged_files())
    if (std::find(held.begin(), held.end(), name) == held.end()) damaged.push_back(name);
  for (size_t i = 0; i < chunks.size(); ++i)
    if (chunks[i])
      for (const std::string& name : chunks[i]->damaged_files())
        damaged.push_back((paths[i] / name).lexically_relative(dir).string());
  return damaged;
}

// SHA256SUMS from the digests DIR's manifest records for the frames (each checked or computed as
// it was moved in): written only when every frame is there and none was damaged.
void write_checksums(const std::string& dir, const FarmCollection& c, const OutputFolder& out) {
  const fs::path file = fs::path(dir) / kFarmChecksumsName;
  if (!c.missing.empty() || !c.damaged.empty()) {
    std::error_code ec;
    fs::remove(file, ec);
    return;
  }
  std::string text;
  for (const std::string& name : c.files) text += out.file_digests().at(name) + "  " + name + "\n";
  write_text_file(file.string(), text);
}

}  // namespace

void refuse_other_run(const std::string& dir, const std::string& digest,
                      const std::vector<std::string>& replaceable) {
  const nlohmann::json m = read_manifest(dir);
  std::error_code ec;
  if (!fs::exists(fs::path(dir) / kOutputManifestName, ec) || manifest_digest(m) == digest ||
      std::count(replaceable.begin(), replaceable.end(), manifest_digest(m)) > 0)
    return;
  throw UserError(dir, "",
                  "a folder for this farm job's frames; its manifest (" +
                      std::string(kOutputManifestName) +
                      ") holds another run's (another "
                      "scene, asset, settings or engine): use another folder");
}

FarmCollection collect_farm(const std::string& dir, const FarmRecord& record,
                            const NoteSink& note) {
  refuse_other_run(dir, record.digest(), record.superseded);
  OutputFolderOptions options;
  options.wait = true;    // a render by hand into DIR finishes first
  options.resume = true;  // takes up what a killed collect had moved into DIR's staging folder
  OutputFolder out(dir, record.identity.dump(), describe_difference, options);
  const std::vector<fs::path> paths = chunk_folders(dir);
  std::vector<std::unique_ptr<OutputFolder>> chunks;
  for (const fs::path& p : paths) chunks.push_back(open_chunk(p, record, note));
  const std::string quality = run_quality(out, chunks, paths, note);
  out.begin(quality.empty() ? "{}"
                            : nlohmann::json{{"quality", nlohmann::json::parse(quality)}}.dump());
  FarmCollection c;
  c.moved = move_chunks_in(out, chunks, paths, record.frames);
  out.commit();
  c.damaged = damaged_frames(dir, out, chunks, paths);
  remove_collected(chunks, paths);
  std::set<int> present;
  for (const std::string& name : out.held_files()) {
    const int frame = frame_of_file(name);
    if (frame < record.frames.first || frame > record.frames.last) continue;
    c.files.push_back(name);
    present.insert(frame);
  }
  c.missing = missing_ranges(record.frames, present);
  write_checksums(dir, c, out);
  return c;
}

std::set<int> finished_farm_frames(const std::string& dir, const FarmRecord& record) {
  std::set<int> frames = frames_in_manifest(dir, record);
  for (const fs::path& chunk : chunk_folders(dir)) frames.merge(frames_in_manifest(chunk, record));
  return frames;
}

}  // namespace pyro
