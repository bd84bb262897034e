#include "tools/bench/import_scale.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>

#include <sys/resource.h>
#include <unistd.h>

#include "engine/core/content_path.h"
#include "engine/core/file_kind.h"
#include "engine/core/stopwatch.h"
#include "engine/core/user_error.h"
#include "engine/io/output_gate.h"
#include "engine/io/vdb_file_check.h"
#include "engine/io/vdb_reader.h"
#include "engine/io/vdb_resampled_volume.h"
#include "engine/volume/procedural_cloud.h"
#include "tools/import/sparse_import_error.h"
#include "systems/runtime/cloud_import/cloud_import.h"
#include "systems/runtime/cloud_import/grid_framing.h"

namespace pyro {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

uint64_t peak_rss_bytes(int who) {
  struct rusage usage;
  if (::getrusage(who, &usage) != 0) return 0;
  return uint64_t(usage.ru_maxrss) * 1024;  // Linux: kilobytes
}

// The small grid to resample, and a name for it.
DenseGrid source_grid(const ImportScaleOptions& o, std::string& name) {
  fs::path file = o.source;
  if (file.empty()) {
    const fs::path disney =
        fs::path(content_dir()) / ".." / ".." / "shared" / "data" / "vdb" / "wdas_cloud_sixteenth.vdb";
    std::error_code ec;
    if (fs::is_regular_file(disney, ec)) file = fs::weakly_canonical(disney, ec);
  }
  if (!file.empty()) {
    name = file.string();
    return read_vdb_grid(file.string());
  }
  ProceduralCloudOptions cloud;
  cloud.width = 160;
  name = "the procedural cloud (engine/volume/procedural_cloud.h), width " + std::to_string(cloud.width);
  return make_procedural_cloud(cloud);
}

void note(const ImportScaleOptions& o, const std::string& line) {
  if (o.on_note) o.on_note(line);
}

// Writes the synthetic file: the source resampled by the cube root of voxels / its active voxels
// (the trilinear halo adds a little more).
nlohmann::json make_file(const ImportScaleOptions& o, const std::string& file) {
  std::string name;
  const auto t0 = Clock::now();
  const DenseGrid source = source_grid(o, name);
  if (source.active_voxels == 0) throw UserError(name, "", "a source grid with active voxels to resample");
  // Active voxels grow about as scale^3; a file short of the count is written again, finer.
  double scale = std::cbrt(double(o.voxels) / double(source.active_voxels));
  VdbResampleReport r;
  for (int attempt = 0; attempt < 4; ++attempt) {
    char line[512];
    std::snprintf(line, sizeof line, "writing %s: %s resampled %.4f times finer (%llu active voxels there)",
                  file.c_str(), name.c_str(), scale, static_cast<unsigned long long>(source.active_voxels));
    note(o, line);
    r = write_vdb_resampled_fog_volume(file, "density", source, scale, o.progress_fd, "pyro bench import-scale: ");
    if (r.active_voxels >= o.voxels) break;
    scale *= 1.01 * std::cbrt(double(o.voxels) / double(std::max<uint64_t>(r.active_voxels, 1)));
  }
  return {{"source", name}, {"scale", scale}, {"generate_seconds", seconds_since(t0)},
          {"writer_peak_rss_bytes", r.child_peak_rss_bytes}};
}

// --keep FILE is refused before any work when it would replace the source or cannot be written.
void check_kept_file(const ImportScaleOptions& o) {
  if (o.keep.empty()) return;
  OutputGate().reads(o.source, "the --source file").writes_file(o.keep, "--keep").check();
}

// A kept file is an input like any other: one cut short (a full disk, a killed writer) or damaged
// is removed with a note and written again, never read as if whole.
void discard_damaged_kept_file(const ImportScaleOptions& o, const std::string& file) {
  std::error_code ec;
  if (!fs::exists(file, ec)) return;
  try {
    if (const std::string kind = non_regular_file_kind(file); !kind.empty())
      throw UserError(file, "--keep", "a regular file, found " + kind);
    check_vdb_file_structure(file);
  } catch (const UserError& e) {
    if (!non_regular_file_kind(file).empty()) throw;  // never remove what is not a file
    note(o, std::string("discarding the kept file (") + e.what() + "); writing it again");
    fs::remove(file, ec);
  }
}

// The particles drawn by the GL splats against the path-traced single-scattering truth of the
// sparse grid, both seen from the grid's framing camera through the import's medium.
nlohmann::json measure_import(const SparseGrid& grid, const std::vector<GaussianParticle>& particles,
                              const VolumeMedium& medium, const ImportScaleOptions& o) {
  if (o.error_size <= 0 || o.error_samples <= 0) return {{"measured", false}};
  const SparseViewError e =
      sparse_view_error(grid, particles, medium, framing_camera(grid), o.error_size, o.error_samples, o.threads);
  return {{"measured", true},
          {"rmse_vs_reference", e.rmse},
          {"reference_monte_carlo_error", e.noise},
          {"rmse_without_noise", e.without_noise()},
          {"reference_seconds", e.seconds},
          {"error_size", o.error_size},
          {"error_samples", o.error_samples},
          {"reference", "single scattering path traced through the sparse bricks, exact shadows by ratio tracking"}};
}

}  // namespace

nlohmann::json bench_import_scale(const ImportScaleOptions& o) {
  if (o.voxels == 0) throw UserError("", "--voxels", "a positive number of active voxels");
  check_kept_file(o);
  ProgressTask task(o.progress, "bench import-scale", 4);
  const bool temporary = o.keep.empty();
  const fs::path folder = temporary ? fs::temp_directory_path() / ("pyro_import_scale_" + std::to_string(::getpid())) : fs::path();
  const std::string file = temporary ? (folder / "import_scale.vdb").string() : o.keep;
  nlohmann::json out = {{"file", file}, {"generated", false}, {"generate_seconds", 0.0},
                        {"source", nullptr}, {"scale", nullptr}};
  struct Cleanup {
    fs::path folder;
    ~Cleanup() {
      std::error_code ec;
      if (!folder.empty()) fs::remove_all(folder, ec);
    }
  } cleanup{folder};
  std::error_code ec;
  if (temporary) fs::create_directories(folder, ec);
  if (!temporary) discard_damaged_kept_file(o, file);
  if (temporary || !fs::exists(file, ec)) {
    task.stage(0, "write the file");
    out.update(make_file(o, file));
    out["generated"] = true;
  } else {
    note(o, "reusing " + file);
  }
  out["file_bytes"] = fs::file_size(file, ec);

  task.stage(1, "read");
  auto t0 = Clock::now();
  VdbReadStats read_stats;
  const SparseGrid grid = read_vdb_grid_sparse(file, {}, nullptr, &read_stats);
  const double read_seconds = seconds_since(t0);

  task.stage(2, "import");
  CloudImportOptions opt;
  opt.medium.extinction = default_extinction(grid);
  opt.tau_tolerance = tau_tolerance_for_error(o.error);
  opt.threads = o.threads;
  CloudImportReport rep;
  t0 = Clock::now();
  const std::vector<GaussianParticle> particles = import_cloud(grid, opt, &rep);
  const double import_seconds = seconds_since(t0);
  task.stage(3, "measure the import's error");
  out.update(measure_import(grid, particles, opt.medium, o));
  task.update(4);

  const uint64_t parent = peak_rss_bytes(RUSAGE_SELF), child = read_stats.child_peak_rss_bytes;
  const int threads = o.threads > 0 ? o.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  out.update({{"active_voxels", grid.active_voxels}, {"box_voxels", grid.box_voxels()},
              {"bricks", grid.bricks()}, {"read_seconds", read_seconds}, {"import_seconds", import_seconds},
              {"light_seconds", rep.light_seconds}, {"fit_seconds", rep.fit_seconds},
              {"voxels_per_second", double(grid.active_voxels) / std::max(1e-9, read_seconds + import_seconds)},
              {"particles", particles.size()}, {"error_target", o.error}, {"threads", threads},
              {"parent_peak_rss_bytes", parent}, {"child_peak_rss_bytes", child},
              {"peak_rss_bytes", std::max(parent, child)},
              {"children_peak_rss_bytes", peak_rss_bytes(RUSAGE_CHILDREN)}});
  if (temporary) out["file"] = nullptr;  // deleted
  return out;
}

}  // namespace pyro
