#pragma once
// One view of one grid, rendered three ways in one run: the splatting pipeline (the grid imported
// as import-vdb imports it, fitted anisotropic Gaussians, drawn by the GL splats; best of 3 frames), the CPU reference (systems/runtime/reference),
// and OpenVDB's vdb_render (Debian's libopenvdb-tools) as a separate process with the same camera
// (position, look-at, up, horizontal field of view), resolution, light direction and colour, and
// absorption / scattering per voxel (vdb_render integrates in voxel units: sigma per voxel =
// extinction * voxel length, split by the albedo; its shadow "gain" is set to 0). vdb_render has
// no ambient term and a black background, so it is scored against the splats and the CPU
// reference of that scene (the same grid imported and rendered without ambient light, black
// behind): rmse_vs_vdb_render {splats, reference, splats_vs_reference}.
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

struct VdbBenchOptions {
  std::string file, grid;
  std::string vdb_render = "vdb_render";  // the program (from PATH unless a path)
  // vdb_render's integration steps in voxels, along the view ray and towards the light (its
  // quadrature error shrinks with them, and its time grows).
  double vdb_render_step = 0.5, vdb_render_shadow_step = 1.0;
  int grid_index = -1;
  double error = 0.03;  // the import's error target (import-vdb's default)
  int width = 512, height = 512;
  ProgressSink* progress = nullptr;
  NoteSink on_note;  // the reader's note on the grid chosen; a failing vdb_render
};

// Fields: file, width, height, active_voxels, particles, import_target_met,
// import_rmse_views_max (the import's own error from every side, at 256^2), import_seconds,
// splat_ms, reference_ms,
// vdb_render_ms (-1 when it failed), speedup_vs_vdb_render, speedup_vs_reference,
// rmse_vs_reference, rmse_vs_vdb_render (null when vdb_render failed), vdb_render_command. Throws UserError naming the file for a grid without
// active voxels.
nlohmann::json bench_vdb(const VdbBenchOptions& options);

}  // namespace pyro
