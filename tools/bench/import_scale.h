#pragma once
// The VDB import at production sizes: a synthetic OpenVDB file of at least `voxels` active voxels
// (a small cloud resampled finer, engine/io/vdb_resampled_volume.h: the Disney cloud when
// ../shared/data/vdb is beside the checkout, else the project's procedural cloud), read sparse
// (engine/io/vdb_reader.h, read_vdb_grid_sparse) and imported as Gaussian particles
// (systems/runtime/cloud_import/cloud_import.h), read and import timed apart, with the peak resident
// memory of the engine's process and of the child process that reads the file.
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

struct ImportScaleOptions {
  uint64_t voxels = 200000000;  // active voxels wanted (at least) in the synthetic file
  // The synthetic file: reused when it exists, else written there and kept. Empty: written in a
  // temporary folder and deleted at the end.
  std::string keep;
  // The small grid to resample (a .vdb). Empty: the Disney cloud beside the checkout when
  // present, else the project's procedural cloud.
  std::string source;
  double error = 0.03;  // the import's error target (tau_tolerance_for_error), as import-vdb's default
  // The import's error, measured: the particles drawn by the GL splats from the grid's framing
  // camera at this size, against the single-scattering path-traced truth of the sparse grid
  // (systems/runtime/reference/path_traced_volume.h) with this many paths per pixel. 0: not measured.
  int error_size = 256;
  int error_samples = 256;
  int threads = 0;      // the import's threads (0: one per core)
  int progress_fd = -1;  // where the child writing the file says how far it is (-1: nowhere)
  ProgressSink* progress = nullptr;
  NoteSink on_note;  // what is being made, from what, and where
};

// Fields: file, file_bytes, generated, generate_seconds (0 when reused), source, scale,
// active_voxels, box_voxels, bricks, read_seconds, import_seconds, light_seconds, fit_seconds,
// voxels_per_second (active / (read + import)), particles, threads, parent_peak_rss_bytes
// (getrusage RUSAGE_SELF), child_peak_rss_bytes (the reading child, wait4), peak_rss_bytes
// (the larger), children_peak_rss_bytes (getrusage RUSAGE_CHILDREN: every child, the writer too);
// measured, and when it is: rmse_vs_reference, reference_monte_carlo_error (the truth's own
// noise, inside that RMSE), rmse_without_noise (√(rmse² − noise²)), reference_seconds, error_size, error_samples, reference (what the
// truth is). The peak memory figures include the measurement.
nlohmann::json bench_import_scale(const ImportScaleOptions& options);

}  // namespace pyro
