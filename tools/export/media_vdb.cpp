#include "tools/export/media_vdb.h"

namespace pyro {

namespace {

VdbGridToWrite grid_of(const MediaVoxels& v, const std::string& name, std::vector<float> values, bool vec3) {
  VdbGridToWrite g;
  g.name = name;
  g.origin = v.box.origin;
  g.dims = v.box.dims;
  g.values = std::move(values);
  g.vec3 = vec3;
  g.voxel_size = {v.box.voxel, v.box.voxel, v.box.voxel};
  g.translation = {0.0, 0.0, 0.0};
  return g;
}

}  // namespace

std::vector<VdbGridToWrite> media_vdb_grids(const MediaVoxels& voxels) {
  std::vector<VdbGridToWrite> grids;
  grids.push_back(grid_of(voxels, "density", voxels.density, false));
  if (!voxels.temperature.empty()) grids.push_back(grid_of(voxels, "temperature", voxels.temperature, false));
  if (!voxels.color.empty()) grids.push_back(grid_of(voxels, "color", voxels.color, true));
  if (!voxels.emission.empty()) grids.push_back(grid_of(voxels, "emission", voxels.emission, true));
  return grids;
}

}  // namespace pyro
