#include "tools/bench/vdb_sequence_bench.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <string_view>

#include <sys/resource.h>
#include <unistd.h>

#include "engine/core/stopwatch.h"
#include "engine/core/user_error.h"
#include "engine/io/isolated_call.h"
#include "engine/io/output_gate.h"
#include "engine/io/scratch_folder.h"
#include "engine/volume/puff_sequence.h"
#include "systems/runtime/cloud_import/vdb_sequence_import.h"

namespace pyro {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The folder the bench works in: `keep` (left in place), or a fresh scratch folder removed at
// the end.
struct WorkFolder {
  std::optional<ScratchFolder> scratch;
  fs::path path;
  explicit WorkFolder(const std::string& keep) {
    if (keep.empty()) {
      scratch.emplace("pyro-bench-vdb-sequence");
      path = scratch->path;
    } else {
      path = keep;
      fs::create_directories(path);
    }
  }
};

nlohmann::json run_json(const VdbSequenceImportReport& r, double seconds) {
  return {{"frames", r.frames},         {"particles", r.particles},       {"particles_max", r.particles_max},
          {"active_voxels", r.active_voxels}, {"seconds", seconds},
          {"frames_per_second", double(r.frames) / std::max(seconds, 1e-9)},
          {"check_seconds", r.check_seconds}, {"read_seconds", r.read_seconds},
          {"import_seconds", r.import_seconds}, {"write_seconds", r.write_seconds},
          {"reader_peak_rss_bytes", r.reader_peak_rss_bytes}};
}

// Imports the first `length` members into `out`, in a child process; its report and peak memory.
nlohmann::json import_in_child(const std::vector<VdbSequenceMember>& all, int length, const fs::path& out,
                               double error) {
  const std::vector<VdbSequenceMember> members(all.begin(), all.begin() + length);
  nlohmann::json result;
  IsolatedRunStats stats;
  run_isolated(
      out.string(), "importing the sequence",
      [&](ResultWriter& w) {
        fs::remove_all(out);
        fs::create_directories(out);
        const auto t0 = Clock::now();
        VdbSequenceImportReport r;
        check_vdb_sequence_members(members, {}, nullptr, &r);
        VdbSequenceImportOptions o;
        o.error = error;
        import_vdb_sequence(members, o, out, nullptr, &r);
        nlohmann::json run = run_json(r, seconds_since(t0));
        rusage self{};
        ::getrusage(RUSAGE_SELF, &self);
        run["importer_peak_rss_bytes"] = uint64_t(self.ru_maxrss) * 1024;  // Linux: kilobytes
        const std::string text = run.dump();
        w.append(text.data(), text.size());
      },
      [&](std::string_view bytes) { result = nlohmann::json::parse(bytes); }, IsolationLimits{3600.0, 0}, &stats);
  result["peak_rss_bytes"] = stats.peak_rss_bytes;
  return result;
}

}  // namespace

// The puff's whole motion in `length` frames, written into `folder`.
std::vector<VdbSequenceMember> write_members(const VdbSequenceBenchOptions& o, int length, const fs::path& folder) {
  PuffSequenceOptions puff;
  puff.frames = length;
  puff.side = o.side;
  fs::create_directories(folder);
  std::vector<VdbSequenceMember> members;
  int frame = puff.first_frame;
  for (const std::string& path : write_puff_sequence(folder.string(), puff)) members.push_back({path, frame++});
  return members;
}

nlohmann::json bench_vdb_sequence(const VdbSequenceBenchOptions& o) {
  if (o.lengths.empty() || *std::min_element(o.lengths.begin(), o.lengths.end()) < 1)
    throw UserError("", "--frames", "one or more sequence lengths, each at least 1");
  OutputGate().writes({o.keep, "--keep", OutputShape::container}).check();
  const WorkFolder work(o.keep);
  nlohmann::json out = {{"side", o.side}, {"error_target", o.error}, {"runs", nlohmann::json::array()}};
  ProgressTask task(o.progress, "bench vdb-sequence", 2 * o.lengths.size());
  double generate_seconds = 0.0;
  for (std::size_t i = 0; i < o.lengths.size(); ++i) {
    const std::string name = "puff_" + std::to_string(o.lengths[i]);
    task.stage(2 * i, "write " + std::to_string(o.lengths[i]) + " frames");
    if (o.on_note) o.on_note("writing " + std::to_string(o.lengths[i]) + " frames of a " + std::to_string(o.side) +
                             "^3 puff into " + (work.path / name).string());
    const auto t0 = Clock::now();
    const std::vector<VdbSequenceMember> members = write_members(o, o.lengths[i], work.path / name);
    generate_seconds += seconds_since(t0);
    task.stage(2 * i + 1, "import " + std::to_string(o.lengths[i]) + " frames");
    out["runs"].push_back(import_in_child(members, int(members.size()), work.path / (name + ".pyroseq"), o.error));
  }
  out["generate_seconds"] = generate_seconds;
  const auto& runs = out["runs"];
  out["peak_rss_ratio"] = runs.back()["importer_peak_rss_bytes"].get<double>() /
                          std::max(1.0, runs.front()["importer_peak_rss_bytes"].get<double>());
  return out;
}

}  // namespace pyro
