#pragma once
// A frame's media sampled on a voxel grid (plain data for engine/io/vdb_reader.h's writer): the
// extinction per world unit at each voxel centre, and beside it the extinction-weighted mean
// temperature and colour of the particles there. Index (i, j, k) is the world point
// (i, j, k) * voxel (the grid's transform is a pure scale, the same for every frame of a
// sequence, so hosts see the frames in one place); the box covers every particle's support.
//
// Gaussians (clamped and anisotropic) are sampled at the voxel centre: what a host's trilinear
// lookup reconstructs. A sphere's field has an integrable singularity at its centre
// (engine/math/sphere_field.h), so its voxels within 1.5 voxels of its centre take the mean of
// 2^3 samples at +-voxel/4.
#include <array>
#include <cstdint>
#include <vector>

#include "tools/export/media_sample.h"

namespace pyro {

struct VoxelBox {
  std::array<int, 3> origin{0, 0, 0};  // index of local voxel (0, 0, 0)
  std::array<int, 3> dims{0, 0, 0};
  double voxel = 1.0;                  // side, world units
  uint64_t voxels() const { return uint64_t(dims[0]) * uint64_t(dims[1]) * uint64_t(dims[2]); }
  size_t at(int x, int y, int z) const { return (size_t(z) * dims[1] + size_t(y)) * dims[0] + size_t(x); }
};

struct MediaVoxels {
  VoxelBox box;
  std::vector<float> density;      // extinction per world unit, x fastest
  std::vector<float> temperature;  // kelvin where density > 0; empty unless asked for
  std::vector<float> color;        // 3 a voxel, linear RGB where density > 0; empty unless asked for
  std::vector<float> emission;     // 3 a voxel: emitted radiance per unit length, the sum of each sample's
                                   // extinction times its emission; empty unless asked for
};

// The box of voxels of side `voxel` over every sample's support (empty samples: an empty box).
VoxelBox media_box(const std::vector<MediaSample>& samples, double voxel);

struct VoxelizeOptions {
  bool temperature = false;
  bool color = false;
  bool emission = false;
};

// The samples on `box` (media_box's, or a larger one).
MediaVoxels voxelize_media(const std::vector<MediaSample>& samples, const VoxelBox& box,
                           const VoxelizeOptions& options = VoxelizeOptions());

}  // namespace pyro
