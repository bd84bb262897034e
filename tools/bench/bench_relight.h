#pragma once
// pyro bench relight FILE: an OpenVDB grid imported once as isotropic Gaussian particles that keep
// their albedo (as scenes with "shadows" import their volumes), or with `fitted` as the anisotropic
// Gaussians `pyro import-vdb` fits (relit from the albedo a particle file records), then relit by the light phase
// (docs/lighting.md) from `directions` sun directions without importing again. Each direction's
// frame is scored against the CPU volume reference lit from that direction (the grid itself,
// ray marched with exact shadows: systems/runtime/reference/volume_reference.h), and the relit frames are
// timed against the same particles drawn without per-frame lighting, in the same run, in
// alternating blocks of frames.
#include <string>

#include <nlohmann/json.hpp>

#include "components/shadow_settings.h"
#include "engine/core/progress_sink.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

struct RelightBenchOptions {
  std::string file, grid;
  int grid_index = -1;
  double error = 0.03;  // the import's error target (as a scene's volume)
  int directions = 8;   // sun azimuths 360 / directions apart, at 40 degrees elevation
  int width = 512, height = 512;
  int frames = 16;      // timed frames of each (lit: the sun turning every frame; unlit)
  bool fitted = false;  // the fitted anisotropic import instead of the octree's isotropic one
  ShadowSettings shadows;
  ProgressSink* progress = nullptr;
  NoteSink on_note;
};

// Fields: file, particles, kind ("isotropic" or "fitted"), width, height, shadows {method, map_size, map_slices}, directions
// [{direction, rmse_vs_reference}], max_rmse_vs_reference, fps (relit), unlit_fps,
// fps_over_unlit, import_seconds, reference_seconds (all directions). Throws UserError naming the
// file for a grid without active voxels.
nlohmann::json bench_relight(const RelightBenchOptions& options);

}  // namespace pyro
