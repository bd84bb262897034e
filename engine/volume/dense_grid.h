#pragma once
// A float grid made dense over its active bounding box (grid_header.h). Inactive voxels hold the
// background of a fog volume (0). Element (x, y, z) holds index coordinate origin + (x, y, z).
// Small grids only: its memory grows with the box, not with the active voxels (sparse_grid.h
// is the grid whose memory grows with the active voxels).
#include <cstddef>
#include <vector>

#include "engine/volume/grid_header.h"

namespace pyro {

struct DenseGrid : GridHeader {
  std::vector<float> values;  // x fastest: values[(z * dims[1] + y) * dims[0] + x]

  bool empty() const { return values.empty(); }
  size_t size() const { return values.size(); }
  float at(int x, int y, int z) const {
    return values[(static_cast<size_t>(z) * dims[1] + y) * dims[0] + x];
  }
};

}  // namespace pyro
