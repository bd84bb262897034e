#pragma once
// The project's own sample cloud: a cumulus-like density field, deterministic from a seed, made
// without OpenVDB (tools/make_sample_volume writes it as a .vdb through engine/io/vdb_reader.h).
//
// Shape: a few overlapping ellipsoidal "puffs" (centres and radii drawn from the seed) over a
// flattened base, cut by a soft floor (cumulus have flat bottoms), eroded by fractal value noise
// (4 octaves of trilinear lattice noise, lattice values hashed from the seed with splitmix64, so
// no floating-point state carries between voxels and the result depends on the seed only).
#include <cstdint>

#include "engine/io/vdb_reader.h"

namespace pyro {

struct ProceduralCloudOptions {
  uint64_t seed = 1;
  int width = 80;      // voxels along x (the cloud's long axis); y is width*3/5, z is width*2/3
  int puffs = 7;       // ellipsoids in the body
  double voxel_size = 0.1;
};

// Dense values over origin (0,0,0) .. dims - 1, x fastest; zero outside the cloud. The transform
// is the uniform voxel size with the grid's centre at the world origin. active_voxels counts the
// non-zero values and max_value is their maximum.
DenseGrid make_procedural_cloud(const ProceduralCloudOptions& options = {});

}  // namespace pyro
