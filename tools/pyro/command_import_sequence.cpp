// pyro import-vdb "smoke_%06d.vdb" | "smoke_*.vdb" | FOLDER --out NAME.pyroseq [--fps F]
//                 [--extinction K] [--grid NAME | --grid-index I] [--error E] [--json]
// Every member is found and checked before anything is written; the frames are imported one at a
// time into a staging folder beside the output, which replaces the output only when complete.
#include "tools/pyro/import_sequence.h"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/io/folder_replacement.h"
#include "engine/io/output_gate.h"
#include "engine/io/particle_sequence.h"
#include "systems/runtime/cloud_import/vdb_sequence_import.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

void check_sequence_destination(const SequenceImportArgs& a) {
  if (a.out.empty()) throw UserError("", "--out", "the particle sequence folder to write (NAME.pyroseq)");
  const std::string ext = std::filesystem::path(a.out).extension().string();
  if (ext != ".pyroseq")
    throw UserError(a.out, "--out", "a folder name ending in \".pyroseq\" for an animated sequence, found \"" +
                                        (ext.empty() ? std::string("no extension") : ext) + "\"");
  char found[64];
  std::snprintf(found, sizeof found, "%g", a.error);
  if (!(a.error > 0.0 && a.error <= 1.0))
    throw UserError("", "--error", std::string("a number in (0, 1], found ") + found);
}

uint64_t peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return uint64_t(usage.ru_maxrss) * 1024;  // Linux: kilobytes
}

nlohmann::json summary(const SequenceImportArgs& a, const ParticleSequence& s, const VdbSequenceImportReport& r,
                       double seconds) {
  return {{"input", a.input}, {"out", a.out}, {"frames", r.frames},
          {"first_frame", s.frames.front().number}, {"last_frame", s.frames.back().number},
          {"empty_frames", r.empty_frames}, {"particles", r.particles}, {"particles_max", r.particles_max},
          {"active_voxels", r.active_voxels}, {"grid", s.grid}, {"extinction", s.extinction}, {"fps", s.fps},
          {"error_target", s.error_target}, {"seconds", seconds}, {"check_seconds", r.check_seconds},
          {"read_seconds", r.read_seconds}, {"import_seconds", r.import_seconds},
          {"write_seconds", r.write_seconds}, {"frames_per_second", double(r.frames) / std::max(seconds, 1e-9)},
          {"peak_rss_bytes", peak_rss_bytes()}, {"reader_peak_rss_bytes", r.reader_peak_rss_bytes}};
}

void print_summary(const nlohmann::json& j) {
  std::printf("%s: %llu frames (%lld..%lld, %llu empty) -> %llu particles (at most %llu a frame), %.2f s "
              "(%.2f frames/s); wrote %s\n",
              j["input"].get<std::string>().c_str(), j["frames"].get<unsigned long long>(),
              j["first_frame"].get<long long>(), j["last_frame"].get<long long>(),
              j["empty_frames"].get<unsigned long long>(), j["particles"].get<unsigned long long>(),
              j["particles_max"].get<unsigned long long>(), j["seconds"].get<double>(),
              j["frames_per_second"].get<double>(), j["out"].get<std::string>().c_str());
}

}  // namespace

void run_sequence_import(const SequenceImportArgs& a) {
  check_sequence_destination(a);
  const std::vector<VdbSequenceMember> members = find_vdb_sequence_members(a.input);
  OutputGate gate;
  if (std::filesystem::is_directory(a.input)) gate.reads(a.input, "the sequence's folder");
  for (const VdbSequenceMember& m : members) gate.reads(m.path, "a member of the sequence");
  gate.writes({a.out, "--out", OutputShape::folder, particle_sequence_output_kind(), a.overwrite}).check();
  const auto t0 = std::chrono::steady_clock::now();
  VdbSequenceImportReport report;
  check_vdb_sequence_members(members, a.grid, terminal_progress(), &report);
  FolderReplacement staged(a.out, particle_sequence_output_kind(), a.overwrite);
  const ParticleSequence sequence = import_vdb_sequence(
      members, {a.grid, a.error, a.extinction, a.fps, 0}, staged.path(), terminal_progress(), &report);
  staged.commit();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const nlohmann::json j = summary(a, sequence, report, seconds);
  if (report.empty_frames > 0)
    std::fprintf(stderr, "pyro import-vdb: %s: %llu frame(s) with no active voxels: 0 particles each\n",
                 a.input.c_str(), static_cast<unsigned long long>(report.empty_frames));
  if (a.json)
    write_stdout(j.dump() + "\n");
  else
    print_summary(j);
}

}  // namespace pyro::cli
