#pragma once
// What a volume grid read from a file is apart from its values: where it came from, the index box
// its values cover, and the map from index space to world space. The dense and the sparse grid
// (dense_grid.h, sparse_grid.h) both carry it, so that what depends only on where a grid lies
// (its world bounds, its framing camera, its default extinction) takes either.
//
// Coordinates: OpenVDB stores a value at every integer index coordinate (i, j, k), the voxel
// centre; its transform maps index space to world space, kept here as a 4x4 affine matrix (column
// vectors: world = index_to_world * (i, j, k, 1)). Local coordinate (x, y, z) is index coordinate
// origin + (x, y, z), for x in [0, dims[0]) and so on.
#include <array>
#include <cstdint>
#include <string>

#include <glm/mat4x4.hpp>

namespace pyro {

struct GridHeader {
  std::string file;
  std::string name;
  int file_index = 0;
  std::array<int, 3> origin{0, 0, 0};  // the active voxels' index bounding box: its low corner
  std::array<int, 3> dims{0, 0, 0};    // ... and its size
  glm::dmat4 index_to_world{1.0};
  std::array<double, 3> voxel_size{1, 1, 1};
  uint64_t active_voxels = 0;
  float max_value = 0.0f;  // the largest value, at least 0
  bool converted_from_level_set = false;
  bool half_float = false;

  // Voxels in the box, dims[0] * dims[1] * dims[2] (0 when any is 0 or negative).
  uint64_t box_voxels() const {
    for (int d : dims)
      if (d <= 0) return 0;
    return uint64_t(dims[0]) * uint64_t(dims[1]) * uint64_t(dims[2]);
  }
};

}  // namespace pyro
