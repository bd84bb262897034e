#pragma once
// What `pyro import-vdb` and `pyro chart particle-budget` share: a grid imported as Gaussian
// particles for an image error target, and the image RMSE of the splatted particles (the real GL
// pipeline, offscreen) against the CPU reference render of the grid (systems/reference) from
// the camera framing the grid. The reference is rendered once per grid and reused across targets.
#include <vector>

#include "engine/particles/gaussian_particle.h"
#include "components/volume_medium.h"
#include "systems/scene/scene_description.h"
#include "engine/io/vdb_reader.h"
#include "systems/cloud_import/cloud_import.h"
#include "systems/reference/rgb_image.h"

namespace pyro {

struct VdbImportReference {
  VolumeMedium medium;       // default_medium(grid)
  CameraDescription camera;  // framing_camera(grid)
  int width = 0, height = 0;
  RgbImage image;            // the CPU reference render (empty for an empty grid)
  double seconds = 0.0;      // light sweep + reference render
};

// Renders the reference of `grid` at width x height.
VdbImportReference make_vdb_import_reference(const DenseGrid& grid, int width, int height);

struct VdbImportResult {
  std::vector<GaussianParticle> particles;
  CloudImportReport report;
  double tau_tolerance = 0.0;
  double import_seconds = 0.0;
  double rmse = 0.0;            // splats against the reference (0 for an empty grid)
  double render_seconds = 0.0;  // one splat frame (sort + draw + readback), best of `repeats`
};

// Imports `grid` for the image error target `error` (tau_tolerance_for_error) and measures it.
VdbImportResult import_and_measure(const DenseGrid& grid, double error, const VdbImportReference& reference,
                                   int render_repeats = 1);

}  // namespace pyro
