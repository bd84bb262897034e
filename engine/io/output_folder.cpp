#include "engine/io/output_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <iterator>
#include <set>
#include <system_error>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/io/content_digest.h"
#include "engine/io/durable_file.h"
#include "engine/io/folder_output_kind.h"
#include "engine/io/io_error.h"

namespace pyro {

namespace fs = std::filesystem;

namespace {

bool same_inode(int fd, const std::string& path) {
  struct stat a {}, b {};
  return ::fstat(fd, &a) == 0 && ::stat(path.c_str(), &b) == 0 && a.st_dev == b.st_dev &&
         a.st_ino == b.st_ino;
}

std::vector<std::string> unaccounted_frames(const fs::path& out) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(out, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind("frame_", 0) == 0) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

// The JSON in `file`; a discarded value when it cannot be read or parsed.
nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return nlohmann::json::parse(text, nullptr, false);
}

nlohmann::json read_manifest(const fs::path& file) {
  nlohmann::json m = read_json(file);
  if (m.is_discarded() || !m.is_object() || !m["files"].is_array())
    throw UserError(file.string(), "", "a manifest written by pyro (a JSON object with \"files\"); "
                                       "pass --overwrite to replace the folder's contents");
  return m;
}

// The digest an identity, a manifest or a run record names; empty where it names none.
std::string digest_in(const nlohmann::json& j) {
  if (!j.is_object()) return {};
  const nlohmann::json& id = j.contains("identity") ? j.at("identity") : j;
  return id.is_object() && id.contains("digest") && id.at("digest").is_string() ? id.at("digest").get<std::string>()
                                                                               : std::string();
}

nlohmann::json parts_in(const nlohmann::json& j) {
  if (!j.is_object() || !j.contains("identity") || !j.at("identity").is_object()) return nullptr;
  return j.at("identity").value("parts", nlohmann::json());
}

nlohmann::json choices_in(const nlohmann::json& j) {
  return j.is_object() && j.contains("choices") && j.at("choices").is_object() ? j.at("choices")
                                                                               : nlohmann::json::object();
}

// What a run was made from ({"path": canonical path, "file": device and inode} of its scene
// file), when its identity records it.
nlohmann::json source_in(const nlohmann::json& identity) {
  return identity.is_object() && identity.contains("source") && identity.at("source").is_object()
             ? identity.at("source")
             : nlohmann::json();
}

// Whether two sources name one file: the same file by device and inode, or the same path.
bool same_source(const nlohmann::json& a, const nlohmann::json& b) {
  auto same = [&](const char* key) {
    return a.contains(key) && b.contains(key) && a.at(key).is_string() && a.at(key) == b.at(key);
  };
  return a.is_object() && b.is_object() && (same("file") || same("path"));
}

struct CheckedFiles {
  std::vector<std::string> held, damaged;
  std::map<std::string, std::string> digests;
};

// The files `listed` by manifest `m` that `out` holds, each read and checked against the SHA-256
// the manifest records for it: held when they agree, damaged otherwise (or when none is recorded,
// or the file cannot be read).
CheckedFiles check_listed_files(const fs::path& out, const nlohmann::json& m,
                                const std::vector<std::string>& listed) {
  const nlohmann::json recorded =
      m.contains("sha256") && m.at("sha256").is_object() ? m.at("sha256") : nlohmann::json::object();
  CheckedFiles c;
  std::error_code ec;
  for (const std::string& name : listed) {
    const fs::path file = out / name;
    if (!fs::exists(file, ec)) continue;
    std::string digest;
    try {
      digest = file_sha256(file.string());
    } catch (const IoError&) {
    }
    const auto it = recorded.find(name);
    if (!digest.empty() && it != recorded.end() && it->is_string() && *it == digest) {
      c.held.push_back(name);
      c.digests[name] = digest;
    } else {
      c.damaged.push_back(name);
    }
  }
  return c;
}

}  // namespace

OutputFolder::OutputFolder(const std::string& out, const std::string& identity_json,
                           Difference describe, OutputFolderOptions options)
    : out_(out), identity_json_(identity_json), describe_(describe), resume_(options.resume) {
  digest_ = digest_in(nlohmann::json::parse(identity_json_));
  std::error_code ec;
  created_ = create_output_folder(out_, "--out");
  try {
    lock(options.wait);
    check_manifest(options);
  } catch (...) {
    if (created_ && fs::is_empty(out_, ec)) fs::remove(out_, ec);
    if (lock_fd_ >= 0) ::close(lock_fd_);  // no destructor runs: a refusal holds no lock
    throw;
  }
}

OutputFolder::~OutputFolder() {
  staging_.reset();
  std::error_code ec;
  if (created_ && fs::is_empty(out_, ec)) fs::remove(out_, ec);  // a run that wrote nothing
  if (lock_fd_ >= 0) ::close(lock_fd_);  // releases the flock
}

void OutputFolder::lock(bool wait) {
  for (;;) {
    lock_fd_ = ::open(out_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (lock_fd_ < 0) throw IoError(out_, "open the output folder to lock it", errno);
    int rc;
    do rc = ::flock(lock_fd_, LOCK_EX | (wait ? 0 : LOCK_NB));
    while (rc != 0 && errno == EINTR);
    if (rc != 0 && errno == EWOULDBLOCK)
      throw UserError(out_, "--out", "a folder no other run is writing into; another pyro process "
                                     "holds its lock (pass --wait to wait for it to finish)");
    if (rc != 0) throw IoError(out_, "lock the output folder (flock)", errno);
    if (same_inode(lock_fd_, out_)) return;
    // The folder was removed (an empty one, by the run we waited for) while we waited.
    ::close(lock_fd_);
    lock_fd_ = -1;
    std::error_code ec;
    fs::create_directories(out_, ec);
  }
}

void OutputFolder::check_manifest(OutputFolderOptions options) {
  const fs::path file = fs::path(out_) / kOutputManifestName;
  std::error_code ec;
  std::vector<std::string> listed;
  std::string why;
  bool earlier_render = false;
  const bool has_manifest = fs::exists(file, ec);
  if (has_manifest) {
    const nlohmann::json m = read_manifest(file);
    for (const auto& f : m["files"])
      if (f.is_string() && f.get<std::string>().find('/') == std::string::npos)
        listed.push_back(f.get<std::string>());
    if (digest_in(m) == digest_) {
      // A run killed while moving its files in wrote the manifest first: keep what arrived, and
      // only what still has the bytes the manifest records.
      CheckedFiles checked = check_listed_files(out_, m, listed);
      held_ = std::move(checked.held);
      damaged_ = std::move(checked.damaged);
      digests_ = std::move(checked.digests);
      manifest_choices_ = choices_in(m).dump();
      return;
    }
    const nlohmann::json id_now = nlohmann::json::parse(identity_json_);
    const nlohmann::json& identity = m.value("identity", nlohmann::json::object());
    const std::string of = identity.is_object() && identity.value("scene_file", nlohmann::json()).is_string()
                               ? " of " + identity.at("scene_file").get<std::string>()
                               : std::string();
    // An earlier render of the same scene file, alone in the folder, is this render's to replace.
    earlier_render = same_source(source_in(identity), source_in(id_now)) &&
                     read_folder_output(out_, render_output_kind()).foreign.empty();
    why = "holds " + std::to_string(listed.size()) + " file(s) of " +
          (earlier_render ? "an earlier render" : "another run") + of +
          ", which differs from this one in " +
          describe_(parts_in(m).dump(), id_now.value("parts", nlohmann::json()).dump());
  } else {
    listed = unaccounted_frames(out_);
    if (listed.empty()) return;
    why = "holds " + std::to_string(listed.size()) + " frame files no manifest accounts for";
  }
  if (options.overwrite || (options.resume && has_manifest) || earlier_render) {
    if (has_manifest) stale_ = listed;  // files no manifest names are not this engine's to remove
    replaced_because_ = why;
    return;
  }
  throw UserError(out_, "--out", "an empty folder or one holding this run's frames; the folder " +
                                     why.substr(0, 400) +
                                     (has_manifest ? " (pass --resume to draw them again for this "
                                                     "run, or --overwrite to replace them)"
                                                   : " (pass --overwrite to write over them)"));
}

std::string OutputFolder::recorded(const std::string& key) const {
  nlohmann::json choices = manifest_choices_.empty() ? nlohmann::json::object()
                                                      : nlohmann::json::parse(manifest_choices_);
  if (!choices.contains(key)) {
    for (const fs::path& stale : stale_staging_folders(out_)) {
      const nlohmann::json r = read_json(stale / kStagingRecordName);
      if (digest_in(r) == digest_ && choices_in(r).contains(key)) {
        choices = choices_in(r);
        break;
      }
    }
  }
  return choices.contains(key) ? choices.at(key).dump() : std::string();
}

void OutputFolder::begin(const std::string& choices_json) {
  choices_json_ = choices_json;
  staging_ = std::make_unique<StagingFolder>(out_, /*remove_stale=*/false);
  const nlohmann::json record = {{"identity", nlohmann::json::parse(identity_json_)},
                                 {"choices", nlohmann::json::parse(choices_json_)}};
  write_file_durably((staging_->path() / kStagingRecordName).string(), record.dump() + "\n");
  take_killed_runs_files(resume_);
  removed_leftovers_ = remove_stale_staging(out_);
}

bool OutputFolder::same_run(const fs::path& record) const {
  const nlohmann::json r = read_json(record);
  return !r.is_discarded() && digest_in(r) == digest_ &&
         choices_in(r) == nlohmann::json::parse(choices_json_);
}

void OutputFolder::take_killed_runs_files(bool resume) {
  std::error_code ec;
  for (const fs::path& stale : stale_staging_folders(out_)) {
    if (!same_run(stale / kStagingRecordName)) continue;
    for (fs::directory_iterator it(stale, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string name = it->path().filename().string();
      // Finished files only: a temporary file (NAME.partial-PID) was cut by the kill.
      if (name.rfind("frame_", 0) != 0 || name.find(".partial-") != std::string::npos) continue;
      if (!resume) {
        ++discarded_;
      } else if (std::find(adopted_.begin(), adopted_.end(), name) == adopted_.end()) {
        staging_->adopt(it->path());
        adopted_.push_back(name);
      }
    }
  }
  std::sort(adopted_.begin(), adopted_.end());
}

void OutputFolder::commit() {
  std::set<std::string> files(held_.begin(), held_.end());
  std::error_code ec;
  for (fs::directory_iterator it(staging_->path(), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name == kStagingRecordName) continue;
    files.insert(name);
    digests_[name] = file_sha256(it->path().string());  // the bytes that are moved in
  }
  // The manifest first: a run killed while the files move in leaves a manifest naming them
  // (check_manifest keeps those that arrived; --resume adopts the rest from the staging folder,
  // whose record goes last).
  nlohmann::json digests = nlohmann::json::object();
  for (const std::string& name : files) digests[name] = digests_.at(name);
  nlohmann::json manifest = {{"identity", nlohmann::json::parse(identity_json_)},
                             {"choices", nlohmann::json::parse(choices_json_)},
                             {"files", std::vector<std::string>(files.begin(), files.end())},
                             {"sha256", digests}};
  write_file_durably((fs::path(out_) / kOutputManifestName).string(), manifest.dump(1) + "\n");
  staging_->commit();
  // The replaced run's files, and the damaged ones, that this run did not rewrite.
  for (const std::vector<std::string>* gone : {&stale_, &damaged_})
    for (const std::string& name : *gone)
      if (!files.count(name)) fs::remove(fs::path(out_) / name, ec);
  stale_.clear();
  held_.assign(files.begin(), files.end());
  created_ = false;
}

}  // namespace pyro
