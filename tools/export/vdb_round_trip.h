#pragma once
// The export's round trip, measured (pyro bench export-vdb): one frame of a scene exported
// (vdb_export.h), imported again as the engine imports a .vdb on load (a scene volumes[] entry:
// systems/runtime/cloud_import, the importer of `pyro import-vdb`, with extinction 1 because the
// grid holds extinction per unit length, anchored at the file's origin), and both particle sets
// drawn by the CPU reference (systems/runtime/reference/particle_reference.h, the engine's ground
// truth) through the scene's camera as opacity images: white media over black, each pixel its
// ray's 1 - exp(-tau). Two differences: the exported grid itself, read back by the VDB reader and
// ray marched as a host draws it (systems/runtime/reference/volume_reference.h), which is the
// export's projection error alone; and the particles imported from it, which adds the import's
// own (an RMSE target).
// The reference draws Gaussian splats: scenes of spheres (the explosion) or fitted anisotropic
// particles are refused.
#include <string>

#include <nlohmann/json.hpp>

#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

struct VdbRoundTripOptions {
  std::string scene;
  int frame = 0;
  double error = 0.01;         // the export's --error
  double voxel_size = 0.0;     // the export's --voxel-size (0: chosen)
  double import_error = 0.01;  // the volume's "error"
  int width = 160, height = 120;
};

struct VdbRoundTrip {
  // export (its summary), particles, import_particles, import_seconds, grid_opacity_max_difference,
  // grid_opacity_rmse, opacity_max_difference, opacity_rmse (the imported particles')
  nlohmann::json json;
  std::string text;
};

VdbRoundTrip measure_vdb_round_trip(const VdbRoundTripOptions& options, const NoteSink& note);

}  // namespace pyro
