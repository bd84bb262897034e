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
#include "engine/io/durable_file.h"
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

// The settings a manifest or a run record names; null where it names none.
nlohmann::json settings_in(const nlohmann::json& j) {
  return j.is_object() && j.contains("settings") ? j.at("settings") : nlohmann::json();
}

nlohmann::json read_manifest(const fs::path& file) {
  nlohmann::json m = read_json(file);
  if (m.is_discarded() || !m.is_object() || !m["files"].is_array())
    throw UserError(file.string(), "", "a manifest written by pyro (a JSON object with \"files\"); "
                                       "pass --overwrite to replace the folder's contents");
  return m;
}

}  // namespace

OutputFolder::OutputFolder(const std::string& out, const std::string& scene,
                           const std::string& settings_json, OutputFolderOptions options)
    : out_(out), scene_(scene), settings_json_(settings_json) {
  std::error_code ec;
  if (fs::exists(out_, ec) && !fs::is_directory(out_, ec))
    throw UserError(out_, "--out", "expected a folder for the output, found a file");
  const bool created = !fs::exists(out_, ec);
  fs::create_directories(out_, ec);
  if (ec) throw UserError(out_, "--out", "cannot create the output folder: " + ec.message());
  try {
    lock(options.wait);
    check_manifest(options.overwrite);
    staging_ = std::make_unique<StagingFolder>(out_, /*remove_stale=*/false);
    write_run_record();
    take_killed_runs_files(options.resume);
    remove_stale_staging(out_);
  } catch (...) {
    if (created && fs::is_empty(out_, ec)) fs::remove(out_, ec);
    throw;
  }
}

OutputFolder::~OutputFolder() {
  staging_.reset();
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

void OutputFolder::check_manifest(bool overwrite) {
  const fs::path file = fs::path(out_) / kOutputManifestName;
  std::error_code ec;
  std::vector<std::string> listed;
  std::string why;
  if (fs::exists(file, ec)) {
    const nlohmann::json m = read_manifest(file);
    for (const auto& f : m["files"])
      if (f.is_string()) listed.push_back(f.get<std::string>());
    const nlohmann::json settings = nlohmann::json::parse(settings_json_);
    if (m.value("scene", "") != scene_)
      why = "holds frames of " + m.value("scene", std::string("another scene"));
    else if (settings_in(m) != settings)
      why = "holds frames of this scene with other settings: " + settings_in(m).dump();
  } else {
    listed = unaccounted_frames(out_);
    if (!listed.empty()) why = "holds " + std::to_string(listed.size()) + " frame files no manifest accounts for";
  }
  if (why.empty()) {
    // A run killed while moving its files in wrote the manifest first: keep what is there.
    for (const std::string& name : listed)
      if (name.find('/') == std::string::npos && fs::exists(fs::path(out_) / name, ec))
        held_.push_back(name);
    return;
  }
  if (!overwrite)
    throw UserError(out_, "--out", "an empty folder or one holding this scene's frames with the "
                                   "same settings; the folder " + why.substr(0, 300) +
                                       " (pass --overwrite to replace them)");
  stale_ = listed;
}

void OutputFolder::write_run_record() {
  const nlohmann::json record = {{"scene", scene_}, {"settings", nlohmann::json::parse(settings_json_)}};
  write_file_durably((staging_->path() / kStagingRecordName).string(), record.dump() + "\n");
}

bool OutputFolder::same_run(const fs::path& record) const {
  const nlohmann::json r = read_json(record);
  return !r.is_discarded() && r.is_object() && r.value("scene", "") == scene_ &&
         settings_in(r) == nlohmann::json::parse(settings_json_);
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
  for (fs::directory_iterator it(staging_->path(), ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename() != kStagingRecordName) files.insert(it->path().filename().string());
  // The manifest first: a run killed while the files move in leaves a manifest naming them
  // (check_manifest keeps those that arrived; --resume adopts the rest from the staging folder,
  // whose record goes last).
  nlohmann::json manifest = {{"scene", scene_},
                             {"settings", nlohmann::json::parse(settings_json_)},
                             {"files", std::vector<std::string>(files.begin(), files.end())}};
  write_file_durably((fs::path(out_) / kOutputManifestName).string(), manifest.dump(1) + "\n");
  staging_->commit();
  // With --overwrite: the other run's files this one did not rewrite.
  for (const std::string& name : stale_)
    if (!files.count(name) && name.find('/') == std::string::npos)
      fs::remove(fs::path(out_) / name, ec);
  stale_.clear();
  held_.assign(files.begin(), files.end());
}

}  // namespace pyro
