#pragma once
// What `pyro import-vdb` and `pyro chart particle-budget` share: a grid imported as Gaussian
// particles for an image error target, and the image RMSE of the splatted particles (the real GL
// pipeline, offscreen) against the CPU reference render of the grid (systems/runtime/reference) from
// the camera framing the grid. The reference is rendered once per grid and reused across targets.
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "engine/particles/anisotropic_gaussian.h"
#include "engine/particles/gaussian_particle.h"
#include "components/volume_medium.h"
#include "systems/runtime/scene/scene_description.h"
#include "engine/io/vdb_reader.h"
#include "systems/runtime/cloud_import/cloud_import.h"
#include "systems/runtime/cloud_import/grid_gaussian.h"
#include "systems/runtime/reference/rgb_image.h"
#include "systems/runtime/reference/volume_emission.h"

namespace pyro {

struct VdbImportReference {
  VolumeMedium medium;       // default_medium(grid)
  CameraDescription camera;  // framing_camera(grid)
  int width = 0, height = 0;
  RgbImage image;            // the CPU reference render (empty for an empty grid)
  // The reference's optical depth from each voxel to the light (volume_reference.h,
  // light_optical_depth; the layout of grid.values): the fitted import lights its Gaussians
  // from the same field the reference is lit by.
  std::vector<float> light_depth;
  double seconds = 0.0;      // light sweep + reference render(s)
  // With every view (grid_framing.h: views_around, the framing camera first, then every side;
  // and view_inside when the camera fits): each view's camera and reference image; empty
  // otherwise.
  std::vector<CameraDescription> view_cameras;
  std::vector<RgbImage> view_images;
  std::optional<CameraDescription> inside_camera;
  RgbImage inside_image;
  // A fire's temperature and its emission (off when empty): the reference emits L_e(T), and the
  // fitted particles are given their temperatures and emission before every measurement
  // (systems/runtime/cloud_import/gaussian_temperature.h), so the error target covers the fire's light.
  VolumeEmission emission;
};

// Renders the reference of `grid` at width x height, from the framing camera alone or from
// every view around it (`every_view`).
VdbImportReference make_vdb_import_reference(const DenseGrid& grid, int width, int height,
                                             bool every_view = false, VolumeEmission emission = {});

struct VdbImportResult {
  std::vector<GaussianParticle> particles;  // the octree's isotropic particles
  // The fitted import's anisotropic particles (fitted_import.h), and the same in the grid's index
  // space with their lit values (to light them again for another medium); empty for the octree
  // alone.
  std::vector<AnisotropicGaussian> fitted;
  std::vector<GridGaussian> grid_gaussians;
  // With the reference's emission on: each fitted particle's temperature (grid units).
  std::vector<float> temperatures;
  CloudImportReport report;
  double tau_tolerance = 0.0;
  double import_seconds = 0.0;
  double rmse = 0.0;            // splats against the reference (0 for an empty grid)
  double render_seconds = 0.0;  // one splat frame (sort + draw + readback), best of `repeats`
  // With every view: each view around the volume's RMSE (the reference's order), their mean and
  // maximum, and the RMSE from inside (NaN without that view). The inside view is kept apart:
  // billboards that reach the camera are where splatting is known to fail (the camera inside a
  // particle sees its flat billboard, not its density), so no import can meet a target there.
  std::vector<double> view_rmse;
  double rmse_views_mean = 0.0, rmse_views_max = 0.0;
  double rmse_inside = std::numeric_limits<double>::quiet_NaN();
};

// Imports `grid` for the image error target `error` (tau_tolerance_for_error) and measures it.
VdbImportResult import_and_measure(const DenseGrid& grid, double error, const VdbImportReference& reference,
                                   int render_repeats = 1);
// The same with the import's octree tolerance given (import-vdb's refinement tightens it).
VdbImportResult import_and_measure_at(const DenseGrid& grid, double tau_tolerance,
                                      const VdbImportReference& reference, int render_repeats = 1);

// The RMSE of `render`'s image (render(camera) -> RgbImage) against the reference from the
// framing camera (rmse), every view (view_rmse, their mean and maximum) and from inside, into `r`.
void measure_views(VdbImportResult& r, const VdbImportReference& reference,
                   const std::function<RgbImage(const CameraDescription&)>& render);

}  // namespace pyro
