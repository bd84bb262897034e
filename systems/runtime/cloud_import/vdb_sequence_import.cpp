#include "systems/runtime/cloud_import/vdb_sequence_import.h"

#include <algorithm>
#include <chrono>

#include <nlohmann/json.hpp>

#include "engine/core/file_kind.h"
#include "engine/core/stopwatch.h"
#include "engine/core/user_error.h"
#include "engine/io/particle_file.h"
#include "engine/io/vdb_file_check.h"
#include "systems/runtime/cloud_import/cloud_import.h"

namespace pyro {

namespace {

// The grid the reader would pick for `choice` (vdb_reader.h), or null.
const VdbGridInfo* chosen_grid(const std::vector<VdbGridInfo>& grids, const VdbGridChoice& choice) {
  if (choice.index >= 0) return choice.index < int(grids.size()) ? &grids[std::size_t(choice.index)] : nullptr;
  const auto named = [&](const std::string& name, bool float_only) -> const VdbGridInfo* {
    for (const VdbGridInfo& g : grids)
      if ((name.empty() || g.name == name) && (!float_only || g.is_float())) return &g;
    return nullptr;
  };
  if (!choice.name.empty()) return named(choice.name, false);
  if (const VdbGridInfo* density = named("density", true)) return density;
  return named("", true);
}

std::string choice_text(const VdbGridChoice& choice) {
  if (choice.index >= 0) return "grid index " + std::to_string(choice.index);
  if (!choice.name.empty()) return "grid \"" + choice.name + "\"";
  return "grid \"density\" or another float grid";
}

struct Bounds {
  bool any = false;
  std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
  void add(const GaussianParticle& p) {
    const std::array<double, 3> c{p.x, p.y, p.z};
    for (int k = 0; k < 3; ++k) {
      lo[k] = any ? std::min(lo[k], c[k]) : c[k];
      hi[k] = any ? std::max(hi[k], c[k]) : c[k];
    }
    any = true;
  }
};

// One frame: read, imported, written, dropped.
class FrameImporter {
 public:
  FrameImporter(const VdbSequenceImportOptions& o, const std::filesystem::path& folder, VdbSequenceImportReport& r)
      : options_(o), folder_(folder), report_(r), extinction_(o.extinction) {}

  ParticleSequenceFrame run(const VdbSequenceMember& m) {
    auto t = std::chrono::steady_clock::now();
    VdbReadStats stats;
    const SparseGrid grid = read_vdb_grid_sparse(m.path, options_.grid, nullptr, &stats);
    report_.read_seconds += seconds_since(t);
    report_.reader_peak_rss_bytes = std::max(report_.reader_peak_rss_bytes, stats.child_peak_rss_bytes);
    if (grid_name_.empty()) grid_name_ = grid.name;
    if (extinction_ <= 0.0 && !grid.empty() && grid.max_value > 0.0f) extinction_ = default_extinction(grid);
    t = std::chrono::steady_clock::now();
    ParticleFile file;
    file.version = 1;
    if (!grid.empty() && extinction_ > 0.0) file.particles = import_cloud(grid, import_options());
    report_.import_seconds += seconds_since(t);
    for (const GaussianParticle& p : file.particles) bounds_.add(p);
    t = std::chrono::steady_clock::now();
    const ParticleSequenceFrame frame{m.frame, particle_sequence_frame_name(m.frame), m.path,
                                      file.particles.size(), grid.active_voxels};
    file.metadata_json = metadata(m, grid).dump();
    write_particle_file((folder_ / frame.file).string(), file);
    report_.write_seconds += seconds_since(t);
    count(frame);
    return frame;
  }

  void finish(ParticleSequence& s) const {
    s.grid = grid_name_;
    s.extinction = extinction_;
    s.albedo = VolumeMedium{}.albedo;
    s.error_target = options_.error;
    s.fps = options_.fps;
    s.has_bounds = bounds_.any;
    s.bounds_min = bounds_.lo;
    s.bounds_max = bounds_.hi;
  }

 private:
  CloudImportOptions import_options() const {
    CloudImportOptions opt;
    opt.medium.extinction = extinction_;
    opt.tau_tolerance = tau_tolerance_for_error(options_.error);
    opt.threads = options_.threads;
    return opt;
  }
  nlohmann::json metadata(const VdbSequenceMember& m, const SparseGrid& grid) const {
    return {{"source", m.path}, {"grid", grid.name}, {"grid_index", grid.file_index},
            {"error_target", options_.error}, {"extinction", extinction_}, {"albedo", VolumeMedium{}.albedo},
            {"active_voxels", grid.active_voxels}, {"sequence_frame", m.frame}};
  }
  void count(const ParticleSequenceFrame& f) {
    report_.frames += 1;
    report_.empty_frames += f.particles == 0 ? 1 : 0;
    report_.particles += f.particles;
    report_.particles_max = std::max(report_.particles_max, f.particles);
    report_.active_voxels += f.active_voxels;
  }

  const VdbSequenceImportOptions& options_;
  std::filesystem::path folder_;
  VdbSequenceImportReport& report_;
  double extinction_;
  std::string grid_name_;
  Bounds bounds_;
};

}  // namespace

void check_vdb_sequence_member(const std::string& path, const VdbGridChoice& choice) {
  if (const std::string kind = non_regular_file_kind(path); !kind.empty())
    throw UserError(path, "", "a member of the sequence that is an OpenVDB file, found " + kind);
  check_vdb_file_structure(path);
  const std::vector<VdbGridInfo> grids = list_vdb_grids(path);
  const VdbGridInfo* grid = chosen_grid(grids, choice);
  if (grid == nullptr || !grid->is_float() || !grid->affine)
    throw UserError(path, choice_text(choice),
                    "a float grid with an affine transform to import, found " +
                        (grids.empty() ? std::string("no grids") : describe_grids(grids)));
}

void check_vdb_sequence_members(const std::vector<VdbSequenceMember>& members, const VdbGridChoice& choice,
                                ProgressSink* progress, VdbSequenceImportReport* report) {
  ProgressTask task(progress, "import-vdb: check the sequence", members.size());
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < members.size(); ++i) {
    task.stage(i, std::filesystem::path(members[i].path).filename().string());
    check_vdb_sequence_member(members[i].path, choice);
  }
  if (report) report->check_seconds = seconds_since(t0);
}

ParticleSequence import_vdb_sequence(const std::vector<VdbSequenceMember>& members,
                                     const VdbSequenceImportOptions& options, const std::filesystem::path& folder,
                                     ProgressSink* progress, VdbSequenceImportReport* report) {
  VdbSequenceImportReport local;
  ProgressTask task(progress, "import-vdb: import the sequence", members.size());
  ParticleSequence sequence;
  FrameImporter importer(options, folder, report ? *report : local);
  for (std::size_t i = 0; i < members.size(); ++i) {
    task.stage(i, "frame " + std::to_string(members[i].frame));
    sequence.frames.push_back(importer.run(members[i]));
  }
  importer.finish(sequence);
  write_particle_sequence_manifest(folder, sequence);
  task.update(members.size());
  return sequence;
}

}  // namespace pyro
