#pragma once
// A large OpenVDB file made from a small grid: the grid resampled `scale` times finer on every
// axis and written as a float fog volume, leaf by leaf, in a child process
// (engine/io/isolated_call.h), never through a dense copy of the fine grid. What the import
// benchmark at production sizes reads (tools/bench/import_scale.h).
//
// The fine grid's voxel I lies at the source's index coordinate S = (I + 1/2) / scale - 1/2 (the
// fine voxels tile the source's), its value the trilinear reconstruction of the source there,
// falling to 0 over the one voxel past the source's box (as systems/runtime/reference/grid_sampling.h
// reconstructs a grid); voxels whose value is not 0 are active. The transform is the source's
// composed with that map, so the fine grid fills the same region of the world.
#include <cstdint>
#include <string>

#include "engine/volume/dense_grid.h"

namespace pyro {

struct VdbResampleReport {
  uint64_t active_voxels = 0;
  uint64_t leaves = 0;
  uint64_t file_bytes = 0;
  uint64_t child_peak_rss_bytes = 0;  // the writing child's peak resident memory
};

// Writes `source` resampled `scale` (> 0) times finer as grid `grid_name` of a new file at
// `path` (written to a temporary name, then renamed). `progress_fd` (>= 0): a descriptor to
// which the child writes a line at every tenth of the leaf layers done, each starting with
// `progress_label`.
VdbResampleReport write_vdb_resampled_fog_volume(const std::string& path, const std::string& grid_name,
                                                 const DenseGrid& source, double scale,
                                                 int progress_fd = -1,
                                                 const std::string& progress_label = "");

}  // namespace pyro
