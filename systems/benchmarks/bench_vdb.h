#pragma once
// One view of one grid, rendered three ways in one run: the splatting pipeline (the imported
// particles through the real GL passes; best of 3 frames), the CPU reference (systems/reference),
// and OpenVDB's vdb_render (Debian's libopenvdb-tools) as a separate process with the same camera
// (position, look-at, up, horizontal field of view), resolution, light direction and colour, and
// absorption / scattering per voxel (vdb_render integrates in voxel units: sigma per voxel =
// extinction * voxel length, split by the albedo; its shadow "gain" is set to 0). vdb_render has
// no ambient term, so its image is not expected to match ours; it is timed, not scored.
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"
#include "systems/scene_runtime/runtime_options.h"

namespace pyro {

struct VdbBenchOptions {
  std::string file, grid;
  std::string vdb_render = "vdb_render";  // the program (from PATH unless a path)
  int grid_index = -1;
  double error = 0.03;  // the import's error target
  int width = 512, height = 512;
  ProgressSink* progress = nullptr;
  NoteSink on_note;  // the reader's note on the grid chosen; a failing vdb_render
};

// Fields: file, width, height, active_voxels, particles, import_seconds, splat_ms, reference_ms,
// vdb_render_ms (-1 when it failed), speedup_vs_vdb_render, speedup_vs_reference,
// rmse_vs_reference, vdb_render_command. Throws UserError naming the file for a grid without
// active voxels.
nlohmann::json bench_vdb(const VdbBenchOptions& options);

}  // namespace pyro
