#include "tools/farm/farm_record.h"

#include <fstream>
#include <iterator>

#include "engine/core/user_error.h"
#include "engine/io/text_file.h"

namespace pyro {

namespace fs = std::filesystem;

fs::path farm_folder(const std::string& dir) { return fs::path(dir) / ".farm"; }
fs::path farm_record_path(const std::string& dir) { return farm_folder(dir) / "farm.json"; }
fs::path chunk_folder(const std::string& dir, const FrameRange& chunk) {
  return farm_folder(dir) / "chunks" /
         (std::to_string(chunk.first) + "-" + std::to_string(chunk.last));
}

namespace {

nlohmann::json range_json(const FrameRange& r) { return nlohmann::json::array({r.first, r.last}); }

nlohmann::json submission_json(const FarmSubmission& s) {
  nlohmann::json chunks = nlohmann::json::array();
  for (const FrameRange& c : s.chunks) chunks.push_back(range_json(c));
  return {{"array_job", s.array_job}, {"collect_job", s.collect_job}, {"chunks", chunks}};
}

// The value at `pointer`, of the type `check` accepts; UserError naming both otherwise.
const nlohmann::json& field(const nlohmann::json& j, const std::string& pointer,
                            const std::string& file, bool (nlohmann::json::*check)() const noexcept,
                            const std::string& expected) {
  const nlohmann::json::json_pointer p(pointer);
  if (!j.contains(p) || !(j.at(p).*check)()) throw UserError(file, pointer, "expected " + expected);
  return j.at(p);
}

FrameRange range_from(const nlohmann::json& j, const std::string& pointer,
                      const std::string& file) {
  const nlohmann::json& r =
      field(j, pointer, file, &nlohmann::json::is_array, "[first, last] frames");
  if (r.size() != 2 || !r[0].is_number_integer() || !r[1].is_number_integer() ||
      r[0].get<int>() < 0 || r[0].get<int>() > r[1].get<int>())
    throw UserError(file, pointer, "expected [first, last] frames with 0 <= first <= last");
  return {r[0].get<int>(), r[1].get<int>()};
}

std::vector<std::string> strings_from(const nlohmann::json& j, const std::string& pointer,
                                      const std::string& file) {
  std::vector<std::string> out;
  for (const auto& s : field(j, pointer, file, &nlohmann::json::is_array, "an array of strings")) {
    if (!s.is_string()) throw UserError(file, pointer, "expected an array of strings");
    out.push_back(s.get<std::string>());
  }
  return out;
}

FarmSubmission submission_from(const nlohmann::json& j, const std::string& pointer,
                               const std::string& file) {
  FarmSubmission s;
  s.array_job = field(j, pointer + "/array_job", file, &nlohmann::json::is_string, "a job id")
                    .get<std::string>();
  s.collect_job = field(j, pointer + "/collect_job", file, &nlohmann::json::is_string, "a job id")
                      .get<std::string>();
  const size_t n =
      field(j, pointer + "/chunks", file, &nlohmann::json::is_array, "an array of chunks").size();
  for (size_t i = 0; i < n; ++i)
    s.chunks.push_back(range_from(j, pointer + "/chunks/" + std::to_string(i), file));
  return s;
}

nlohmann::json scheduler_json(const FarmScheduler& s) {
  return {{"time", s.time},
          {"mem", s.mem},
          {"cpus_per_task", s.cpus_per_task},
          {"account", s.account},
          {"sbatch_args", s.sbatch_args}};
}

// The scheduler options under /scheduler; none for a record written before they existed.
FarmScheduler scheduler_from(const nlohmann::json& j, const std::string& file) {
  using J = nlohmann::json;
  FarmScheduler s;
  if (!j.contains("scheduler")) return s;
  s.time = field(j, "/scheduler/time", file, &J::is_string, "a time limit or \"\"").get<std::string>();
  s.mem = field(j, "/scheduler/mem", file, &J::is_string, "a memory size or \"\"").get<std::string>();
  s.cpus_per_task =
      field(j, "/scheduler/cpus_per_task", file, &J::is_number_integer, "a CPU count").get<int>();
  s.account = field(j, "/scheduler/account", file, &J::is_string, "an account or \"\"").get<std::string>();
  s.sbatch_args = strings_from(j, "/scheduler/sbatch_args", file);
  return s;
}

}  // namespace

nlohmann::json farm_record_json(const FarmRecord& r) {
  nlohmann::json submissions = nlohmann::json::array();
  for (const FarmSubmission& s : r.submissions) submissions.push_back(submission_json(s));
  return {{"scene", r.scene},
          {"frames", range_json(r.frames)},
          {"chunk", r.chunk},
          {"identity", r.identity},
          {"pyro", r.pyro},
          {"render_options", r.render_options},
          {"partition", r.partition},
          {"scheduler", scheduler_json(r.scheduler)},
          {"frames_per_second", r.frames_per_second},
          {"submissions", submissions},
          {"superseded", r.superseded}};
}

FarmRecord farm_record_from_json(const nlohmann::json& j, const std::string& file) {
  using J = nlohmann::json;
  FarmRecord r;
  r.scene = field(j, "/scene", file, &J::is_string, "the scene file's path").get<std::string>();
  r.frames = range_from(j, "/frames", file);
  r.chunk = field(j, "/chunk", file, &J::is_number_integer, "frames per task").get<int>();
  if (r.chunk < 1) throw UserError(file, "/chunk", "expected at least one frame per task");
  r.identity = field(j, "/identity", file, &J::is_object, "the run's identity");
  field(j, "/identity/digest", file, &J::is_string, "the identity's digest");
  r.pyro = field(j, "/pyro", file, &J::is_string, "the pyro binary's path").get<std::string>();
  r.render_options = strings_from(j, "/render_options", file);
  r.partition =
      field(j, "/partition", file, &J::is_string, "a partition name or \"\"").get<std::string>();
  r.scheduler = scheduler_from(j, file);
  r.frames_per_second =
      field(j, "/frames_per_second", file, &J::is_number, "the scene's fps").get<double>();
  if (j.contains("superseded")) r.superseded = strings_from(j, "/superseded", file);
  const size_t n = field(j, "/submissions", file, &J::is_array, "the jobs submitted").size();
  for (size_t i = 0; i < n; ++i)
    r.submissions.push_back(submission_from(j, "/submissions/" + std::to_string(i), file));
  return r;
}

FarmRecord read_farm_record(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw UserError(dir, "", "an output folder of `pyro farm submit`; no such folder");
  const std::string file = farm_record_path(dir).string();
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw UserError(file, "",
                    "the farm record `pyro farm submit` writes into its --out folder; "
                    "there is none, so " +
                        dir + " holds no farm job");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object())
    throw UserError(file, "", "a JSON object (a farm record)");
  return farm_record_from_json(j, file);
}

void write_farm_record(const std::string& dir, const FarmRecord& record) {
  write_text_file(farm_record_path(dir).string(), farm_record_json(record).dump(1) + "\n");
}

}  // namespace pyro
